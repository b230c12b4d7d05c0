// tritri/point_bounds.h
//
// x_bounds(p): an interval [lo, hi] that certainly contains the exact x coordinate of an
// implicit point (explicit points: [x, x]), from the filtered homogeneous coordinates the
// point caches. compare_xyz_bounded(p, bp, q, bq): tritri::compare_xyz, exactly, that
// settles pairs whose x intervals are disjoint with two double comparisons. For sorting
// many implicit points (deduplication), where most comparisons are between points far
// apart: the bounds are computed once per point instead of per comparison.
//
// box_bounds(p), orient2d_bounded(a, b, box, plane): a certified box around a point, and
// the sign of orient2d(a, b, x) for explicit a, b and every x in the box when a filter
// can tell (locating many implicit points in a triangle: most are decided without the
// point's filtered or exact predicate).
//
// direction_bounds(p), compare_along_direction(p, bp, q, bq): an interval for kSortDirection . p and an exact total
// order along a fixed direction, for deduplication by sorting (coincident points compare equal): structured inputs have
// many distinct points with exactly equal x, which compare_xyz can only separate with exact arithmetic (and caches it
// per point: memory).
//
// Why the interval holds: the cached X and W carry certified absolute errors e = gamma *
// perm (tritri/detail/filtered_value.h: depth * 2^-53 * (1 + 2^-20) * perm, the bound
// certified_sign uses). With |W^| > e_W, W has the sign of W^ and X / W lies between the
// quotients of the interval ends [X^ -+ e_X] / [|W^| -+ e_W] (signs folded into X). The
// four roundings on the way (two ends, one quotient, ...) are below 4u relative; the ends
// are widened by 2^-50 relative plus 2^-1070 absolute (underflow). Non-finite values, or
// |W^| <= e_W, give (-inf, +inf): the comparison then falls back to compare_xyz.
// Cost: a few flops per point; compare_xyz_bounded costs two comparisons when it decides.
#pragma once

#include <CGAL/Mpzf.h>

#include <array>
#include <cmath>
#include <utility>
#include <limits>

#include "tritri/detail/incidence.h"
#include "tritri/double_predicates.h"
#include "tritri/implicit_point.h"
#include "tritri/implicit_predicates.h"

