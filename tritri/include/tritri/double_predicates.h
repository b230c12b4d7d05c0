// tritri/double_predicates.h
//
// Exact orient3d / orient2d on double coordinates (and orient3d_each: three points against
// one plane), in three stages:
//   1. a semi-static floating-point filter with a proven error bound (below);
//   2. when the filter cannot decide and every coordinate is 0 or has magnitude in
//      [2^-280, 2^280]: 128-bit integers if the differences are exact doubles within a
//      narrow bit window (detail/integer_orient.h), exact expansion arithmetic otherwise;
//   3. otherwise (huge, tiny or subnormal coordinates) exact expansion arithmetic on long
//      doubles where their exponent range holds every product (x87: always), else exact
//      GMP integers.
//
// Preconditions: all coordinates finite (NaN / Inf give unspecified signs); IEEE binary64
// with gradual underflow (no flush-to-zero, as -ffast-math would set) and no
// floating-point traps (the filter may overflow on inputs it then does not use).
// Exactness: the returned sign is the sign of the exact determinant, for every finite
// input. Cost: a few nanoseconds on the filter path; ~100 ns to a few us otherwise.
//
// Filter bound (derived for both evaluation orders below: orient3d's expansion along
// b-a, and orient3d_each's (d-a) . ((b-a) x (c-a))): with differences rounded once, each
// of the six elementary terms of the 3x3 determinant passes through at most 8 roundings,
// so |det_fp - det| <= 6 * gamma_8 * mx*my*mz / (1-u)^3 ~= 48u * mx*my*mz (u = 2^-53),
// where mx, my, mz are the largest absolute coordinate differences. We use 5.4e-15
// (> 48u = 5.329e-15 with margin for the rounding of the bound itself and for at most
// ~2^-821 of absolute underflow error). The filter only runs when mx, my, mz lie in
// [2^-250, 2^250], where no product overflows and underflow is negligible against the
// bound. For orient2d: 4 roundings, 2 terms, 8u = 8.88e-16, we use 8.9e-16.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "tritri/detail/expansion.h"
#include "tritri/detail/gmp_orient.h"
#include "tritri/detail/integer_orient.h"
#include "tritri/sign.h"

