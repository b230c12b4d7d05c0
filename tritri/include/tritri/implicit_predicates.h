// tritri/implicit_predicates.h
//
// Exact predicates on ImplicitPoints (any mix of explicit, LPI and TPI points):
// orient3d, orient2d (XY, YZ, ZX), equal, less and compare_xyz (lexicographic x, y, z).
//
// Each predicate is one polynomial in the points' homogeneous coordinates, written once
// over a number type and evaluated in stages: FilteredValue on offset and on cached
// coordinates (a certified error bound; decides almost always); then, when the filters
// cannot decide, the incidences known by construction (detail/incidence.h: points on one
// defining plane or line, coordinates fixed by axis-aligned planes), which decide most
// exact zeros without arithmetic; the same filter in long double where double's exponent
// range failed (subnormal-scale or overflowing monomials); then CGAL::Mpzf (exact).
// Predicates on explicit points only use the double backend (double_predicates.h).
// Exact for every input.
//
// Conventions are those of the kernel concept: orient3d(a, b, c, d) is the sign of
// det[b-a; c-a; d-a], orient2d the sign of det[b-a; c-a] in the projection.
// Homogeneous form: with rows (X, Y, Z, W), det4 = W_a W_b W_c W_d * (-orient3d), so
// orient3d = -sign(det4) * prod sign(W). When an operand e is explicit, subtracting its
// row leaves a 3x3 determinant of rows W_i (p_i - p_e), which has lower degree.
#pragma once

#include <CGAL/Mpzf.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <type_traits>

#include "tritri/detail/incidence.h"
#include "tritri/detail/filtered_value.h"
#include "tritri/detail/homogeneous.h"
#include "tritri/double_predicates.h"
#include "tritri/implicit_point.h"
#include "tritri/sign.h"