namespace tritri {

struct XBounds {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
};

namespace detail {

// An interval that certainly contains N / W, for exact N, W with |N - n| <= en and
// |W - w| <= ew (see the top comment); (-inf, +inf) when |w| <= ew or anything is not
// finite.
inline XBounds quotient_bounds(double n, double en, double w, double ew) {
  const double s = w < 0 ? -1.0 : 1.0;
  w = std::fabs(w);
  n *= s;
  if (!(w > ew) || !std::isfinite(w) || !std::isfinite(n) || !std::isfinite(en) || !std::isfinite(ew)) return {};
  const double wl = w - ew, wh = w + ew, nl = n - en, nh = n + en;
  double lo = nl / (nl >= 0 ? wh : wl);
  double hi = nh / (nh >= 0 ? wl : wh);
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {};
  lo -= std::fabs(lo) * 0x1p-50 + 0x1p-1070;
  hi += std::fabs(hi) * 0x1p-50 + 0x1p-1070;
  return {lo, hi};
}

inline constexpr double kFilterGamma = 0x1p-53 * (1.0 + 0x1p-20);  // per rounding, as certified_sign

}  // namespace detail

namespace detail {

// An interval that certainly contains coordinate k (0, 1, 2: x, y, z) of p.
inline XBounds coordinate_bounds(const ImplicitPoint& p, int k) {
  if (p.is_explicit()) return {p.approx()[k], p.approx()[k]};
  const auto& f = p.filtered();
  const auto& d = ImplicitPoint::rounding_depth(p.kind());
  const FilteredValue& c = k == 0 ? f.x : (k == 1 ? f.y : f.z);
  const double depth = k == 0 ? d.x.depth : (k == 1 ? d.y.depth : d.z.depth);
  return quotient_bounds(c.v, c.perm * (depth * kFilterGamma), f.w.v, f.w.perm * (d.w.depth * kFilterGamma));
}

}  // namespace detail

inline XBounds x_bounds(const ImplicitPoint& p) { return detail::coordinate_bounds(p, 0); }

// A box that certainly contains p: x_bounds for each coordinate (explicit points: the
// point itself). Infinite ends where the filtered coordinates cannot bound the point.
using BoxBounds = std::array<XBounds, 3>;

inline BoxBounds box_bounds(const ImplicitPoint& p) {
  return {detail::coordinate_bounds(p, 0), detail::coordinate_bounds(p, 1), detail::coordinate_bounds(p, 2)};
}

// The sign of orient2d(a, b, x) in `plane` (tritri::orient2d's convention) that holds for
// every x in `box`, when a filter can certify it; kUndecided otherwise (then ask
// tritri::orient2d on the point itself). Never certifies 0 unless the box is a point.
// Why it holds: orient2d(a, b, x) = orient2d(a, b, c) + u_i (x_j - c_j) - u_j (x_i - c_i)
// with u = b - a and c the box's centre, |x_k - c_k| <= hi_k - lo_k. The first term is
// decided by double_predicates' orient2d filter (bound kOrient2dBound * mx * my, same
// ranges); the second is at most |u_i| r_j + |u_j| r_i, computed from rounded u and r
// with a relative margin of 2^-45 (each of the five roundings is at most 2^-53) plus
// 2^-1060 for underflow. Cost: about 20 flops.
inline constexpr int kUndecided = 2;

inline int orient2d_bounded(const std::array<double, 3>& a, const std::array<double, 3>& b, const BoxBounds& box,
                            Plane plane) noexcept {
  const int i = plane == Plane::XY ? 0 : (plane == Plane::YZ ? 1 : 2);
  const int j = (i + 1) % 3;
  const double li = box[i].lo, hi_ = box[i].hi, lj = box[j].lo, hj = box[j].hi;
  if (!(std::isfinite(li) && std::isfinite(hi_) && std::isfinite(lj) && std::isfinite(hj))) return kUndecided;
  const double ri = (hi_ - li) * (1 + 0x1p-50), rj = (hj - lj) * (1 + 0x1p-50);
  const double ci = li + (hi_ - li) * 0.5, cj = lj + (hj - lj) * 0.5;
  if (!(ci >= li && ci <= hi_ && cj >= lj && cj <= hj) || !std::isfinite(ri) || !std::isfinite(rj))
    return kUndecided;
  const double ux = b[i] - a[i], uy = b[j] - a[j], vx = ci - a[i], vy = cj - a[j];
  const double mx = detail::max_abs(ux, vx), my = detail::max_abs(uy, vy);
  if (!detail::in_filter_range(mx) || !detail::in_filter_range(my)) {
    if (ri == 0 && rj == 0) return to_int(orient2d(a[i], a[j], b[i], b[j], ci, cj));
    return kUndecided;
  }
  const double det = ux * vy - uy * vx;
  const double spread = (std::fabs(ux) * rj + std::fabs(uy) * ri) * (1 + 0x1p-45) + 0x1p-1060;
  const double bound = detail::kOrient2dBound * mx * my + spread;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  if (ri == 0 && rj == 0) return to_int(orient2d(a[i], a[j], b[i], b[j], ci, cj));
  return kUndecided;
}

// A sorting direction with no simple relation to the axes: distinct points of structured
// inputs (grids, copies rotated about an axis) often share x or even x and y exactly,
// which only the exact stage can confirm; along this direction they rarely tie.
inline constexpr std::array<double, 3> kSortDirection = {1.0, 0x1.6a09e667f3bcdp-1, 0x1.3c6ef372fe94fp-2};

// An interval that certainly contains kSortDirection . p. Explicit points: the dot
// product in double (three products, two sums: at most 4u of the absolute terms, plus
// underflow). Implicit points: the same on the cached X, Y, Z plus their certified errors,
// divided by W as in quotient_bounds.
inline XBounds direction_bounds(const ImplicitPoint& p) {
  const auto& d = kSortDirection;
  constexpr double four_u = 4 * 0x1p-53;
  if (p.is_explicit()) {
    const auto& c = p.approx();
    const double t0 = d[0] * c[0], t1 = d[1] * c[1], t2 = d[2] * c[2];
    const double e = (std::fabs(t0) + std::fabs(t1) + std::fabs(t2)) * four_u + 0x1p-1070;
    return detail::quotient_bounds(t0 + t1 + t2, e * (1 + 0x1p-40), 1.0, 0.0);
  }
  const auto& f = p.filtered();
  const auto& r = ImplicitPoint::rounding_depth(p.kind());
  const double ex = f.x.perm * (r.x.depth * detail::kFilterGamma);
  const double ey = f.y.perm * (r.y.depth * detail::kFilterGamma);
  const double ez = f.z.perm * (r.z.depth * detail::kFilterGamma);
  const double t0 = d[0] * f.x.v, t1 = d[1] * f.y.v, t2 = d[2] * f.z.v;
  const double e =
      d[0] * ex + d[1] * ey + d[2] * ez + (std::fabs(t0) + std::fabs(t1) + std::fabs(t2)) * four_u + 0x1p-1070;
  return detail::quotient_bounds(t0 + t1 + t2, e * (1 + 0x1p-40), f.w.v, f.w.perm * (r.w.depth * detail::kFilterGamma));
}

// A total order on points, exact: by kSortDirection . p, ties by compare_xyz; 0 exactly
// for coincident points. The bounds (direction_bounds) settle almost every comparison;
// then two points of one construction (an LPI of one line and plane, a TPI of one set of
// planes: detail/incidence.h) are equal without arithmetic; otherwise the exact
// homogeneous coordinates decide (CGAL::Mpzf).
inline int compare_along_direction(const ImplicitPoint& p, const XBounds& bp, const ImplicitPoint& q,
                                   const XBounds& bq) {
  if (bp.hi < bq.lo) return -1;
  if (bq.hi < bp.lo) return 1;
  // One point found by several triangles (a TPI of one set of planes): no arithmetic.
  if (detail::same_point_by_construction(p, q)) return 0;
  const auto& d = kSortDirection;
  auto numerator_and_w = [&](const ImplicitPoint& a) {
    if (a.is_explicit()) {
      const auto& c = a.approx();
      return std::pair<CGAL::Mpzf, CGAL::Mpzf>(CGAL::Mpzf(d[0]) * CGAL::Mpzf(c[0]) +
                                                   CGAL::Mpzf(d[1]) * CGAL::Mpzf(c[1]) +
                                                   CGAL::Mpzf(d[2]) * CGAL::Mpzf(c[2]),
                                               CGAL::Mpzf(1.0));
    }
    const auto& h = a.exact_homogeneous();
    return std::pair<CGAL::Mpzf, CGAL::Mpzf>(CGAL::Mpzf(d[0]) * h.x + CGAL::Mpzf(d[1]) * h.y + CGAL::Mpzf(d[2]) * h.z,
                                             h.w);
  };
  const auto [np, wp] = numerator_and_w(p);
  const auto [nq, wq] = numerator_and_w(q);
  // sign(np / wp - nq / wq) = sign(np wq - nq wp) sign(wp) sign(wq).
  const int s =
      static_cast<int>((np * wq - nq * wp).sign()) * static_cast<int>(wp.sign()) * static_cast<int>(wq.sign());
  return s != 0 ? s : compare_xyz(p, q);
}

inline int compare_xyz_bounded(const ImplicitPoint& p, const XBounds& bp, const ImplicitPoint& q, const XBounds& bq) {
  if (bp.hi < bq.lo) return -1;
  if (bq.hi < bp.lo) return 1;
  return compare_xyz(p, q);
}

}  // namespace tritri
