// nudge_conflicts (arrangements/src/rounding/round_nudged.h) on its own: a corner of one triangle
// an ulp through another's face, at magnitudes 2^-30 to 2^30 and offsets up to 1e6, is
// moved out of it by a few ulps; the result passes the exact check (check_arrangement)
// with the same triangles, every vertex within the reported move of where it started;
// with a move limit of 0 nothing moves and the violation stays. The class of what
// nudging settles inside round_safe (grazing copies of a sphere, layers an ulp apart) is
// in test_round_safe.cpp, test_round_safe_input.cpp and test_round_safe_contacts.cpp.
// Nudging in cycles (round_mesh.h: where it stalls, its mesh arranged again, rerouted and
// nudged again) on the region of a turned copy of manifold's openscad-nonmanifold-crash
// (faces crossing at 1e-5 rad beside triangles a few thousand ulps wide), which the single
// nudging left at 149 conflicts in the whole copy and which round_safe refused before.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "arrangements/arrange.h"
#include "arrangements/as_input.h"
#include "arrangements/check_arrangement.h"
#include "arrangements/load_triangle_soup.h"
#include "rounding/round_nudged.h"
#include "rounding/rounding_grid.h"
#include "support/safe_rounding_checks.h"
#include "support/shared_meshes.h"
#include "support/sweep_variants.h"
#include "support/test_scale.h"

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

// The sweep's rot2 variant of the mesh (support/sweep_variants.h), cropped to the triangles
// whose boxes meet the box of the copy's triangles 35, 217, 258, 260, 261 and 283 (where
// the conflicts were), vertices in first-index order.
TriangleSoup turned_crash_region(const TriangleSoup& mesh) {
  const TriangleSoup both = tritri_test::sweep_rot2(mesh);
  const std::vector<Vec3>& V = both.vertices;
  const std::vector<Tri>& F = both.triangles;
  const std::size_t copy = mesh.triangles.size();
  Vec3 rlo = V[F[copy + 35][0]], rhi = rlo;
  for (int r : {35, 217, 258, 260, 261, 283})
    for (int v : F[copy + r])
      for (int k = 0; k < 3; ++k) rlo[k] = std::min(rlo[k], V[v][k]), rhi[k] = std::max(rhi[k], V[v][k]);
  std::vector<Tri> kept;
  std::set<int> used;
  for (const Tri& f : F) {
    bool meets = true;
    for (int k = 0; k < 3; ++k)
      meets = meets && std::min({V[f[0]][k], V[f[1]][k], V[f[2]][k]}) <= rhi[k] &&
              std::max({V[f[0]][k], V[f[1]][k], V[f[2]][k]}) >= rlo[k];
    if (!meets) continue;
    kept.push_back(f);
    used.insert(f.begin(), f.end());
  }
  TriangleSoup out;
  std::vector<int> index(V.size(), -1);
  for (int v : used) {
    index[v] = static_cast<int>(out.vertices.size());
    out.vertices.push_back(V[v]);
  }
  for (const Tri& f : kept) out.triangles.push_back({index[f[0]], index[f[1]], index[f[2]]});
  for (std::size_t i = 0; i < out.triangles.size(); ++i) out.source.push_back(static_cast<std::int64_t>(i));
  if (!mesh.polygon.empty()) out.polygon = out.source;  // every face of the file a triangle, as arrange reads it
  out.label_set.assign(out.triangles.size(), 0);
  out.label_sets = {{0}};
  return out;
}

TEST(NudgeConflicts, InCyclesSettlesTheTurnedOpenscadCrashRegion) {
  const auto path = tritri_test::shared_meshes_dir() / "manifold_tests" / "openscad-nonmanifold-crash.obj";
  TRITRI_REQUIRE_DATA(path);
  // About 20 s in Release; under the sanitizers' reduced scale it would take minutes.
  if (tritri_test::test_scale() < 0.5) GTEST_SKIP() << "the crash region runs at TRITRI_TEST_SCALE >= 0.5";
  const TriangleSoup mesh = load_triangle_soup(path.string());
  ASSERT_EQ(mesh.triangles.size(), 1442u);
  const TriangleSoup region = turned_crash_region(mesh);
  ASSERT_EQ(region.triangles.size(), 198u);
  const ArrangeResult exact = arrange(region, ArrangeOptions{});
  ASSERT_GT(exact.stats.intersection_points, 0u);
  bool nearest_ok = true;
  const RoundReport report = tritri_test::rounding::expect_safe_rounding(exact.mesh, "turned crash region",
                                                                         nearest_ok, &region);
  EXPECT_FALSE(nearest_ok);
  EXPECT_GT(report.nudged, 0u);
  EXPECT_GT(report.snapped_vertices, 0u);
  EXPECT_LE(report.max_move_relative, 1e-12);
  std::printf("turned crash region: %zu triangles, %d passes, %zu snapped, %zu rerouted, %zu nudged, move %.3g of the "
              "diagonal\n",
              region.triangles.size(), report.passes, report.snapped_vertices, report.rerouted, report.nudged,
              report.max_move_relative);
}

}  // namespace
