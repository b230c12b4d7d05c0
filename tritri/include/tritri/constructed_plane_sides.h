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
// Exact: every sign is tritri::orient3d on ImplicitPoint. A plane that common_plane finds
// from line corners may be degenerate (collinear corners); its signs are then all zero,
// and the tests answer false. Cost: the incidence look-up, a few dozen double
// comparisons per triangle (or none, given the planes); then one orient3d per sign asked.
#pragma once

#include <array>
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

  Sign operator()(int t, int k) const {
    const ImplicitPoint& q = (*tri_[1 - t])[k];
    if (!corners_[t]) {
      const Triangle& own = *tri_[t];
      return orient3d(own[0], own[1], own[2], q);
    }
    const detail::PlaneCorners& c = *corners_[t];
    return orient3d(ImplicitPoint::explicit_point(*c[0]), ImplicitPoint::explicit_point(*c[1]),
                    ImplicitPoint::explicit_point(*c[2]), q);
  }

 private:
  const Triangle* tri_[2];
  ConstructedPlane corners_[2];
};

}  // namespace tritri
