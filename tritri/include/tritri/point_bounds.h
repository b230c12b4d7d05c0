// tritri/point_bounds.h
//
// x_bounds(p): an interval [lo, hi] that certainly contains the exact x coordinate of an
// implicit point (explicit points: [x, x]), from the filtered homogeneous coordinates the
// point caches. compare_xyz_bounded(p, bp, q, bq): tritri::compare_xyz, exactly, that
// settles pairs whose x intervals are disjoint with two double comparisons. For sorting
// many implicit points (deduplication), where most comparisons are between points far
// apart: the bounds are computed once per point instead of per comparison.
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

#include <cmath>
#include <limits>

#include "tritri/implicit_point.h"
#include "tritri/implicit_predicates.h"

namespace tritri {

struct XBounds {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
};

inline XBounds x_bounds(const ImplicitPoint& p) {
  if (p.is_explicit()) return {p.approx()[0], p.approx()[0]};
  const auto& f = p.filtered();
  const auto& d = ImplicitPoint::rounding_depth(p.kind());
  constexpr double u = 0x1p-53 * (1.0 + 0x1p-20);
  const double ex = f.x.perm * (d.x.depth * u), ew = f.w.perm * (d.w.depth * u);
  const double s = f.w.v < 0 ? -1.0 : 1.0;
  const double w = std::fabs(f.w.v), x = s * f.x.v;
  if (!(w > ew) || !std::isfinite(w) || !std::isfinite(x) || !std::isfinite(ex) || !std::isfinite(ew)) return {};
  const double wl = w - ew, wh = w + ew, xl = x - ex, xh = x + ex;
  double lo = xl / (xl >= 0 ? wh : wl);
  double hi = xh / (xh >= 0 ? wl : wh);
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {};
  lo -= std::fabs(lo) * 0x1p-50 + 0x1p-1070;
  hi += std::fabs(hi) * 0x1p-50 + 0x1p-1070;
  return {lo, hi};
}

inline int compare_xyz_bounded(const ImplicitPoint& p, const XBounds& bp, const ImplicitPoint& q, const XBounds& bq) {
  if (bp.hi < bq.lo) return -1;
  if (bq.hi < bp.lo) return 1;
  return compare_xyz(p, q);
}

}  // namespace tritri