namespace tritri {

namespace detail {

inline constexpr double kFilterMin = 0x1p-250;
inline constexpr double kFilterMax = 0x1p250;
inline constexpr double kExpansionMin = 0x1p-280;
inline constexpr double kExpansionMax = 0x1p280;
inline constexpr double kOrient3dBound = 5.4e-15;
inline constexpr double kOrient2dBound = 8.9e-16;

inline Sign to_sign(int s) noexcept { return s > 0 ? Sign::Positive : (s < 0 ? Sign::Negative : Sign::Zero); }

// std::fmax handles NaN and often compiles to a library call; inputs here are finite.
// std::fabs is one mask (a < 0 ? -a : a is not, because of -0.0).
inline double max_abs(double a, double b) noexcept {
  a = std::fabs(a);
  b = std::fabs(b);
  return a > b ? a : b;
}
inline double max_abs(double a, double b, double c) noexcept { return max_abs(max_abs(a, b), c); }

inline bool in_filter_range(double m) noexcept { return m >= kFilterMin && m <= kFilterMax; }
// All of them in range: one test on the smallest and the largest (a zero fails it).
inline bool in_filter_range(double mx, double my) noexcept {
  return std::min(mx, my) >= kFilterMin && std::max(mx, my) <= kFilterMax;
}
inline bool in_filter_range(double mx, double my, double mz) noexcept {
  return std::min(mx, std::min(my, mz)) >= kFilterMin && std::max(mx, std::max(my, mz)) <= kFilterMax;
}

// True when x is zero or its magnitude is in the expansion-safe range.
inline bool expansion_safe(double x) noexcept {
  const double a = std::fabs(x);
  return a == 0 || (a >= kExpansionMin && a <= kExpansionMax);
}

// Whether expansions of long doubles decide the determinants exactly for every finite
// double input: their components are multiples of 2^-1074 below 2^1026, products of three
// (splits included) multiples of 2^-3222 below 2^3110, which long double's normal range
// holds when its exponents reach +-4096 (x87 extended precision, IEEE quad).
inline constexpr bool kLongDoubleExpansionsExact = std::numeric_limits<long double>::digits >= 53 &&
                                                   std::numeric_limits<long double>::max_exponent >= 4096 &&
                                                   std::numeric_limits<long double>::min_exponent <= -4096;

// The exact sign of det[b-a; c-a; d-a] in expansions with components of type F: double
// for inputs in the expansion-safe range, long double for all others (see above: exact
// for every finite double when kLongDoubleExpansionsExact; much cheaper than GMP integers
// when the exponents spread: 1 - 2^-1074 is two components there, 1,075 bits in GMP).
template <class F>
int orient3d_expansion(const double (&p)[12]) noexcept {
  Expansion<2, F> u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = diff<F>(p[3 + k], p[k]);
    v[k] = diff<F>(p[6 + k], p[k]);
    w[k] = diff<F>(p[9 + k], p[k]);
  }
  return det3_sign<2>(u, v, w);
}

// The same for det[b-a; c-a] of 2D points.
template <class F>
int orient2d_expansion(const double (&p)[6]) noexcept {
  return det2_sign<2>(diff<F>(p[2], p[0]), diff<F>(p[3], p[1]), diff<F>(p[4], p[0]), diff<F>(p[5], p[1]));
}

template <int N>
bool all_expansion_safe(const double (&p)[N]) noexcept {
  bool ok = true;
  for (int i = 0; i < N; ++i) ok &= expansion_safe(p[i]);
  return ok;
}

template <int N>
bool any_two_points_equal(const double (&p)[N], int dim) noexcept {
  for (int i = 0; i < N; i += dim)
    for (int j = i + dim; j < N; j += dim) {
      bool same = true;
      for (int k = 0; k < dim; ++k) same &= p[i + k] == p[j + k];
      if (same) return true;
    }
  return false;
}

// Exact stages of orient3d (the filter failed or was out of range).
inline Sign orient3d_exact(const double (&p)[12]) {
  // Repeated points (shared mesh vertices) make the determinant zero: skip the exact work.
  if (any_two_points_equal<12>(p, 3)) return Sign::Zero;
  if (!all_expansion_safe<12>(p)) {
    if constexpr (kLongDoubleExpansionsExact) return to_sign(orient3d_expansion<long double>(p));
    return to_sign(orient3d_gmp(p));
  }
  // The differences b-a, c-a, d-a, each split exactly into a rounded part and a tail.
  double hi[9], lo[9];
  bool tails = false;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) {
      two_diff(p[3 * (r + 1) + k], p[k], hi[3 * r + k], lo[3 * r + k]);
      tails |= lo[3 * r + k] != 0;
    }
  // Usually the differences are exact doubles within a narrow bit window (grids, float
  // meshes): 128-bit integers decide in a few dozen instructions.
  if (!tails) {
    const int s = det3_sign_integer(hi);
    if (s != 2) return to_sign(s);
  }
  return to_sign(orient3d_expansion<double>(p));
}

inline Sign orient2d_exact(const double (&p)[6]) {
  if (any_two_points_equal<6>(p, 2)) return Sign::Zero;
  if (!all_expansion_safe<6>(p)) {
    if constexpr (kLongDoubleExpansionsExact) return to_sign(orient2d_expansion<long double>(p));
    return to_sign(orient2d_gmp(p));
  }
  double hi[4], lo[4];
  two_diff(p[2], p[0], hi[0], lo[0]);
  two_diff(p[3], p[1], hi[1], lo[1]);
  two_diff(p[4], p[0], hi[2], lo[2]);
  two_diff(p[5], p[1], hi[3], lo[3]);
  if (lo[0] == 0 && lo[1] == 0 && lo[2] == 0 && lo[3] == 0) {
    const int s = det2_sign_integer(hi);
    if (s != 2) return to_sign(s);
  }
  return to_sign(orient2d_expansion<double>(p));
}

// The filter failed or could not run: an axis whose differences are all exactly zero
// puts the four points in one plane (fl(x - y) == 0 exactly when x == y); otherwise the
// exact stages. Out of line, so that the filter path needs no stack frame.
[[gnu::noinline]] inline Sign orient3d_unfiltered(const double* a, const double* b, const double* c, const double* d,
                                                  double mx, double my, double mz) {
  if (mx == 0 || my == 0 || mz == 0) return Sign::Zero;
  const double p[12] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]};
  return orient3d_exact(p);
}

