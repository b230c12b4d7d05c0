// arrangements/src/booleans/ray_winding.h (internal to the Boolean stage)
//
// winding_beyond<M>(o, soup, weights, boxes, operands): the operands' winding numbers at
// the point o + (d, e, e^2) for infinitesimals 0 < e << d (the cell just beyond o along
// +x), by a ray cast along +x from o against the soup, exactly:
//   a triangle abc adds sign(n_x) * (its weights) when the ray crosses it beyond o, where
//   n = (b - a) x (c - a) (crossing along its normal lowers the winding number by its
//   weight; the winding number is 0 far away);
//   the shift (0, e, e^2) is a symbolic perturbation: the ray never passes through an edge
//   or a corner; inside-ness is orient2d in the YZ projection, its zeros settled by the
//   signs of the edge's coordinates;
//   triangles whose plane holds o, or that are parallel to the ray (n_x = 0), add nothing
//   (the ray meets their plane before d, or never).
// o is a rational point in the soup's frame (any point; stage 6 uses the midpoint of an
// edge). boxes: per soup triangle, a box (lo, hi) of doubles that holds it: triangles
// whose box cannot meet the ray are skipped before any arithmetic.
// Exact (rational arithmetic, CGAL::Gmpq, on the triangles that pass the box test).
// Cost: O(#soup triangles) box tests.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "arrangements/triangle_soup.h"
#include "booleans/operand_weights.h"
#include "booleans/point_orient.h"

namespace arrangements {

namespace ray_detail {

template <class M>
ExactVec3 exact_vertex(const typename M::Vertex& v) {
  if constexpr (std::is_same_v<typename M::Vertex, Vec3>)
    return {CGAL::Gmpq(v[0]), CGAL::Gmpq(v[1]), CGAL::Gmpq(v[2])};
  else
    return M::to_input(v);
}

inline int sign_of(const CGAL::Gmpq& x) { return x > 0 ? 1 : x < 0 ? -1 : 0; }

// orient2d(p, q, o + (0, e, e^2)) in the YZ projection (y first, z second): never zero
// unless p and q project to one point.
inline int perturbed_side(const ExactVec3& p, const ExactVec3& q, const ExactVec3& o) {
  const CGAL::Gmpq qy = q[1] - p[1], qz = q[2] - p[2];
  const int s = sign_of(qy * (o[2] - p[2]) - qz * (o[1] - p[1]));
  if (s != 0) return s;
  if (qz != 0) return -sign_of(qz);
  return sign_of(qy);
}

}  // namespace ray_detail

template <class M>
std::vector<int> winding_beyond(const ExactVec3& o, const BasicTriangleSoup<typename M::Vertex>& soup,
                                const OperandWeights& weights, const std::vector<std::array<Vec3, 2>>& boxes,
                                int operands) {
  std::vector<int> w(operands, 0);
  Vec3 lo, hi;  // a box of doubles around o
  for (int k = 0; k < 3; ++k) {
    const double d = o[k].to_double();
    lo[k] = std::nextafter(d, -HUGE_VAL);
    hi[k] = std::nextafter(d, HUGE_VAL);
  }
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    if (weights.row_begin(t) == weights.row_end(t)) continue;
    const Vec3& tlo = boxes[t][0];
    const Vec3& thi = boxes[t][1];
    if (thi[0] < lo[0] || thi[1] < lo[1] || tlo[1] > hi[1] || thi[2] < lo[2] || tlo[2] > hi[2]) continue;
    const ExactVec3 a = ray_detail::exact_vertex<M>(soup.vertices[soup.triangles[t][0]]);
    const ExactVec3 b = ray_detail::exact_vertex<M>(soup.vertices[soup.triangles[t][1]]);
    const ExactVec3 c = ray_detail::exact_vertex<M>(soup.vertices[soup.triangles[t][2]]);
    // n_x: orient2d(a, b, c) in YZ
    const int nx = ray_detail::sign_of((b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]));
    if (nx == 0) continue;
    if (ray_detail::perturbed_side(a, b, o) != nx || ray_detail::perturbed_side(b, c, o) != nx ||
        ray_detail::perturbed_side(c, a, o) != nx)
      continue;
    const int side = tritri::to_int(orient3d_points(a, b, c, o));  // sign of n . (o - a)
    if (side == 0 || side == nx) continue;  // o on the plane, or the plane behind o
    for (auto it = weights.row_begin(t); it != weights.row_end(t); ++it) w[it->first] += nx * it->second;
  }
  return w;
}

}  // namespace arrangements
