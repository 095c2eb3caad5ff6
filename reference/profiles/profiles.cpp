#include "reference/model/profile.h"
#include "reference/profiles/default_profile.h"

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

// Haas lathe (Classic/NGC operator's manual, G71/G72 pages): FANUC's cycles with a one-block form
// (HAAS.G71.FMT), G41/G42 inside P…Q compensating the shape (HAAS.TNRC.SHAPE). Its alarm numbers are
// not in our sources: the FANUC 0i-F codes stand in for them (interpretation, as for hnc).
Profile haas() {
  Profile p;
  p.name = "haas";
  p.description = "Haas lathe: G71/G72 in one block P Q U W D I K F S T (R1 type II), G41/G42 inside P…Q compensate the shape";
  p.seed = "http://staging-diy.haascnc.com/g71-odid-stock-removal-cycle-group-00-0";
  p.roughingFormat = RoughingBlockFormat::HaasOneBlock;
  p.compensatesTnrcInShape = true;
  // HAAS.G71.SETTINGS: D omitted: Setting 72 (can cycle cut depth); the retract: Setting 73 (can
  // cycle retraction), here parameters 5132/5133. Defaults 0.1000 in and 0.0500 in (interpretation).
  p.defaults.set("5132", 2.54);
  p.defaults.set("5133", 1.27);
  // HAAS.TNRC.SHAPE: G70 follows the compensation commanded inside its shape, as NT2 = 1 does.
  p.defaults.set("NT2", 1);
  return p;
}

// Seed 004, section 二: SINUMERIK 802S/C, stock removal with LCYC95 (R105…R112, the contour named by
// _CNAME). Its alarm numbers come from the planners (reference/siemens).
Profile sinumerik802s() {
  Profile p;
  p.name = "sinumerik-802s";
  p.description = "SINUMERIK 802S/C lathe of seed 004: LCYC95 with R105…R112 and the contour subprogram _CNAME, G23/G22 diameter/radius";
  p.seed = "004_e17a91cae76bcf9f.txt";
  p.dialect = Dialect::Siemens;
  p.siemensControl = SiemensControl::Sinumerik802S;
  return p;
}

// Seed 004, section 三: SINUMERIK 802D, stock removal with CYCLE95(NPP, MID, …, _VRT).
Profile sinumerik802d() {
  Profile p = sinumerik802s();
  p.name = "sinumerik-802d";
  p.description = "SINUMERIK 802D lathe of seed 004: CYCLE95(NPP, MID, FALZ, FALX, FAL, FF1, FF2, FF3, VARI, DT, DAM, _VRT), DIAMON/DIAMOF";
  p.siemensControl = SiemensControl::Sinumerik802D;
  return p;
}
}  // namespace

const std::vector<Profile>& allProfiles() {
  static const std::vector<Profile> profiles = {fanuc0iF(), fanuc0iC(), gsk(), hnc(), haas(), sinumerik802s(),
                                                sinumerik802d()};
  return profiles;
}

const Profile& defaultProfile() {
  static const Profile& profile = *findProfile(kDefaultProfileName);
  return profile;
}

const Profile* findProfile(std::string_view name) {
  for (const Profile& p : allProfiles()) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

}  // namespace cyclecert