[[gnu::noinline]] inline Sign orient2d_unfiltered(double ax, double ay, double bx, double by, double cx, double cy,
                                                  double mx, double my) {
  if (mx == 0 || my == 0) return Sign::Zero;  // the three points are on one axis line
  const double p[6] = {ax, ay, bx, by, cx, cy};
  return orient2d_exact(p);
}

}  // namespace detail

// Sign of det[b-a; c-a; d-a]: Positive when d is on the side of plane abc that
// (b-a) x (c-a) points to. Exact for all finite doubles.
inline Sign orient3d(const double* a, const double* b, const double* c, const double* d) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  const double mx = detail::max_abs(ux, vx, wx);
  const double my = detail::max_abs(uy, vy, wy);
  const double mz = detail::max_abs(uz, vz, wz);
  // The determinant is computed before the range test: out of range it may overflow, and
  // is then unused.
  const double det = ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
  const double bound = detail::kOrient3dBound * mx * my * mz;
  if (detail::in_filter_range(mx, my, mz)) {
    if (det > bound) return Sign::Positive;
    if (det < -bound) return Sign::Negative;
  }
  return detail::orient3d_unfiltered(a, b, c, d, mx, my, mz);
}

inline Sign orient3d(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c,
                     const std::array<double, 3>& d) {
  return orient3d(a.data(), b.data(), c.data(), d.data());
}

namespace detail {
// Points in or near the plane: the queries the shared filter left open (bits of
// `unsure`), again through orient3d, whose filter runs once more: keeping each query's
// mx, my, mz for orient3d_unfiltered instead cost the deciding path ~3 ns per call
// (measured). Out of line, as orient3d_unfiltered.
[[gnu::noinline]] inline void orient3d_each_unfiltered(const double* a, const double* b, const double* c,
                                                       const double* const (&d)[3], int unsure, Sign (&s)[3]) {
  for (int j = 0; j < 3; ++j)
    if (unsure >> j & 1) s[j] = orient3d(a, b, c, d[j]);
}
}  // namespace detail

// s[j] = orient3d(a, b, c, d[j]) for j = 0, 1, 2, with the normal (b-a) x (c-a) computed once:
// det = (d-a) . ((b-a) x (c-a)) has the same six elementary terms as orient3d's
// expansion, each through the same number of roundings, so the same bound holds with
// each query's own mx, my, mz. The three filters run before any exact stage; a query
// they leave open goes through orient3d. Exact for all finite doubles.
inline void orient3d_each(const double* a, const double* b, const double* c, const double* const (&d)[3],
                          Sign (&s)[3]) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  const double mux = detail::max_abs(ux, vx), muy = detail::max_abs(uy, vy), muz = detail::max_abs(uz, vz);
  int unsure = 0;  // bit j: the filter did not decide query j
  for (int j = 0; j < 3; ++j) {
    const double wx = d[j][0] - a[0], wy = d[j][1] - a[1], wz = d[j][2] - a[2];
    const double mx = detail::max_abs(mux, wx), my = detail::max_abs(muy, wy), mz = detail::max_abs(muz, wz);
    const double det = wx * nx + wy * ny + wz * nz;
    const double bound = detail::kOrient3dBound * mx * my * mz;
    const bool sure = detail::in_filter_range(mx, my, mz) && (det > bound || det < -bound);
    s[j] = det > 0 ? Sign::Positive : Sign::Negative;
    unsure |= int(!sure) << j;
  }
  if (unsure) [[unlikely]]
    detail::orient3d_each_unfiltered(a, b, c, d, unsure, s);
}

// Sign of det[b-a; c-a] in 2D: Positive when a, b, c turn counter-clockwise.
// Exact for all finite doubles.
inline Sign orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double ux = bx - ax, uy = by - ay, vx = cx - ax, vy = cy - ay;
  const double mx = detail::max_abs(ux, vx);
  const double my = detail::max_abs(uy, vy);
  const double det = ux * vy - uy * vx;
  const double bound = detail::kOrient2dBound * mx * my;
  if (detail::in_filter_range(mx, my)) {
    if (det > bound) return Sign::Positive;
    if (det < -bound) return Sign::Negative;
  }
  return detail::orient2d_unfiltered(ax, ay, bx, by, cx, cy, mx, my);
}

// orient2d of 3D points projected onto `plane` (see Plane for the axis order).
inline Sign orient2d(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c,
                     Plane plane) {
  const auto [i, j] = plane_axes(plane);
  return orient2d(a[i], a[j], b[i], b[j], c[i], c[j]);
}

}  // namespace tritri
