// Safe rounding's plane snap (snap_near_coplanar_faces, round_snapped_planes.h) on faces whose
// layers are linked only through small triangles. Turned in doubles, a small triangle's plane
// tilts by its corners' rounding errors over its size: a large face's corners lie far off it,
// so the two are not linked although both lie on one plane. Each group then got a plane of its
// own, nearly parallel, and the layers crossed again after snapping (a turned OpenSCAD model:
// 17,249 conflicts left of 23,402). Groups that lie within delta of a neighbouring layered
// group's plane now join it: every corner lands exactly on one plane. Checked exactly on
// generated faces turned about random axes, then end to end on turned boxes with coplanar
// faces, with every check of support/safe_rounding_checks.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "arrangements/arrange.h"
#include "arrangements/round_mesh.h"
#include "rounding/round_snapped_planes.h"
#include "support/bounding_box.h"
#include "support/exact_oracle.h"
#include "support/mesh_generators.h"
#include "support/random_turns.h"
#include "support/safe_rounding_checks.h"

namespace {

using namespace arrangements;
using tritri_test::turn_angle;
using tritri_test::unit_axis;

TriangleSoup triangles(const std::vector<Vec3>& vertices, unsigned label) {
  TriangleSoup s;
  s.vertices = vertices;
  for (std::size_t i = 0; i + 2 < vertices.size(); i += 3) {
    const int a = static_cast<int>(i);
    s.triangles.push_back({a, a + 1, a + 2});
    s.label_set.push_back(0);
    s.source.push_back(static_cast<std::int64_t>(i / 3));
  }
  s.label_sets = {{label}};
  return s;
}

// Two large overlapping triangles (one layered group) and, inside them, two small overlapping
// ones of size `small` (another), all in the plane z = 0: nothing shares a corner.
TriangleSoup large_and_small_layers(double small) {
  const double x = 0.3, y = 0.35;
  return concatenate(
      triangles({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.1, 0.1, 0}, {0.9, 0.05, 0}, {0.05, 0.9, 0}}, 0u),
      triangles({{x, y, 0},
                 {x + small, y, 0},
                 {x, y + small, 0},
                 {x + small / 4, y + small / 4, 0},
                 {x + small, y + small / 2, 0},
                 {x + small / 2, y + small, 0}},
                1u));
}

}  // namespace

TEST(RoundSafePlanes, SmallLayersOnALargeFaceLandOnItsPlane) {
  std::mt19937 rng(11);
  const double delta = std::ldexp(1.0, -48);  // 16 ulps of 1
  int off_before = 0;                          // turns where some corner lay off the large plane
  for (int i = 0; i < 40; ++i) {
    const double small = std::ldexp(1.0, -16 - i % 8);
    const TriangleSoup flat = large_and_small_layers(small);
    const TriangleSoup soup = turned(flat, {0.5, 0.5, 0}, unit_axis(rng), turn_angle(rng), {0, 0, 0});
    const ExactTriangleSoup original = to_exact(soup);
    using tritri_test::exact;
    auto off_plane = [](const ExactTriangleSoup& s, int v) {
      return tritri_test::orient3d(exact(s.vertices[0]), exact(s.vertices[1]), exact(s.vertices[2]),
                                   exact(s.vertices[v]));
    };
    for (int v = 3; v < 12; ++v) off_before += off_plane(original, v) != 0;
    const SnappedPlanes snapped = snap_near_coplanar_faces(soup, delta, 0, false);
    const std::string name = "turn " + std::to_string(i) + ", small 2^" + std::to_string(-16 - i % 8);
    // One plane for all four: every corner exactly on the plane of the first (large) triangle.
    for (int v = 3; v < 12; ++v) EXPECT_EQ(off_plane(snapped.soup, v), 0) << name << ", corner " << v;
    EXPECT_LE(snapped.max_move, 64 * std::sqrt(3.0) * delta) << name;
    EXPECT_EQ(snapped.soup.triangles, soup.triangles) << name;
  }
  EXPECT_GT(off_before, 0);  // the turns did move corners off the plane: the test tells something
}

TEST(RoundSafePlanes, TurnedBoxesWithSmallCoplanarFacesSettle) {
  // A box, a smaller box on its floor (their bottoms overlap in z = 0) and a tiny box on the
  // floor too, turned as one body: the tiny box's bottom lies on the floor's plane but is
  // linked to nothing large. Every case must settle (every check of expect_safe_rounding).
  std::mt19937 rng(5);
  int not_nearest = 0, snapped = 0;
  double largest = 0;
  for (int i = 0; i < 12; ++i) {
    const double tiny = std::ldexp(1.0, -14 - i % 4);
    const TriangleSoup body = concatenate({box({0, 0, 0}, {1, 1, 1}), box({0.25, 0.25, 0}, {0.75, 0.75, 0.5}),
                                           box({0.4, 0.1, 0}, {0.4 + tiny, 0.1 + tiny, tiny})});
    const TriangleSoup soup = turned(body, {0.5, 0.5, 0.5}, unit_axis(rng), turn_angle(rng), {0, 0, 0});
    const std::string name = "turned boxes " + std::to_string(i);
    const ArrangeResult first = arrange(soup, ArrangeOptions{});
    bool nearest_ok = true;
    try {
      const RoundReport report = tritri_test::rounding::expect_safe_rounding(first.mesh, name, nearest_ok, &soup);
      EXPECT_LE(report.max_move_relative, 1e-14) << name;
      not_nearest += !nearest_ok;
      snapped += !nearest_ok && report.snapped_vertices > 0;
      largest = std::max(largest, report.max_move_relative);
    } catch (const RoundingError& error) {
      ADD_FAILURE() << name << ": refused: " << error.what();
    }
  }
  std::printf("turned boxes: 12 cases, %d not settled by rounding to nearest, %d of those snapped, largest move %.3g\n",
              not_nearest, snapped, largest);
}
