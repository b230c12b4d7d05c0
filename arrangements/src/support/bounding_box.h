// BoundingBox: the axis-aligned box of double points, its centre and its diagonal. The one
// definition that round_safe's move limit (rounding/round_mesh.cpp), the generators
// (mesh_generators.cpp) and the tests measure models and place copies with, and that
// coplanar sharing and covers (stages 4 and 5) reject far points with. Exact for the
// box itself (min and max); centre and diagonal are rounded doubles, measures, never
// decisions.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "arrangements/triangle_soup.h"

namespace arrangements {

struct BoundingBox {
  Vec3 lo{}, hi{};
  bool empty = true;

  void add(const Vec3& p) {
    if (empty) {
      lo = hi = p;
      empty = false;
      return;
    }
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  Vec3 centre() const { return {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2}; }
  double diagonal() const { return empty ? 0.0 : std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]); }
  double extent() const { return empty ? 0.0 : std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}); }
};

// The box of `points` (empty when there are none). O(n).
inline BoundingBox bounding_box(const std::vector<Vec3>& points) {
  BoundingBox b;
  for (const Vec3& p : points) b.add(p);
  return b;
}

// A box that certainly holds triangle t of V in point model M (models/point_model.h): the
// box of its corners' M::bounds (exact for doubles, conservative for rationals). O(1).
template <class M>
BoundingBox triangle_bounds(const std::vector<typename M::Vertex>& V, const Tri& t) {
  BoundingBox b;
  for (int k = 0; k < 3; ++k) {
    Vec3 lo, hi;
    M::bounds(V[t[k]], lo, hi);
    b.add(lo);
    b.add(hi);
  }
  return b;
}

}  // namespace arrangements
