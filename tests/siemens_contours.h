#pragma once
// Contours and expectations for the SINUMERIK stock-removal planner tests (lcyc95_test.cpp,
// cycle95_test.cpp): segments built by hand in radius (the programs' X words halved).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "reference/model/toolpath.h"
#include "reference/siemens/siemens_cycles.h"

namespace cyclecert::siemens_test {

inline Segment line(Point from, Point to, int sourceLine = 0) {
  Segment s;
  s.from = from;
  s.to = to;
  s.sourceLine = sourceLine;
  return s;
}

inline Segment arc(SegmentKind kind, Point from, Point to, Point center, int sourceLine = 0) {
  Segment s = line(from, to, sourceLine);
  s.kind = kind;
  s.center = center;
  return s;
}

// A contour through `points` (z, x), lines only.
inline SiemensContour polyline(const std::string& name, const std::vector<Point>& points) {
  SiemensContour c{name, name + ".spf", {}};
  for (std::size_t i = 1; i < points.size(); ++i) c.segments.push_back(line(points[i - 1], points[i], int(i)));
  return c;
}

// The step shaft: (z 0, x 0) up the face to x 4, along to z −10, up to x 9, along to z −20.
inline SiemensContour stepShaft() { return polyline("STEP", {{0, 0}, {0, 4}, {-10, 4}, {-10, 9}, {-20, 9}}); }

// An expected move: kind, end point, phase and pass.
struct Expected {
  MoveKind kind;
  Point to;
  std::string phase;
  int pass = 0;
};
inline constexpr MoveKind G0 = MoveKind::Rapid;
inline constexpr MoveKind G1 = MoveKind::Feed;

inline void expectMoves(const std::vector<Move>& got, const std::vector<Expected>& want, double tol = 1e-6) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    SCOPED_TRACE("move " + std::to_string(i));
    EXPECT_EQ(got[i].kind, want[i].kind);
    EXPECT_NEAR(got[i].to.z, want[i].to.z, tol);
    EXPECT_NEAR(got[i].to.x, want[i].to.x, tol);
    EXPECT_EQ(phaseName(got[i].phase), want[i].phase);
    EXPECT_EQ(got[i].pass, want[i].pass);
  }
}

inline int passCount(const std::vector<Move>& moves) {
  int n = 0;
  for (const Move& m : moves) n = std::max(n, m.pass);
  return n;
}

}  // namespace cyclecert::siemens_test
