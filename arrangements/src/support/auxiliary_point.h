// arrangements/src/support/auxiliary_point.h
//
// auxiliary_point(V, t) = auxiliary_point(a, b, c) of t's corners: an explicit point
// strictly off the plane of triangle t, with finite coordinates, deterministic in t's
// coordinates. Coplanar edge-edge crossings are LPIs whose plane is the other edge plus
// this point: that plane is transverse to the triangles' common plane, so the LPI is well
// defined whenever the edges cross properly.
//
// Construction: vertex a = V[t[0]] plus the rounded normal, if that is finite and off the
// plane (exact orient3d); otherwise a moved along one coordinate axis k. The second way is
// exact by construction for any finite input: for q = a + d e_k (d != 0 after rounding,
// i.e. q[k] != a[k]), orient3d(a, b, c, q) = d * n_k with n = (b - a) x (c - a) the exact
// normal, and n_k != 0 for some k when t is not degenerate. The step is tried as +-(the
// triangle's extent) and, where that rounds away next to a large coordinate (a sliver far
// from the origin) or overflows, as one ulp of a[k]; every candidate is checked exactly.
// Preconditions: t is not degenerate (its corners are not collinear), finite coordinates.
// Cost: O(1) (a few orient3d). Throws std::logic_error if t is degenerate.
#pragma once

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <tritri/double_predicates.h>

#include "arrangements/triangle_soup.h"

namespace arrangements {

inline Vec3 auxiliary_point(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const Vec3 n = {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
  const Vec3 along_normal = {a[0] + n[0], a[1] + n[1], a[2] + n[2]};
  auto finite = [](const Vec3& p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); };
  auto off_plane = [&](const Vec3& q) { return finite(q) && tritri::orient3d(a, b, c, q) != tritri::Sign::Zero; };
  if (off_plane(along_normal)) return along_normal;
  // The rounded normal can vanish, overflow or round into the plane (slivers, large
  // offsets): then a step along a coordinate axis, exact by the argument above.
  double m = 0;
  for (double x : {ux, uy, uz, vx, vy, vz}) m = std::fmax(m, std::fabs(x));
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k)
    for (double x : {a[k] + m, a[k] - m, std::nextafter(a[k], inf), std::nextafter(a[k], -inf)}) {
      if (x == a[k]) continue;
      Vec3 q = a;
      q[k] = x;
      if (off_plane(q)) return q;
    }
  throw std::logic_error("auxiliary_point: degenerate triangle (collinear corners)");
}

inline Vec3 auxiliary_point(const std::vector<Vec3>& V, const Tri& t) {
  return auxiliary_point(V[t[0]], V[t[1]], V[t[2]]);
}

}  // namespace arrangements
