// tritri/projection.h
//
// projection: the axis-aligned plane in which a triangle's projection is not degenerate,
// and the triangle's orientation there. Every exact 2D test on a triangle (locating a
// point of its plane in it, the coplanar case of classify, triangulating it) needs one;
// this is the one place that chooses it. dominant_plane is a rounded, inexact hint of the
// best-conditioned plane for callers that care about filter speed.
//
//   const auto [plane, orientation] = tritri::projection(k, a, b, c);
//   if (orientation == 0) { /* a, b, c are collinear (or equal): degenerate */ }
//   // else: sign(orient2d(a, b, c, plane)) == orientation != 0
//
// The planes are tried in the cyclic order XY -> YZ -> ZX -> XY, starting at `first`
// (next_plane). Starting at XY gives XY, YZ, ZX; starting at dominant_plane(a, b, c)
// tries the best-conditioned plane first and then the others in the same cyclic order.
#pragma once

#include <array>
#include <cmath>
#include <concepts>
#include <utility>

#include "tritri/sign.h"

namespace tritri {

// The plane after p in the cyclic order XY -> YZ -> ZX -> XY.
// Exact, O(1).
constexpr Plane next_plane(Plane p) noexcept {
  return p == Plane::XY ? Plane::YZ : (p == Plane::YZ ? Plane::ZX : Plane::XY);
}

// The first plane, starting at `first` and going on in the cyclic order of next_plane, in
// which the projection of triangle (a, b, c) is not degenerate, with the triangle's
// orientation there (+1 or -1: the sign of k.orient2d(a, b, c, plane)).
//
// Inputs:  k     anything with k.orient2d(a, b, c, Plane) -> Sign (every tritri::Kernel,
//                e.g. DoubleKernel, ImplicitKernel, CountingKernel<...>);
//          a, b, c  the triangle's vertices (P = the kernel's point type);
//          first    the plane tried first (default XY: XY, YZ, ZX).
// Output:  {plane, orientation}; {first, 0} when all three projections are degenerate,
//          i.e. iff a, b, c are collinear (three points are collinear iff their three
//          axis projections are), so orientation == 0 is the exact degeneracy test.
// Preconditions: none beyond the kernel's (e.g. finite coordinates for DoubleKernel).
// Exactness: exact whenever k.orient2d is; no tolerance, no construction.
// Complexity: 1 to 3 calls of k.orient2d(a, b, c, plane), in the order above, stopping at
//          the first non-zero one (callers that count predicates rely on that sequence).
template <class K, class P>
std::pair<Plane, int> projection(const K& k, const P& a, const P& b, const P& c, Plane first = Plane::XY) {
  Plane p = first;
  for (int i = 0; i < 3; ++i, p = next_plane(p)) {
    const int s = to_int(k.orient2d(a, b, c, p));
    if (s != 0) return {p, s};
  }
  return {first, 0};
}

// A hint for `first` in projection(): the plane that drops the coordinate of the largest
// component (in absolute value) of the normal (b - a) x (c - a), computed in rounded
// double arithmetic; ties go to the lower axis (x before y before z). The projection onto
// that plane has the largest area, so orient2d there is the best conditioned and its
// floating-point filters decide the most often.
//
// Inputs:  a, b, c  the triangle's vertices as double coordinates.
// Output:  YZ (normal mostly along x), ZX (along y) or XY (along z).
// Preconditions: none; with overflow or NaN the answer is still one of the three planes.
// Exactness: NOT exact: rounding may pick a plane in which the triangle's projection is
//          degenerate (or, for a degenerate triangle, any plane). Use it only as the
//          `first` of projection(), which checks every choice exactly.
// Complexity: O(1), a few floating-point operations, no predicate.
inline Plane dominant_plane(const std::array<double, 3>& a, const std::array<double, 3>& b,
                            const std::array<double, 3>& c) noexcept {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double n[3] = {std::fabs(uy * vz - uz * vy), std::fabs(uz * vx - ux * vz), std::fabs(ux * vy - uy * vx)};
  const int dominant = n[0] >= n[1] ? (n[0] >= n[2] ? 0 : 2) : (n[1] >= n[2] ? 1 : 2);
  // The plane that drops axis x, y, z.
  constexpr Plane dropping[3] = {Plane::YZ, Plane::ZX, Plane::XY};
  return dropping[dominant];
}

// For points of other kernels (e.g. CGAL points with rational coordinates): the middle of
// their interval approximations (CGAL's lazy kernels), else their CGAL::to_double
// approximations when they have them, else XY; projection() checks the choice exactly
// either way.
template <class P>
Plane dominant_plane(const P& a, const P& b, const P& c) {
  if constexpr (requires { a.approx()[0].inf(); }) {  // no construction: reads the cached intervals
    auto approx = [](const P& p) {
      const auto& i = p.approx();
      return std::array<double, 3>{0.5 * i[0].inf() + 0.5 * i[0].sup(), 0.5 * i[1].inf() + 0.5 * i[1].sup(),
                                   0.5 * i[2].inf() + 0.5 * i[2].sup()};
    };
    return dominant_plane(approx(a), approx(b), approx(c));
  } else if constexpr (requires {
                         { a.approx() } -> std::convertible_to<std::array<double, 3>>;
                       }) {  // tritri::ImplicitPoint: its cached rounded coordinates
    return dominant_plane(a.approx(), b.approx(), c.approx());
  } else if constexpr (requires { to_double(a.x()); }) {  // found by argument-dependent lookup
    auto approx = [](const P& p) {
      return std::array<double, 3>{to_double(p.x()), to_double(p.y()), to_double(p.z())};
    };
    return dominant_plane(approx(a), approx(b), approx(c));
  } else {
    return Plane::XY;
  }
}

}  // namespace tritri