namespace tritri {

// How often the filter decided, per thread (for benchmarks and reports).
struct ImplicitPredicateStats {
  std::uint64_t filtered = 0;  // decided by the floating-point filter
  std::uint64_t exact = 0;     // needed the exact stage
  std::uint64_t exact_zero = 0;  // needed the exact stage, which found 0 (a zero incidence.h missed)
  std::uint64_t wide = 0;        // decided by the long double filter (also counted in filtered)
  std::uint64_t structural = 0;  // exactly 0 by construction (detail/incidence.h)
};
inline ImplicitPredicateStats& implicit_predicate_stats() {
  thread_local ImplicitPredicateStats stats;
  return stats;
}

namespace detail {

struct FilteredCoordinates {
  const Homogeneous<FilteredValue>& operator()(const ImplicitPoint& p) const { return p.filtered(); }
};
struct WideCoordinates {  // only called on implicit points
  const Homogeneous<WideFilteredValue>& operator()(const ImplicitPoint& p) const { return p.wide_homogeneous(); }
};
struct CoordinateDepths {
  const Homogeneous<RoundingDepth>& operator()(const ImplicitPoint& p) const {
    return ImplicitPoint::rounding_depth(p.kind());
  }
};

// A number identifying which operands are explicit, LPI or TPI: the shape of a
// predicate's expression, on which its rounding depth depends.
inline int shape_of(std::initializer_list<const ImplicitPoint*> pts) {
  int shape = 0;
  for (const ImplicitPoint* p : pts) shape = shape * 3 + static_cast<int>(p->kind());
  return shape;
}
struct ExactCoordinates {  // only called on implicit points
  const Homogeneous<CGAL::Mpzf>& operator()(const ImplicitPoint& p) const { return p.exact_homogeneous(); }
};

// Evaluates the sign of poly(T-tag, coordinate getter): `middle` (another filter) first,
// then the filter on the cached (absolute) coordinates, then `known_zero()` (a structural
// test, true only when the value is exactly 0), then the long double filter when the
// double one may have underflowed or overflowed, then exactly. With `tiny_scale`
// operands (ImplicitPoint::tiny_scale: subnormal-scale coordinates) the order is cached
// filter, long double filter, known_zero(), `middle`: there the double filters mostly
// fail alike and the long double one decides most calls. Each stage is exact or
// certified, so the order changes the time only, never the sign.
// `shape` (shape_of, below 81) names the operand kinds: the expression's rounding depth
// is computed once per call site and shape, then read from a cache.
template <class Poly, class Middle, class KnownZero>
int staged_sign(const Poly& poly, int shape, const Middle& middle, const KnownZero& known_zero,
                bool tiny_scale = false) {
  static std::atomic<int> depth_of_shape[81] = {};  // 0: not computed yet
  int depth = depth_of_shape[shape].load(std::memory_order_relaxed);
  if (depth == 0) {
    depth = poly(RoundingDepth{0.0}, CoordinateDepths{}).depth + 1;  // +1: never 0 (cache marker)
    depth_of_shape[shape].store(depth, std::memory_order_relaxed);
  }
  // `middle` (the offset filter: decides near points, which the cached absolute
  // coordinates rarely do; measured faster first), in poly's sign convention, 0 if
  // undecided.
  if (!tiny_scale) {
    const int m = middle();
    if (m != 0) return m;
  }
  const FilteredValue f = poly(FilteredValue{}, FilteredCoordinates{});
  const int s = f.certified_sign(depth);
  if (s != 0) {
    ++implicit_predicate_stats().filtered;
    return s;
  }
  // The same filter in long double (WideFilteredValue), only where double's exponent range
  // may have been the problem: monomials far below 1 (subnormal-scale input, whose
  // products underflow and whose bound is then all underflow floors) or overflow.
  auto wide_sign = [&] {
    if constexpr (kWideFilterUseful) {
      if (may_have_left_double_range(f.perm)) {
        const int ws = poly(WideFilteredValue{}, WideCoordinates{}).certified_sign(depth);
        if (ws != 0) {
          ++implicit_predicate_stats().filtered;
          ++implicit_predicate_stats().wide;
          return ws;
        }
      }
    }
    return 0;
  };
  if (tiny_scale) {
    if (const int ws = wide_sign()) return ws;
  }
  if (known_zero()) {
    ++implicit_predicate_stats().structural;
    return 0;
  }
  if (!tiny_scale) {
    if (const int ws = wide_sign()) return ws;
  } else {
    const int m = middle();
    if (m != 0) return m;
  }
  ++implicit_predicate_stats().exact;
  const int e = static_cast<int>(poly(CGAL::Mpzf{}, ExactCoordinates{}).sign());
  if (e == 0) ++implicit_predicate_stats().exact_zero;
  return e;
}

template <class Poly, class Middle>
int staged_sign(const Poly& poly, int shape, const Middle& middle) {
  return staged_sign(poly, shape, middle, [] { return false; });
}

template <class Poly>
int staged_sign(const Poly& poly, int shape) {
  return staged_sign(poly, shape, [] { return 0; });
}

// First filter stage: poly(tag, off) evaluated on offset coordinates (off(p) = (W (p - o),
// W) for the predicate's origin o), FilteredValue only; 0 if undecided. (A long double
// stage here, uncached, cost more on subnormal-scale input than the exact calls it
// saved.) The rounding depth is computed once per call site and shape, like staged_sign's.
template <class Poly>
int offset_filter_sign(const Poly& poly, int shape) {
  static std::atomic<int> depth_of_shape[81] = {};
  int depth = depth_of_shape[shape].load(std::memory_order_relaxed);
  if (depth == 0) {
    depth = poly(RoundingDepth{0.0}).depth + 1;
    depth_of_shape[shape].store(depth, std::memory_order_relaxed);
  }
  const int s = poly(FilteredValue{}).certified_sign(depth);
  if (s != 0) ++implicit_predicate_stats().filtered;
  return s;
}

// The origin for offset coordinates: an explicit operand if there is one, else the first
// defining point of the first operand (near it, for points of an arrangement).
inline const ImplicitPoint::Coords& offset_origin(std::initializer_list<const ImplicitPoint*> pts) {
  for (const ImplicitPoint* p : pts)
    if (p->is_explicit()) return p->approx();
  return (*pts.begin())->input(0);
}

// Coordinates of point p relative to explicit point c, scaled by W_p: W_p (p - c),
// restricted to the axes in `axes`.
template <class T, class Get, std::size_t N>
std::array<T, N> scaled_difference(const ImplicitPoint& p, const ImplicitPoint::Coords& c,
                                   const std::array<int, N>& axes, const Get& get) {
  std::array<T, N> out;
  if (p.is_explicit()) {
    for (std::size_t k = 0; k < N; ++k) out[k] = T(p.approx()[axes[k]]) - T(c[axes[k]]);
  } else {
    const auto& h = get(p);
    const T* hc[3] = {&h.x, &h.y, &h.z};
    for (std::size_t k = 0; k < N; ++k) out[k] = *hc[axes[k]] - T(c[axes[k]]) * h.w;
  }
  return out;
}

// The same for all three axes.
template <class T, class Get>
std::array<T, 3> scaled_difference3(const ImplicitPoint& p, const ImplicitPoint::Coords& c, const Get& get) {
  if (p.is_explicit()) {
    const auto& x = p.approx();
    return {T(x[0]) - T(c[0]), T(x[1]) - T(c[1]), T(x[2]) - T(c[2])};
  }
  const auto& h = get(p);
  return {h.x - T(c[0]) * h.w, h.y - T(c[1]) * h.w, h.z - T(c[2]) * h.w};
}

template <class T>
std::array<T, 4> row4(const Homogeneous<T>& h) {
  return {h.x, h.y, h.z, h.w};
}

// det of the 4x4 matrix with rows r0..r3, by Laplace expansion on complementary 2x2 minors.
template <class T>
T det4(const std::array<T, 4>& r0, const std::array<T, 4>& r1, const std::array<T, 4>& r2, const std::array<T, 4>& r3) {
  const T s0 = r0[0] * r1[1] - r1[0] * r0[1], s1 = r0[0] * r1[2] - r1[0] * r0[2];
  const T s2 = r0[0] * r1[3] - r1[0] * r0[3], s3 = r0[1] * r1[2] - r1[1] * r0[2];
  const T s4 = r0[1] * r1[3] - r1[1] * r0[3], s5 = r0[2] * r1[3] - r1[2] * r0[3];
  const T c5 = r2[2] * r3[3] - r3[2] * r2[3], c4 = r2[1] * r3[3] - r3[1] * r2[3];
  const T c3 = r2[1] * r3[2] - r3[1] * r2[2], c2 = r2[0] * r3[3] - r3[0] * r2[3];
  const T c1 = r2[0] * r3[2] - r3[0] * r2[2], c0 = r2[0] * r3[1] - r3[0] * r2[1];
  return s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0;
}

template <class T>
T det3(const std::array<T, 3>& r0, const std::array<T, 3>& r1, const std::array<T, 3>& r2) {
  return r0[0] * (r1[1] * r2[2] - r1[2] * r2[1]) - r0[1] * (r1[0] * r2[2] - r1[2] * r2[0]) +
         r0[2] * (r1[0] * r2[1] - r1[1] * r2[0]);
}

inline bool any_tiny_scale(std::initializer_list<const ImplicitPoint*> pts) {
  for (const ImplicitPoint* p : pts)
    if (p->tiny_scale()) return true;
  return false;
}

inline int first_explicit(std::initializer_list<const ImplicitPoint*> pts) {
  int i = 0;
  for (const ImplicitPoint* p : pts) {
    if (p->is_explicit()) return i;
    ++i;
  }
  return -1;
}

inline std::array<int, 2> plane_axes(Plane plane) {
  const int i = plane == Plane::XY ? 0 : (plane == Plane::YZ ? 1 : 2);
  return {i, (i + 1) % 3};
}

// The sign of p_k - q_k when known without arithmetic: one point built twice (a crossing
// found from both triangles), or both on planes (or lines) constant in k, by construction.
inline std::optional<int> compare_coordinate_by_construction(const ImplicitPoint& p, const ImplicitPoint& q, int k) {
  if (same_point_by_construction(p, q)) return 0;
  if (const auto pk = known_coordinate(p, k)) {
    if (const auto qk = known_coordinate(q, k)) return *pk < *qk ? -1 : (*pk > *qk ? 1 : 0);
  }
  return std::nullopt;
}

// sign(X_p W_q - X_q W_p) along axis k, times sign(W_p W_q): the sign of p_k - q_k.
// with_offset = false skips the offset filter stage (for callers that already tried it).
inline int compare_coordinate(const ImplicitPoint& p, const ImplicitPoint& q, int k, bool with_offset = true) {
  if (p.is_explicit() && q.is_explicit()) {
    const double a = p.approx()[k], b = q.approx()[k];
    return a < b ? -1 : (a > b ? 1 : 0);
  }
  if (const auto known = compare_coordinate_by_construction(p, q, k)) {
    ++implicit_predicate_stats().structural;
    return *known;
  }
  auto offset_stage = [&] {
    if (!with_offset) return 0;
    const auto& o = q.is_explicit() ? q.approx() : offset_origin({&p});
    return offset_filter_sign(
        [&](auto tag) {
          using T = decltype(tag);
          const auto hp = p.offset_homogeneous<T>(o);
          const auto hq = q.offset_homogeneous<T>(o);
          const T* pc[3] = {&hp.x, &hp.y, &hp.z};
          const T* qc[3] = {&hq.x, &hq.y, &hq.z};
          return *pc[k] * hq.w - *qc[k] * hp.w;
        },
        shape_of({&p, &q}));
  };
  const int s = staged_sign(
      [&](auto tag, const auto& get) {
        using T = decltype(tag);
        (void)tag;
        if (q.is_explicit()) {
          const auto& h = get(p);
          const T* hc[3] = {&h.x, &h.y, &h.z};
          return *hc[k] - T(q.approx()[k]) * h.w;
        }
        if (p.is_explicit()) {
          const auto& h = get(q);
          const T* hc[3] = {&h.x, &h.y, &h.z};
          return T(p.approx()[k]) * h.w - *hc[k];
        }
        const auto& hp = get(p);
        const auto& hq = get(q);
        const T* pc[3] = {&hp.x, &hp.y, &hp.z};
        const T* qc[3] = {&hq.x, &hq.y, &hq.z};
        return *pc[k] * hq.w - *qc[k] * hp.w;
      },
      shape_of({&p, &q}), offset_stage, [] { return false; }, any_tiny_scale({&p, &q}));
  return s * p.w_sign() * q.w_sign();
}

}  // namespace detail

// Sign of det[b-a; c-a; d-a] (Positive: d on the side of plane abc that (b-a) x (c-a)
// points to). Exact.
inline Sign orient3d(const ImplicitPoint& a, const ImplicitPoint& b, const ImplicitPoint& c, const ImplicitPoint& d) {
  if (a.is_explicit() && b.is_explicit() && c.is_explicit() && d.is_explicit())
    return orient3d(a.approx(), b.approx(), c.approx(), d.approx());
  const ImplicitPoint* pts[4] = {&a, &b, &c, &d};
  const int e = detail::first_explicit({&a, &b, &c, &d});
  const int w = a.w_sign() * b.w_sign() * c.w_sign() * d.w_sign();
  // Offset filter stage, as the sign of det4 of the rows (W (p - o), W).
  auto offset_det4 = [&] {
    const auto& o = detail::offset_origin({&a, &b, &c, &d});
    return detail::offset_filter_sign(
        [&](auto tag) {
          using T = decltype(tag);
          std::array<T, 4> rows[4];
          for (int i = 0; i < 4; ++i) {
            const auto h = pts[i]->offset_homogeneous<T>(o);
            rows[i] = {h.x, h.y, h.z, h.w};
          }
          return detail::det4<T>(rows[0], rows[1], rows[2], rows[3]);
        },
        detail::shape_of({&a, &b, &c, &d}));
  };
  auto on_one_plane = [&] { return detail::orient3d_known_zero({&a, &b, &c, &d}); };
  const bool tiny = detail::any_tiny_scale({&a, &b, &c, &d});
  if (e >= 0) {
    // orient3d = (-1)^e det3(rows W_i (p_i - p_e), i != e, in order) * prod sign(W_i).
    const auto& ref = pts[e]->approx();
    // The three operands other than e, in order.
    const ImplicitPoint& p0 = *pts[e == 0 ? 1 : 0];
    const ImplicitPoint& p1 = *pts[e <= 1 ? 2 : 1];
    const ImplicitPoint& p2 = *pts[e <= 2 ? 3 : 2];
    const int s = detail::staged_sign(
        [&](auto tag, const auto& get) {
          using T = decltype(tag);
          return detail::det3(detail::scaled_difference3<T>(p0, ref, get), detail::scaled_difference3<T>(p1, ref, get),
                              detail::scaled_difference3<T>(p2, ref, get));
        },
        detail::shape_of({&a, &b, &c, &d}), [&] { return e % 2 ? offset_det4() : -offset_det4(); },
        on_one_plane, tiny);
    return detail::to_sign((e % 2 ? -s : s) * w);
  }
  const int s = detail::staged_sign(
      [&](auto tag, const auto& get) {
        using T = decltype(tag);
        (void)tag;
        return detail::det4<T>(detail::row4<T>(get(a)), detail::row4<T>(get(b)), detail::row4<T>(get(c)),
                               detail::row4<T>(get(d)));
      },
      detail::shape_of({&a, &b, &c, &d}), offset_det4, on_one_plane, tiny);
  return detail::to_sign(-s * w);
}

namespace detail {
// orient2d on implicit points; with_offset = false skips the offset filter stage.
inline Sign orient2d_staged(const ImplicitPoint& a, const ImplicitPoint& b, const ImplicitPoint& c, Plane plane,
                            bool with_offset) {
  if (a.is_explicit() && b.is_explicit() && c.is_explicit()) return orient2d(a.approx(), b.approx(), c.approx(), plane);
  const auto axes = detail::plane_axes(plane);
  const ImplicitPoint* pts[3] = {&a, &b, &c};
  const int e = detail::first_explicit({&a, &b, &c});
  const int w = a.w_sign() * b.w_sign() * c.w_sign();
  // Offset filter stage, as the sign of det3 of the rows (W (p - o) projected, W).
  auto offset_det3 = [&] {
    if (!with_offset) return 0;
    const auto& o = detail::offset_origin({&a, &b, &c});
    return detail::offset_filter_sign(
        [&](auto tag) {
          using T = decltype(tag);
          std::array<T, 3> rows[3];
          for (int i = 0; i < 3; ++i) {
            const auto h = pts[i]->offset_homogeneous<T>(o);
            const T* hc[3] = {&h.x, &h.y, &h.z};
            rows[i] = {*hc[axes[0]], *hc[axes[1]], h.w};
          }
          return detail::det3(rows[0], rows[1], rows[2]);
        },
        detail::shape_of({&a, &b, &c}));
  };
  auto on_one_line = [&] { return detail::orient2d_known_zero({&a, &b, &c}, plane); };
  const bool tiny = detail::any_tiny_scale({&a, &b, &c});
  if (e >= 0) {
    const auto& ref = pts[e]->approx();
    const int s = detail::staged_sign(
        [&](auto tag, const auto& get) {
          using T = decltype(tag);
          std::array<T, 2> rows[2];
          int n = 0;
          for (int i = 0; i < 3; ++i)
            if (i != e) rows[n++] = detail::scaled_difference<T>(*pts[i], ref, axes, get);
          return rows[0][0] * rows[1][1] - rows[0][1] * rows[1][0];
        },
        detail::shape_of({&a, &b, &c}), [&] { return e % 2 ? -offset_det3() : offset_det3(); }, on_one_line,
        tiny);
    return detail::to_sign((e % 2 ? -s : s) * w);
  }
  const int s = detail::staged_sign(
      [&](auto tag, const auto& get) {
        using T = decltype(tag);
        std::array<T, 3> rows[3];
        for (int i = 0; i < 3; ++i) {
          const auto& h = get(*pts[i]);
          const T* hc[3] = {&h.x, &h.y, &h.z};
          rows[i] = {*hc[axes[0]], *hc[axes[1]], h.w};
        }
        return detail::det3(rows[0], rows[1], rows[2]);
      },
      detail::shape_of({&a, &b, &c}), offset_det3, on_one_line, tiny);
  return detail::to_sign(s * w);
}
}  // namespace detail

// Sign of det[b-a; c-a] in the projection onto `plane`. Exact.
inline Sign orient2d(const ImplicitPoint& a, const ImplicitPoint& b, const ImplicitPoint& c, Plane plane) {
  return detail::orient2d_staged(a, b, c, plane, /*with_offset=*/true);
}

// Points with cached offset coordinates, for many predicates on points near one explicit
// origin (e.g. every point of one triangle of an arrangement): the first filter stage
// reads the cache instead of rebuilding W (p - o) per call; undecided calls fall back to
// the plain predicates (same results, exact).
//   OffsetPoint q = offset_point(p, o);   // o: an explicit point near p
// Precondition of the predicates: all operands were made with the same origin; the
// ImplicitPoint must outlive the OffsetPoint.
struct OffsetPoint {
  const ImplicitPoint* point = nullptr;
  detail::Homogeneous<detail::FilteredValue> h{};
};

inline OffsetPoint offset_point(const ImplicitPoint& p, const ImplicitPoint::Coords& origin) {
  return {&p, p.offset_homogeneous<detail::FilteredValue>(origin)};
}

// orient2d(*a.point, *b.point, *c.point, plane). Exact.
inline Sign orient2d(const OffsetPoint& a, const OffsetPoint& b, const OffsetPoint& c, Plane plane) {
  const ImplicitPoint& pa = *a.point;
  const ImplicitPoint& pb = *b.point;
  const ImplicitPoint& pc = *c.point;
  const auto axes = detail::plane_axes(plane);
  const int shape = detail::shape_of({&pa, &pb, &pc});
  static std::atomic<int> depth_of_shape[27] = {};
  int depth = depth_of_shape[shape].load(std::memory_order_relaxed);
  auto rows_det = [&](const auto& ha, const auto& hb, const auto& hc) {
    using T = std::decay_t<decltype(ha.w)>;
    std::array<T, 3> rows[3];
    const detail::Homogeneous<T>* h[3] = {&ha, &hb, &hc};
    for (int i = 0; i < 3; ++i) {
      const T* hcoord[3] = {&h[i]->x, &h[i]->y, &h[i]->z};
      rows[i] = {*hcoord[axes[0]], *hcoord[axes[1]], h[i]->w};
    }
    return detail::det3(rows[0], rows[1], rows[2]);
  };
  if (depth == 0) {
    const ImplicitPoint::Coords o{0, 0, 0};  // the depth depends on the kinds only
    depth = rows_det(pa.offset_homogeneous<detail::RoundingDepth>(o), pb.offset_homogeneous<detail::RoundingDepth>(o),
                     pc.offset_homogeneous<detail::RoundingDepth>(o))
                .depth +
            1;
    depth_of_shape[shape].store(depth, std::memory_order_relaxed);
  }
  const int f = rows_det(a.h, b.h, c.h).certified_sign(depth);
  if (f != 0) {
    ++implicit_predicate_stats().filtered;
    return detail::to_sign(f * pa.w_sign() * pb.w_sign() * pc.w_sign());
  }
  return detail::orient2d_staged(pa, pb, pc, plane, /*with_offset=*/false);  // the offset filter failed
}

// Exact lexicographic (x, y, z) comparison: -1 if p < q, 0 if p == q, +1 if p > q.
// One call decides what less(p, q) and less(q, p) would, at the cost of one.
inline int compare_xyz(const ImplicitPoint& p, const ImplicitPoint& q) {
  if (p.is_explicit() && q.is_explicit()) {
    const auto &a = p.approx(), &b = q.approx();
    return a < b ? -1 : (b < a ? 1 : 0);
  }
  // Per axis: the filter on the cached absolute coordinates (cheap; decides points that
  // are far apart, most comparisons of a sort), then the comparison known by
  // construction (equal coordinates, which no filter decides), then the filter on offset
  // coordinates (computed once for all axes: they decide near points), then
  // compare_coordinate (exact).
  const int w = p.w_sign() * q.w_sign();
  const int shape = detail::shape_of({&p, &q});
  static std::atomic<int> depth_of_shape[2][9] = {};
  auto depth = [&](int which, auto&& compute) {
    int d = depth_of_shape[which][shape].load(std::memory_order_relaxed);
    if (d == 0) {
      d = compute() + 1;
      depth_of_shape[which][shape].store(d, std::memory_order_relaxed);
    }
    return d;
  };
  using detail::FilteredValue;
  using detail::RoundingDepth;
  const auto abs_p = p.homogeneous_filtered(), abs_q = q.homogeneous_filtered();
  const int abs_depth = depth(0, [&] {
    const auto& dp = ImplicitPoint::rounding_depth(p.kind());
    const auto& dq = ImplicitPoint::rounding_depth(q.kind());
    return (dp.x * dq.w - dq.x * dp.w).depth;
  });
  // With tiny-scale operands the offset filter is left to compare_coordinate's last
  // filter stage (staged_sign): the long double one decides first there.
  const bool tiny = p.tiny_scale() || q.tiny_scale();
  const ImplicitPoint::Coords* origin = nullptr;
  detail::Homogeneous<FilteredValue> off_p{}, off_q{};
  int off_depth = 0;
  for (int k = 0; k < 3; ++k) {
    const FilteredValue* ap[3] = {&abs_p.x, &abs_p.y, &abs_p.z};
    const FilteredValue* aq[3] = {&abs_q.x, &abs_q.y, &abs_q.z};
    int c = (*ap[k] * abs_q.w - *aq[k] * abs_p.w).certified_sign(abs_depth);
    if (c == 0) {
      // Equal coordinates, which no filter decides, are mostly known by construction.
      if (const auto known = detail::compare_coordinate_by_construction(p, q, k)) {
        ++implicit_predicate_stats().structural;
        if (*known != 0) return *known;
        continue;
      }
    }
    if (c == 0 && !tiny) {
      if (!origin) {
        origin = q.is_explicit() ? &q.approx() : &detail::offset_origin({&p});
        off_p = p.offset_homogeneous<FilteredValue>(*origin);
        off_q = q.offset_homogeneous<FilteredValue>(*origin);
        off_depth = depth(1, [&] {
          const auto hp = p.offset_homogeneous<RoundingDepth>(*origin);
          const auto hq = q.offset_homogeneous<RoundingDepth>(*origin);
          return (hp.x * hq.w - hq.x * hp.w).depth;  // the same for every axis
        });
      }
      const FilteredValue* op[3] = {&off_p.x, &off_p.y, &off_p.z};
      const FilteredValue* oq[3] = {&off_q.x, &off_q.y, &off_q.z};
      c = (*op[k] * off_q.w - *oq[k] * off_p.w).certified_sign(off_depth);
    }
    if (c != 0) {
      ++implicit_predicate_stats().filtered;
      c *= w;
    } else {
      c = detail::compare_coordinate(p, q, k, /*with_offset=*/origin == nullptr || tiny);
    }
    if (c != 0) return c;
  }
  return 0;
}

// Exact coincidence.
inline bool equal(const ImplicitPoint& p, const ImplicitPoint& q) {
  for (int k = 0; k < 3; ++k)
    if (detail::compare_coordinate(p, q, k) != 0) return false;
  return true;
}

// Exact lexicographic (x, y, z) order.
inline bool less(const ImplicitPoint& p, const ImplicitPoint& q) { return compare_xyz(p, q) < 0; }

}  // namespace tritri
