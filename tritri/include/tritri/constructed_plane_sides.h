// tritri/constructed_plane_sides.h
//
// ConstructedPlaneSides(a, b): the plane signs of two triangles of implicit points, each
// against a plane that holds the other triangle by construction: a defining plane of its
// corners (the input triangle's plane its LPIs and TPIs were built on), found by
// detail::common_plane without arithmetic; the triangle's own corners when none is known.
// It is the `side` argument of meet_only_in_shared_by_sides and separated_by_plane
// (shared_vertices.h): side(t, k) is the exact sign of corner k of the other triangle
// against triangle t's plane, up to one sign per t, which those tests allow (they only
// compare the signs of one t with each other and with zero).
//
// Why: triangles of an arrangement lie in their source triangles' planes, which are three
// explicit corners. Their signs are orient3d with three explicit operands (degree 6 in
// the input coordinates), where the orient3d of a triangle's own corners has up to three
// implicit ones (degree up to 15). On near-coincident input (subnormal offsets beside
// O(1) coordinates, issue 36) both reach the exact stage, whose cost grows with the
// degree; and the signs settle in 1 to 6 what the projection and classification tests
// take dozens of orient2d for.
//
// same_plane(): both triangles lie on one defining plane by construction, so every sign
// is zero (coplanar: the caller goes to the tests in a projection).
//
// SourcePlaneKernel: the same signs inside tritri::classify of the pair. The orient3d of a
// triangle's own corners against x is orientation_in_plane (+-1, one evaluation per
// triangle, source_plane) times x's sign against the source plane.
//
// Exact: every sign is tritri::orient3d on ImplicitPoint. A plane that common_plane finds
// from line corners may be degenerate (collinear corners); its signs are then all zero,
// and the tests answer false. Cost: the incidence look-up, a few dozen double
// comparisons per triangle (or none, given the planes); then one orient3d per sign asked.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "tritri/detail/incidence.h"
#include "tritri/implicit_point.h"
#include "tritri/implicit_predicates.h"

namespace tritri {

// The plane that holds triangle (a, b, c) by construction, as three explicit corners
// (pointers into the points' or their defining points' storage), if one is known.
using ConstructedPlane = std::optional<detail::PlaneCorners>;
inline ConstructedPlane constructed_plane(const ImplicitPoint& a, const ImplicitPoint& b, const ImplicitPoint& c) {
  return detail::common_plane({&a, &b, &c});
}

class ConstructedPlaneSides {
 public:
  using Triangle = std::array<ImplicitPoint, 3>;
  ConstructedPlaneSides(const Triangle& a, const Triangle& b)
      : ConstructedPlaneSides(a, b, constructed_plane(a[0], a[1], a[2]), constructed_plane(b[0], b[1], b[2])) {}
  // With the planes already found (constructed_plane of a's and of b's corners), e.g.
  // once per triangle of a mesh whose pairs are tested.
  ConstructedPlaneSides(const Triangle& a, const Triangle& b, const ConstructedPlane& plane_a,
                        const ConstructedPlane& plane_b)
      : tri_{&a, &b}, corners_{plane_a, plane_b} {}

  bool same_plane() const { return corners_[0] && corners_[1] && detail::same_plane(*corners_[0], *corners_[1]); }

  // The sign of corner k of the other triangle (computed once, then remembered).
  Sign operator()(int t, int k) const {
    if (known_[t][k] == kUnknown) known_[t][k] = static_cast<signed char>(to_int(side_of(t, (*tri_[1 - t])[k])));
    return detail::to_sign(known_[t][k]);
  }

  // The sign of any point q against triangle t's plane, same convention.
  Sign side_of(int t, const ImplicitPoint& q) const {
    if (!corners_[t]) {
      const Triangle& own = *tri_[t];
      return orient3d(own[0], own[1], own[2], q);
    }
    const detail::PlaneCorners& c = *corners_[t];
    return orient3d(ImplicitPoint::explicit_point(*c[0]), ImplicitPoint::explicit_point(*c[1]),
                    ImplicitPoint::explicit_point(*c[2]), q);
  }

  const Triangle& triangle(int t) const { return *tri_[t]; }

