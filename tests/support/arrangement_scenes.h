// tests/support/arrangement_scenes.h
//
// Scenes for the arrangement tests (triangulation, counts, labels, threads), each with
// what makes it interesting derived by hand in its comment: two triangles crossing or
// piercing, three meeting in one triple point, spheres, boxes and grids crossing or
// sharing cells, coplanar overlapping squares and triangles with labels and sources, stars
// of David (coplanar edge crossings, integer and non-dyadic); hand_soup writes a soup by
// hand, scaled / scaled_pow2 rescale one, generated_scenes lists the scenes of the
// whole-arrangement checks (the two largest shrink below TRITRI_TEST_SCALE 0.5).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "arrangements/triangle_soup.h"
#include "support/mesh_generators.h"

#include "test_scale.h"

namespace tritri_test::arrangement {

using namespace ::arrangements;

// A soup written by hand: one label set per triangle index in `labels` (default all 0 with
// label_sets {{0}}), `source` defaults to the triangle index.
inline TriangleSoup hand_soup(std::vector<Vec3> vertices, std::vector<Tri> triangles, std::vector<int> labels = {},
                              std::vector<LabelSet> label_sets = {{0}}, std::vector<std::int64_t> source = {}) {
  TriangleSoup s;
  s.vertices = std::move(vertices);
  s.triangles = std::move(triangles);
  s.label_set = labels.empty() ? std::vector<int>(s.triangles.size(), 0) : std::move(labels);
  s.label_sets = std::move(label_sets);
  if (source.empty())
    for (std::size_t i = 0; i < s.triangles.size(); ++i) source.push_back(static_cast<std::int64_t>(i));
  s.source = std::move(source);
  return s;
}

inline TriangleSoup scaled(TriangleSoup s, double factor) {
  for (Vec3& v : s.vertices)
    for (double& x : v) x *= factor;
  return s;
}
inline TriangleSoup scaled_pow2(TriangleSoup s, int k) {
  for (Vec3& v : s.vertices)
    for (double& x : v) x = std::ldexp(x, k);
  return s;
}

// A in z = 0; B in the plane y = 1 crosses A along (1,1,0)-(2,1,0): each end is a crossing
// of an edge of B with the interior of A.
inline TriangleSoup two_triangles_crossing() {
  return hand_soup({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, -1}, {3, 1, -1}, {1, 1, 1}}, {{0, 1, 2}, {3, 4, 5}}, {0, 1},
                   {{0}, {1}});
}

// B pierces A: the intersection runs from p = (1,1,0) (B's edge (1,1,-1)-(1,1,1) through
// A's interior) to q = (3,1,0) (A's edge x + y = 4 through B's interior).
inline TriangleSoup triangle_pierced() {
  return hand_soup({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, -1}, {1, 1, 1}, {6, 1, 0.5}}, {{0, 1, 2}, {3, 4, 5}},
                   {0, 1}, {{0}, {1}});
}

// Three triangles in the planes z = 0 (A), y = 0 (B), x = 0 (C), each crossing the other
// two, all three through the origin O (inside each). On the axes:
//   x: A covers [-1, 3], B [-2, 2]: A n B = [-1, 2] x {0} x {0}, -1 on A's edge, 2 on B's;
//   y: A covers [-1, 3], C [-2, 1]: A n C = [-1, 1], -1 on A's edge, 1 on C's;
//   z: B covers [-1, 2], C [-2, 1]: B n C = [-1, 1], -1 on B's edge, 1 on C's.
// In each triangle the two segments cross at O: one TPI.
inline TriangleSoup three_triangles_triple_point() {
  return hand_soup({{-1, -1, 0},
                    {4, -1, 0},
                    {-1, 4, 0},  // A: x >= -1, y >= -1, x + y <= 3
                    {-2, 0, -1},
                    {3, 0, -1},
                    {-2, 0, 4},  // B: x >= -2, z >= -1, x + z <= 2
                    {0, -2, -2},
                    {0, 3, -2},
                    {0, -2, 3}},  // C: y >= -2, z >= -2, y + z <= 1
                   {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}}, {0, 1, 2}, {{0}, {1}, {2}});
}

// Three spheres, centres near an equilateral triangle of side 1, radii near 1: every two
// cross in one closed curve, and all three meet in two triple points (near
// (0.5, 0.29, +-0.82)).
inline TriangleSoup three_spheres(int rings = 10) {
  return concatenate(
      concatenate(uv_sphere({0, 0, 0}, 1.0, rings, rings + 4), uv_sphere({1, 0.05, 0.02}, 0.95, rings - 1, rings + 3)),
      uv_sphere({0.45, 0.85, -0.03}, 1.05, rings + 1, rings + 2));
}

