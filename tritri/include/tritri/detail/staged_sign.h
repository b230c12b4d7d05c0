// tritri/detail/staged_sign.h
//
// The machinery of the implicit predicates (implicit_predicates.h): staged_sign, which
// evaluates one polynomial in the operands' homogeneous coordinates stage by stage
// (filters, incidences known by construction, long double filter, CGAL::Mpzf), the
// offset-filter stage, the shared polynomials (det3, det4, scaled differences) and the
// per-thread counters of which stage decided (tritri::implicit_predicate_stats).
// Each stage is certified or exact, so the order of the stages changes time only.
#pragma once

#include <CGAL/Mpzf.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <initializer_list>

#include "tritri/detail/filtered_value.h"
#include "tritri/detail/homogeneous.h"
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


}  // namespace detail
}  // namespace tritri
