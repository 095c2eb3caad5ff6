#pragma once
// The SINUMERIK oracle tests' hand-written paths (tests/siemens_oracles_test.cpp,
// tests/siemens_call_oracles_test.cpp): a program on contour L1 or on the groove L3, and the moves the
// rules demand, written move by move from the rules (x radius; the contour L1 is (z0,x10) → (−10,10)
// → (−10,16) → (−20,16) → (−20,20), so the start is (z1,x21) and the depth 10 divides into 4 steps of
// 2.5 for R108 = 3).
#include <algorithm>
#include <iterator>
#include <string>
#include <vector>

#include "harness/judge/judging.h"
#include "oracles/judgement.h"

namespace cyclecert::siemens_test {

inline const char* const kL1 = "G1 X20 Z0\nZ-10\nX32\nZ-20\nX40\nRET\n";

inline std::string lcyc95Program(const std::string& r105, const std::string& r109 = "0") {
  return "G0 X50 Z2\n_CNAME=\"L1\"\nR105=" + r105 + " R106=0 R108=3 R109=" + r109 + "\nR110=1 R111=0.3 R112=0.1\nLCYC95\nM02\n";
}

inline std::string cycle95Program(const std::string& vari, const std::string& dam = "0") {
  return "G0 X50 Z2\nCYCLE95(\"L1\", 3, 0, 0, 0, 0.3, 0.15, 0.1, " + vari + ", 0, " + dam + ", 1)\nM02\n";
}

// A toolpath written move by move (plane coordinates z, x radius).
struct PathBuilder {
  Toolpath path;
  explicit PathBuilder(Point start) { path.start = start; }
  PathBuilder& rapid(double z, double x) {
    Move m;
    m.kind = MoveKind::Rapid;
    m.to = {z, x};
    path.moves.push_back(m);
    return *this;
  }
  PathBuilder& feed(double z, double x, double f) {
    Move m;
    m.kind = MoveKind::Feed;
    m.to = {z, x};
    m.feed = f;
    path.moves.push_back(m);
    return *this;
  }
  // The last move ends with a dwell of `seconds` (CYCLE95's DT).
  PathBuilder& dwell(double seconds) {
    path.moves.back().dwell = seconds;
    return *this;
  }
};

// The program with its one contour subprogram, as the oracles and the reference read it.
inline JudgeRequest siemensRequest(const std::string& program, const std::string& profile,
                                   const std::string& subprogram = kL1, const std::string& name = "L1") {
  JudgeRequest request;
  request.program.programText = program;
  request.program.file = "test.mpf";
  request.program.profile = profile;
  request.program.subprograms.push_back({name, subprogram, "test#/subprograms/" + name});
  return request;
}

inline std::vector<Finding> judged(const std::string& program, const std::string& profile, const Toolpath& path,
                                   const std::string& subprogram = kL1, const std::string& name = "L1") {
  return judge(judgeInputFor(siemensRequest(program, profile, subprogram, name), path));
}

inline std::vector<Finding> of(const std::vector<Finding>& all, const std::string& oracle) {
  std::vector<Finding> out;
  std::copy_if(all.begin(), all.end(), std::back_inserter(out), [&](const Finding& f) { return f.oracle == oracle; });
  return out;
}

// LCYC95 R105=1, R109=0: G0 to S; per level a G1 infeed at R111 from the retract height, the cut to
// the roughing intersection, along the profile up to the previous level, G0 retract (+1, +1), G0 back
// to z1; after the last pass G0 to S in both axes.
inline PathBuilder lcyc95Roughing() {
  PathBuilder p({2, 25});
  p.rapid(1, 21);
  p.feed(1, 17.5, 0.3).feed(-20, 17.5, 0.3).feed(-20, 20, 0.3).rapid(-19, 21).rapid(1, 21);
  p.feed(1, 15, 0.3).feed(-10, 15, 0.3).feed(-10, 16, 0.3).feed(-20, 16, 0.3).feed(-20, 17.5, 0.3).rapid(-19, 18.5).rapid(1, 18.5);
  p.feed(1, 12.5, 0.3).feed(-10, 12.5, 0.3).feed(-10, 15, 0.3).rapid(-9, 16).rapid(1, 16);
  p.feed(1, 10, 0.3).feed(0, 10, 0.3).feed(-10, 10, 0.3).feed(-10, 12.5, 0.3).rapid(-9, 13.5);
  p.rapid(1, 21);
  return p;
}

// CYCLE95 VARI 1: G0 infeeds, the axes return one after the other (x first).
inline PathBuilder cycle95Roughing() {
  PathBuilder p({2, 25});
  p.rapid(1, 21);
  p.rapid(1, 17.5).feed(-20, 17.5, 0.3).feed(-20, 20, 0.3).rapid(-19, 21).rapid(1, 21);
  p.rapid(1, 15).feed(-10, 15, 0.3).feed(-10, 16, 0.3).feed(-20, 16, 0.3).feed(-20, 17.5, 0.3).rapid(-19, 18.5).rapid(1, 18.5);
  p.rapid(1, 12.5).feed(-10, 12.5, 0.3).feed(-10, 15, 0.3).rapid(-9, 16).rapid(1, 16);
  p.rapid(1, 10).feed(0, 10, 0.3).feed(-10, 10, 0.3).feed(-10, 12.5, 0.3).rapid(-9, 13.5);
  p.rapid(-9, 21).rapid(1, 21);
  return p;
}

// CYCLE95 with a groove (z−10…−15, down to x12), MID 3, FF1 0.3, FF2 0.15: the axis-parallel passes
// stop at the rim (−10,16); the pocket below the level 17.5 in its own two steps (14.75, 12) at FF2.
// `firstPocketLevel`: where the pocket's first cut across runs (14.75; a test doctors it).
inline const char* const kGroove = "G1 X20 Z0\nZ-5\nX32\nZ-10\nX24\nZ-15\nX32\nZ-20\nX40\nRET\n";

inline PathBuilder grooveRoughing(double undercutFeed, double firstPocketLevel = 14.75) {
  const double u = undercutFeed, l = firstPocketLevel;
  PathBuilder p({2, 25});
  p.rapid(1, 21);
  p.rapid(1, 17.5).feed(-20, 17.5, 0.3).feed(-20, 20, 0.3).rapid(-19, 21).rapid(1, 21);
  p.rapid(1, 15).feed(-5, 15, 0.3).feed(-5, 16, 0.3).feed(-10, 16, 0.3).rapid(-9, 17).rapid(1, 17);
  p.rapid(1, 12.5).feed(-5, 12.5, 0.3).feed(-5, 15, 0.3).rapid(-4, 16).rapid(1, 16);
  p.rapid(1, 10).feed(0, 10, 0.3).feed(-5, 10, 0.3).feed(-5, 12.5, 0.3).rapid(-4, 13.5);
  p.rapid(-4, 21);
  p.rapid(-10, 21).feed(-10, l, u).feed(-15, l, u).feed(-15, 16, u).feed(-20, 16, u).feed(-20, 17.5, u).rapid(-19, 18.5);
  p.rapid(-10, 18.5).feed(-10, 12, u).feed(-15, 12, u).feed(-15, l, u).rapid(-14, l + 1);
  p.rapid(-14, 21).rapid(1, 21);
  return p;
}

inline std::string grooveProgram() { return "G0 X50 Z2\nCYCLE95(\"L3\", 3, 0, 0, 0, 0.3, 0.15, 0.1, 1, 0, 0, 1)\nM02\n"; }

}  // namespace cyclecert::siemens_test