inline TriangleSoup two_spheres() {
  return concatenate(uv_sphere({0, 0, 0}, 1.0, 10, 16), uv_sphere({0.7, 0.3, 0.2}, 0.8, 9, 14));
}
inline TriangleSoup cube_through_cube() {
  return concatenate(box({0, 0, 0}, {2, 2, 2}), box({1, -1, 0.5}, {3, 3, 1.5}));
}
inline TriangleSoup coplanar_grids() { return concatenate(grid(6, 1.0, 0.0), grid(5, 1.0, 0.0, 0.5, 0.25)); }
inline TriangleSoup grids_sharing_cells() { return concatenate(grid(4, 1.0, 0.0), grid(4, 1.0, 0.0, 1.0, 0.0)); }
inline TriangleSoup grid_through_sphere() {
  return concatenate(grid(8, 0.25, 0.0, -1, -1), uv_sphere({0, 0, 0}, 0.9, 8, 12));
}

// Two squares [0,2]^2 and [1,3]^2 in z = 0, two triangles each, with their diagonals on
// the same line y = x; labels 0 and 1, sources 100, 101 and 200, 201.
inline TriangleSoup overlapping_squares() {
  return hand_soup({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}},
                   {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}}, {0, 0, 1, 1}, {{0}, {1}}, {100, 101, 200, 201});
}

// Two coplanar triangles T0 = (0,0),(4,0),(0,4) (label 0, source 100) and T1 = (1,1),(5,1),
// (1,5) (label 1, source 200) in z = 0; `t1_first` lists T1 first.
inline TriangleSoup overlapping_triangles(bool t1_first) {
  std::vector<Vec3> V = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0}, {5, 1, 0}, {1, 5, 0}};
  if (t1_first) return hand_soup(V, {{3, 4, 5}, {0, 1, 2}}, {0, 1}, {{1}, {0}}, {200, 100});
  return hand_soup(V, {{0, 1, 2}, {3, 4, 5}}, {0, 1}, {{0}, {1}}, {100, 200});
}

// A star of David (two coplanar triangles whose edges cross in six points) in the plane
// z = cz + ax x + ay y, from 2D corners.
struct Star {
  std::array<std::array<double, 2>, 6> corners;  // A = 0, 1, 2; B = 3, 4, 5
  double cz, ax, ay;
  Vec3 lift(const std::array<double, 2>& p) const { return {p[0], p[1], cz + ax * p[0] + ay * p[1]}; }
  TriangleSoup soup() const {
    std::vector<Vec3> V;
    for (const auto& c : corners) V.push_back(lift(c));
    return hand_soup(V, {{0, 1, 2}, {3, 4, 5}}, {0, 1}, {{0}, {1}}, {100, 200});
  }
};
// Integer corners; crossings (4,0), (8,0), (4,8), (8,8), (2,4), (10,4).
inline const Star kIntegerStar{{{{0, 0}, {12, 0}, {6, 12}, {0, 8}, {6, -4}, {12, 8}}}, 0, 1, 2};
// Dyadic corners, non-dyadic crossings (21/20, 7/4), ...: the LPIs are not doubles.
inline const Star kRationalStar{{{{0, 0}, {3, 0}, {1.5, 2.5}, {0, 1.75}, {1.5, -0.75}, {3, 1.75}}}, 1, 0.25, -0.5};

// The scenes of the whole-arrangement checks; the two largest shrink below scale 0.5.
inline std::vector<std::pair<std::string, TriangleSoup>> generated_scenes() {
  const bool full = test_scale() >= 0.5;
  return {
      {"two triangles crossing", two_triangles_crossing()},
      {"triangle pierced", triangle_pierced()},
      {"two spheres", two_spheres()},
      {"cube through cube", cube_through_cube()},
      {"coplanar grids", coplanar_grids()},
      {"grids sharing cells", grids_sharing_cells()},
      {"grid through sphere", grid_through_sphere()},
      {"overlapping squares", overlapping_squares()},
      {"star of David", kIntegerStar.soup()},
      {"rational star", kRationalStar.soup()},
      {"rotated spheres",
       full ? rotated_copies(uv_sphere({0, 0, 0}, 1.0, 6, 10), 4) : rotated_copies(uv_sphere({0, 0, 0}, 1.0, 4, 6), 3)},
      {"three triangles, triple point", three_triangles_triple_point()},
      {"three spheres", three_spheres(full ? 10 : 6)},
      {"rotated boxes", rotated_copies(box({0, 0, 0}, {2, 1, 1}), 4)},
      {"rotated grids", rotated_copies(grid(4, 1.0, 0.0), 3)},
  };
}

}  // namespace tritri_test::arrangement
