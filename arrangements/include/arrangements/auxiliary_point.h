// arrangements/auxiliary_point.h
//
// auxiliary_point(V, F, t): an explicit point strictly off the plane of triangle t,
// deterministic in t's coordinates. Coplanar edge-edge crossings are LPIs whose plane is
// the other edge plus this point: that plane is transverse to the triangles' common
// plane, so the LPI is well defined whenever the edges cross properly.
//
// Construction: vertex 0 plus the (rounded) normal, checked exactly with orient3d; if that
// fails, vertex 0 moved along a coordinate axis. Preconditions: t is not
// degenerate. Cost: O(1).
#pragma once

#include <cmath>
#include <vector>

#include <tritri/double_predicates.h>

#include "arrangements/triangle_soup.h"

namespace arrangements {

inline Vec3 auxiliary_point(const std::vector<Vec3>& V, const Tri& t) {
  const Vec3 &a = V[t[0]], &b = V[t[1]], &c = V[t[2]];
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const Vec3 n = {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
  const Vec3 along_normal = {a[0] + n[0], a[1] + n[1], a[2] + n[2]};
  if (tritri::orient3d(a, b, c, along_normal) != tritri::Sign::Zero) return along_normal;
  // The rounded normal can vanish or round into the plane for slivers: then one of the
  // three axis directions, scaled like the triangle, leaves the plane (they span space).
  double m = 0;
  for (double x : {ux, uy, uz, vx, vy, vz}) m = std::fmax(m, std::fabs(x));
  for (int k = 0; k < 3; ++k) {
    Vec3 q = a;
    q[k] += m;
    if (tritri::orient3d(a, b, c, q) != tritri::Sign::Zero) return q;
  }
  return along_normal;  // unreachable for a proper triangle
}

}  // namespace arrangements
