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

// BasicFilteredValue<Real>: the filter in any binary floating-point type; the constants
// are Real's (u = epsilon / 2, underflow floor = numeric_limits<Real>::min(), whose product
// with u is half the smallest subnormal: the largest absolute error of an underflowing
// product). For double: u = 2^-53, floor 2^-1022. Exact leaves are doubles.
template <class Real>
struct BasicFilteredValue {
  Real v;     // value computed in Real
  Real perm;  // bound on the sum of |monomials| (plus underflow floors)

  BasicFilteredValue() = default;  // uninitialised, like a double
  BasicFilteredValue(double x) : v(x), perm(x < 0 ? -static_cast<Real>(x) : static_cast<Real>(x)) {}  // exact leaf
  BasicFilteredValue(Real v_, Real p_) : v(v_), perm(p_) {}

  friend BasicFilteredValue operator+(const BasicFilteredValue& a, const BasicFilteredValue& b) {
    return {a.v + b.v, a.perm + b.perm};
  }
  friend BasicFilteredValue operator-(const BasicFilteredValue& a, const BasicFilteredValue& b) {
    return {a.v - b.v, a.perm + b.perm};
  }
  friend BasicFilteredValue operator-(const BasicFilteredValue& a) { return {-a.v, a.perm}; }
  friend BasicFilteredValue operator*(const BasicFilteredValue& a, const BasicFilteredValue& b) {
    return {a.v * b.v, a.perm * b.perm + std::numeric_limits<Real>::min()};
  }

  // +1 / -1 when the exact value's sign is certain, 0 when the filter cannot decide;
  // `depth` is the expression's rounding depth (RoundingDepth below).
  int certified_sign(int depth) const {
    constexpr Real u = std::numeric_limits<Real>::epsilon() / 2;
    const Real bound = perm * (depth * (u * (Real(1) + Real(0x1p-20))));
    if (v > bound) return 1;
    if (v < -bound) return -1;
    return 0;  // undecided (also for exact zeros, inf and NaN)
  }
};

using FilteredValue = BasicFilteredValue<double>;

// WideFilteredValue: the same filter in long double, for the inputs whose monomials
// leave double's exponent range (subnormal or near-subnormal coordinates, issue 36: a
// product of two tiny doubles underflows and the double filter can then never decide,
// however far from zero the exact value is relative to its monomials). Where long double
// is the x87 80-bit format (exponents to 2^-16382), a product of double-derived values
// does not underflow. kWideFilterUseful is false where long double is double.
using WideFilteredValue = BasicFilteredValue<long double>;
inline constexpr bool kWideFilterUseful = std::numeric_limits<long double>::max_exponent > 1024 &&
                                          std::numeric_limits<long double>::min_exponent < -1021;

// True when a double filter's bound `perm` says its monomials may have left double's
// exponent range (underflow floors dominate, or overflow): only then can the long double
// filter decide what the double one could not, so only then is it tried.
inline bool may_have_left_double_range(double perm) { return !(perm >= 0x1p-800 && perm <= 0x1p+800); }

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
