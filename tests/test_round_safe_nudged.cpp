// nudge_conflicts (arrangements/src/round_nudged.h) on its own: a corner of one triangle
// an ulp through another's face, at magnitudes 2^-30 to 2^30 and offsets up to 1e6, is
// moved out of it by a few ulps; the result passes the exact check (check_arrangement)
// with the same triangles, every vertex within the reported move of where it started;
// with a move limit of 0 nothing moves and the violation stays. The class of what
// nudging settles inside round_safe (grazing copies of a sphere, layers an ulp apart) is
// in test_round_safe.cpp, test_round_safe_input.cpp and test_round_safe_contacts.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "arrangements/as_input.h"
#include "arrangements/check_arrangement.h"
#include "round_nudged.h"
#include "support/rounding_grid.h"

namespace {

using namespace arrangements;

// Triangle A = o + s (0,0,0), (1,0,0), (0,1,0), and B with its lowest corner at
// o + s (0.25, 0.25, 0), one double below A's plane, its other corners s above it: B
// pierces A near that corner.
RoundedMesh piercing_corner(const Vec3& o, double s) {
  RoundedMesh m;
  const double below = std::nextafter(o[2], -std::numeric_limits<double>::infinity());
  m.vertices = {{o[0], o[1], o[2]},
                {o[0] + s, o[1], o[2]},
                {o[0], o[1] + s, o[2]},
                {o[0] + 0.25 * s, o[1] + 0.25 * s, below},
                {o[0] + 0.75 * s, o[1] + 0.25 * s, o[2] + s},
                {o[0] + 0.25 * s, o[1] + 0.75 * s, o[2] + s}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  m.source = {0, 1};
  m.label_sets = {{0}, {1}};
  m.label_set = {0, 1};
  return m;
}

TEST(RoundSafeNudged, APiercingCornerIsMovedOutAtEveryScaleAndOffset) {
  int cases = 0;
  for (int k : {-30, -8, 0, 8, 30})
    for (double offset : {0.0, 1.0, 1e6}) {
      const double s = std::ldexp(1.0, k);
      const RoundedMesh start = piercing_corner({offset, -offset, offset}, s);
      const std::string name = "2^" + std::to_string(k) + " at " + std::to_string(offset);
      ASSERT_EQ(check_arrangement(start).violations, 1u) << name;
      const double step = grid_spacing(largest_magnitude(start.vertices), 0);
      const Nudged n = nudge_conflicts(start, step, std::numeric_limits<double>::infinity(), 16);
      EXPECT_EQ(n.violations, 0u) << name;
      EXPECT_TRUE(check_arrangement(n.mesh).ok()) << name;
      EXPECT_EQ(n.mesh.triangles, start.triangles) << name;
      EXPECT_GT(n.moved, 0u) << name;
      EXPECT_GT(n.max_move, 0.0) << name;
      // The first ring that helps: a few ulps (the corner one double below a plane of
      // slope 0; A's corners tilt it by half their move where B pierces it).
      EXPECT_LE(n.max_move, 8 * std::sqrt(3.0) * step * (1 + 1e-12)) << name;
      for (std::size_t v = 0; v < start.vertices.size(); ++v)
        EXPECT_LE(distance_bound(to_exact(start.vertices[v]), n.mesh.vertices[v]), n.max_move) << name << " " << v;
      ++cases;
    }
  std::printf("piercing corner: %d scales and offsets, each settled by nudging\n", cases);
}

TEST(RoundSafeNudged, NothingMovesBeyondTheLimit) {
  const RoundedMesh start = piercing_corner({0, 0, 0}, 1.0);
  const double step = grid_spacing(largest_magnitude(start.vertices), 0);
  const Nudged none = nudge_conflicts(start, step, 0.0, 16);
  EXPECT_EQ(none.violations, 1u);
  EXPECT_EQ(none.moved, 0u);
  EXPECT_EQ(none.mesh.vertices, start.vertices);
  // One round of the budget: the check only, no move.
  const Nudged once = nudge_conflicts(start, step, std::numeric_limits<double>::infinity(), 1);
  EXPECT_EQ(once.violations, 1u);
  EXPECT_EQ(once.moved, 0u);
  EXPECT_EQ(once.rounds, 1);
}

}  // namespace
