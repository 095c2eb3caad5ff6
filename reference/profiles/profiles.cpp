#include "reference/model/profile.h"

namespace cyclecert {

namespace {
Profile fanuc0iF() {
  Profile p;
  p.name = "fanuc-0i-f";
  p.description = "FANUC Series 0i-F lathe (T series), G code system A (B, C with 3401#6 GSB / #7 GSC), diameter programming";
  p.seed = "000_036281bf73fad5d1.txt";
  p.gCodeSystemByParameters = true;  // PROG.GSYS.SELECT: 3401#6 GSB, #7 GSC
  return p;
}

Profile fanuc0iC() {
  Profile p = fanuc0iF();
  p.name = "fanuc-0i-c";
  p.description = "FANUC Series 0i-C lathe: as 0i-F, but type II roughs pockets level by level";
  p.pocketsLevelByLevel = true;  // G71.T2.ORDER: seed 000 contrasts 0i-F's order with 0i-C's
  return p;
}

Profile gsk() {
  Profile p;
  p.name = "gsk";
  p.description = "GSK-style lathe controller of seed 001 (FANUC-compatible parameter numbers)";
  p.seed = "001_f6c35fe49e180329.txt";
  // G72.STEP8: this manual returns straight from C' to A, which FANUC calls DTP=1.
  p.defaults.set("DTP", 1);
  // G72.NSNF.GCODES: G40/G41/G42 are allowed in ns…nf and only take effect in G70.
  p.toleratesTnrcInShape = true;
  return p;
}

// Seed 003: Huazhong (HNC) lathe, G71 in one block (HNC.G71.*). Its parameters and alarm codes
// are not in the seed: the FANUC 0i-F defaults and codes stand in for them (interpretation).
Profile hnc() {
  Profile p;
  p.name = "hnc";
  p.description = "Huazhong (HNC) lathe of seed 003: one-block G71 U(Δd) R(r) P Q X(Δx) Z(Δz), ns…nf run again as finishing";
  p.seed = "003_22785bbc34f78b07.txt";
  p.roughingFormat = RoughingBlockFormat::HuazhongOneBlock;
  p.gCodeSystem = GCodeSystem::Huazhong;  // G90/G91, G94/G95 are modes (seed 003 example 1: `N1 G94 G90`)
  p.namesProgramsWithPercent = true;
  return p;
}
}  // namespace

const std::vector<Profile>& allProfiles() {
  static const std::vector<Profile> profiles = {fanuc0iF(), fanuc0iC(), gsk(), hnc()};
  return profiles;
}

const Profile* findProfile(std::string_view name) {
  for (const Profile& p : allProfiles()) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

}  // namespace cyclecert
