// tritri/detail/filtered_value.h
//
// FilteredValue: a double evaluated together with a certified error bound, the filter
// stage of the implicit-point predicates. Written once, the predicate polynomials are
// instantiated with this type (fast, may be undecided) and with an exact type.
//
// Bound (classical forward error analysis of a +,-,* expression tree on exact leaves):
// the computed value is sum_m m * prod(1 + delta) over the monomials m of the expanded
// polynomial, with at most `depth` factors |delta| <= u = 2^-53 per monomial. So
// |computed - exact| <= gamma_depth * sum_m |m|, and sum_m |m| is what `perm` tracks
// (the same tree evaluated on absolute values with + for -). Each product adds 2^-1022
// to perm so that gamma * perm also covers the absolute error (<= 2^-1075) of a product
// that underflows, scaled by whatever multiplies it later. Overflow gives inf or NaN,
// which never passes the test. `certified_sign()` inflates gamma_depth by 2^-20 for the
// rounding of perm itself, valid for depth < 2^20.
#pragma once

#include <limits>

namespace tritri::detail {

struct FilteredValue {
  double v;     // value computed in double
  double perm;  // bound on the sum of |monomials| (plus underflow floors)

  FilteredValue() = default;                               // uninitialised, like a double
  FilteredValue(double x) : v(x), perm(x < 0 ? -x : x) {}  // exact leaf
  FilteredValue(double v_, double p_) : v(v_), perm(p_) {}

  friend FilteredValue operator+(const FilteredValue& a, const FilteredValue& b) {
    return {a.v + b.v, a.perm + b.perm};
  }
  friend FilteredValue operator-(const FilteredValue& a, const FilteredValue& b) {
    return {a.v - b.v, a.perm + b.perm};
  }
  friend FilteredValue operator-(const FilteredValue& a) { return {-a.v, a.perm}; }
  friend FilteredValue operator*(const FilteredValue& a, const FilteredValue& b) {
    return {a.v * b.v, a.perm * b.perm + 0x1p-1022};
  }

  // +1 / -1 when the exact value's sign is certain, 0 when the filter cannot decide;
  // `depth` is the expression's rounding depth (RoundingDepth below).
  int certified_sign(int depth) const {
    const double bound = perm * (depth * (0x1p-53 * (1.0 + 0x1p-20)));
    if (v > bound) return 1;
    if (v < -bound) return -1;
    return 0;  // undecided (also for exact zeros, inf and NaN)
  }
};

// WideFilteredValue: the same filter in long double, for the inputs whose monomials
// leave double's exponent range (subnormal or near-subnormal coordinates, issue 36: a
// product of two tiny doubles underflows and the double filter can then never decide,
// however far from zero the exact value is relative to its monomials). Where long double
// is the x87 80-bit format (exponents to 2^-16382), a product of double-derived values
// does not underflow. The bound is the one above with u = epsilon/2 of long double and
// the underflow floor numeric_limits<long double>::min() (min * u = half the smallest
// subnormal, the largest absolute error of an underflowing product). Exact leaves are
// doubles (converted exactly). kWideFilterUseful is false where long double is double.
inline constexpr bool kWideFilterUseful = std::numeric_limits<long double>::max_exponent > 1024 &&
                                          std::numeric_limits<long double>::min_exponent < -1021;

struct WideFilteredValue {
  long double v;
  long double perm;

  WideFilteredValue() = default;
  WideFilteredValue(double x) : v(x), perm(x < 0 ? -static_cast<long double>(x) : static_cast<long double>(x)) {}
  WideFilteredValue(long double v_, long double p_) : v(v_), perm(p_) {}

  friend WideFilteredValue operator+(const WideFilteredValue& a, const WideFilteredValue& b) {
    return {a.v + b.v, a.perm + b.perm};
  }
  friend WideFilteredValue operator-(const WideFilteredValue& a, const WideFilteredValue& b) {
    return {a.v - b.v, a.perm + b.perm};
  }
  friend WideFilteredValue operator-(const WideFilteredValue& a) { return {-a.v, a.perm}; }
  friend WideFilteredValue operator*(const WideFilteredValue& a, const WideFilteredValue& b) {
    return {a.v * b.v, a.perm * b.perm + std::numeric_limits<long double>::min()};
  }

  int certified_sign(int depth) const {
    constexpr long double u = std::numeric_limits<long double>::epsilon() / 2;
    const long double bound = perm * (depth * (u * (1.0L + 0x1p-20L)));
    if (v > bound) return 1;
    if (v < -bound) return -1;
    return 0;
  }
};

// RoundingDepth: evaluates the same expression counting only the roundings per monomial
// (a sum: the deeper operand plus one; a product: both plus one). The depth depends only
// on the expression's shape, never on the values, so predicates compute it once per shape
// and cache it (the filter then needs no per-operation bookkeeping).
struct RoundingDepth {
  int depth;

  RoundingDepth() = default;
  RoundingDepth(double) : depth(0) {}  // exact leaf
  explicit RoundingDepth(int d, int) : depth(d) {}

  friend RoundingDepth operator+(RoundingDepth a, RoundingDepth b) {
    return RoundingDepth((a.depth > b.depth ? a.depth : b.depth) + 1, 0);
  }
  friend RoundingDepth operator-(RoundingDepth a, RoundingDepth b) { return a + b; }
  friend RoundingDepth operator-(RoundingDepth a) { return a; }
  friend RoundingDepth operator*(RoundingDepth a, RoundingDepth b) { return RoundingDepth(a.depth + b.depth + 1, 0); }
};

}  // namespace tritri::detail
