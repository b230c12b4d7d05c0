// arrangements/src/support/mesh_generators.h
//
// Generated test meshes: the project's embedded default inputs (no download needed) and
// the inputs of the tests with known answers. Coordinates are doubles computed with
// ordinary rounding; the pipeline treats them as exact.
//
//   uv_sphere       closed sphere, `rings` x `segments` quads split into triangles
//   box             closed axis-aligned box, 12 triangles
//   grid            flat n x n grid of squares (2 n^2 triangles) in the plane z = z0,
//                   with exactly representable (dyadic) coordinates
//   rotated_copies  k copies of a soup rotated about the z axis through its bounding-box
//                   centre by 2*pi*i/k (a workload whose intersections grow with k^2)
//   rotation_matrix Rodrigues' matrix of the turn by an angle about a unit axis, in doubles
//   turned          a soup turned by an angle about a unit axis through a centre, then
//                   moved (rotation_matrix)
//   concatenate     the union of soups, each part's label sets shifted past those of the
//                   parts before it (two one-label parts: labels 0 and 1); no polygon ids
//
// All return a TriangleSoup with one label set {0} (concatenate: the parts' label sets)
// and `source` = triangle index.
#pragma once

#include <array>
#include <vector>

#include "arrangements/triangle_soup.h"

namespace arrangements {

TriangleSoup uv_sphere(const Vec3& centre, double radius, int rings, int segments);
TriangleSoup box(const Vec3& lo, const Vec3& hi);
TriangleSoup grid(int n, double cell, double z0, double x0 = 0, double y0 = 0);
TriangleSoup rotated_copies(const TriangleSoup& soup, int k);
using RotationMatrix = std::array<std::array<double, 3>, 3>;
RotationMatrix rotation_matrix(const Vec3& axis, double angle);
TriangleSoup turned(TriangleSoup soup, const Vec3& centre, const Vec3& axis, double angle, const Vec3& shift);
TriangleSoup concatenate(const std::vector<TriangleSoup>& parts);
TriangleSoup concatenate(const TriangleSoup& a, const TriangleSoup& b);  // concatenate({a, b})

}  // namespace arrangements