 private:
  static constexpr signed char kUnknown = 2;
  const Triangle* tri_[2];
  ConstructedPlane corners_[2];
  mutable signed char known_[2][3] = {{kUnknown, kUnknown, kUnknown}, {kUnknown, kUnknown, kUnknown}};
};

// +1 when orient3d(a0, a1, a2, x) has the sign of orient3d(r, s, u, x) for every x, where
// (r, s, u) = plane's corners (both are multiples of one determinant when the triangle
// lies on the plane); -1 when the signs are opposite; 0 when not known (no plane, or the
// plane or the triangle degenerate). Decided on one explicit point off the plane, far from
// it (the triangle's orient3d there is rarely near zero). Exact. Cost: up to 3 orient3d
// on doubles and one with the three implicit corners.
inline int orientation_in_plane(const ConstructedPlane& plane, const ImplicitPoint& a0, const ImplicitPoint& a1,
                                const ImplicitPoint& a2) {
  if (!plane) return 0;
  const detail::PlaneCorners& c = *plane;
  double extent = 0;
  for (int i = 1; i < 3; ++i)
    for (int m = 0; m < 3; ++m) extent = std::max(extent, std::fabs((*c[i])[m] - (*c[0])[m]));
  const ImplicitPoint r = ImplicitPoint::explicit_point(*c[0]), s = ImplicitPoint::explicit_point(*c[1]),
                      u = ImplicitPoint::explicit_point(*c[2]);
  for (int k = 0; k < 3; ++k) {
    ImplicitPoint::Coords off = *c[0];
    off[k] += std::fabs(off[k]) + extent;  // leaves the plane unless it contains axis k's direction
    if (!std::isfinite(off[k])) continue;
    const ImplicitPoint x = ImplicitPoint::explicit_point(off);
    const int o = to_int(orient3d(r, s, u, x));
    if (o != 0) return o * to_int(orient3d(a0, a1, a2, x));
  }
  return 0;
}

// A triangle's constructed plane and its orientation in it (orientation_in_plane), found
// once per triangle of a mesh whose pairs are tested.
struct SourcePlane {
  ConstructedPlane corners;
  int orientation = 0;
};
inline SourcePlane source_plane(const ImplicitPoint& a0, const ImplicitPoint& a1, const ImplicitPoint& a2) {
  SourcePlane p;
  p.corners = constructed_plane(a0, a1, a2);
  p.orientation = orientation_in_plane(p.corners, a0, a1, a2);
  return p;
}

// The kernel for classifying the pair of `sides` (tritri::classify(kernel, a0, ..., b2)
// with the same point objects): orient3d of a triangle's corners, in their order, against
// any point is its orientation times the sign against its source plane (the signs
// `sides` already found are reused); everything else is ImplicitKernel's. orientation[t]
// is orientation_in_plane of triangle t (0: no substitution). Exact, as ImplicitKernel.
struct SourcePlaneKernel {
  using Point = ImplicitPoint;
  const ConstructedPlaneSides* sides;
  int orientation[2];

  Sign orient3d(const Point& p, const Point& q, const Point& r, const Point& x) const {
    for (int t = 0; t < 2; ++t) {
      const ConstructedPlaneSides::Triangle& tri = sides->triangle(t);
      if (orientation[t] == 0 || &p != &tri[0] || &q != &tri[1] || &r != &tri[2]) continue;
      const ConstructedPlaneSides::Triangle& other = sides->triangle(1 - t);
      for (int k = 0; k < 3; ++k)
        if (&x == &other[k]) return detail::to_sign(orientation[t] * to_int((*sides)(t, k)));
      return detail::to_sign(orientation[t] * to_int(sides->side_of(t, x)));
    }
    return tritri::orient3d(p, q, r, x);
  }
  Sign orient2d(const Point& a, const Point& b, const Point& c, Plane plane) const {
    return tritri::orient2d(a, b, c, plane);
  }
  bool equal(const Point& a, const Point& b) const { return tritri::equal(a, b); }
  bool less(const Point& a, const Point& b) const { return tritri::less(a, b); }
};

}  // namespace tritri
