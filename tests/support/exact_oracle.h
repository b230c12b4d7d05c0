// tests/support/exact_oracle.h
//
// The exact reference of the tests, in one place: rational points and exact predicates
// written from their definitions, independent of the code under test (tritri is used only
// to read an ImplicitPoint's exact coordinates, tritri::to_exact).
//
//   Q, Q3              GMP rationals and rational points (mpq_class(double) is exact)
//   exact(p)           the Q3 of a double point, an ImplicitPoint, a Gmpq triple or an
//                      ExactKernel point
//   InputKernel, ExactKernel, RationalKernel   the CGAL kernels the tests compare with;
//                      to_cgal<K>(p) makes a K point of doubles or of a Q3
//   sub, cross, dot, normal, is_zero           vector arithmetic on Q3
//   ZPoint             a Q3 over one common denominator, for fast determinants
//   orient3d, orient2d(plane), compare, collinear   exact signs, -1, 0 or +1
//   kPlanes, projected_axes                    the projections of the 2D predicates
//   area2(a, b, c, axis), projection_axis, in_closed_triangle   projected areas and
//                      containment (area2 and projection_axis also on CGAL points)
//   in_open_segment, in_open_face              incidences on CGAL points (any kernel)
//   exact_lpi, exact_tpi                       LPI and TPI from their definitions
//   representable, to_string                   rationals that are doubles; printing
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <gmpxx.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include <tritri/implicit_point.h>
#include <tritri/sign.h>

namespace tritri_test {

using Q = mpq_class;
using Q3 = std::array<Q, 3>;

// Exact predicates on double input (filtered, fast); exact constructions (lazy rationals);
// plain rationals, no filter at all.
using InputKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using RationalKernel = CGAL::Simple_cartesian<CGAL::Gmpq>;

// ---------------------------------------------------------------------------------------
// Conversions.

inline Q3 exact(const std::array<double, 3>& p) { return {Q(p[0]), Q(p[1]), Q(p[2])}; }
inline Q3 exact(const std::array<CGAL::Gmpq, 3>& q) { return {Q(q[0].mpq()), Q(q[1].mpq()), Q(q[2].mpq())}; }
inline Q3 exact(const tritri::ImplicitPoint& p) { return exact(tritri::to_exact(p)); }
inline Q3 exact(const ExactKernel::Point_3& p) { return {CGAL::exact(p.x()), CGAL::exact(p.y()), CGAL::exact(p.z())}; }

template <class K>
typename K::Point_3 to_cgal(const std::array<double, 3>& p) {
  return typename K::Point_3(p[0], p[1], p[2]);
}

template <class K>
typename K::Point_3 to_cgal(const Q3& q) {
  using FT = typename K::FT;
  if constexpr (std::is_same_v<FT, CGAL::Gmpq>) {
    return typename K::Point_3(FT(q[0].get_mpq_t()), FT(q[1].get_mpq_t()), FT(q[2].get_mpq_t()));
  } else {
    return typename K::Point_3(FT(q[0]), FT(q[1]), FT(q[2]));
  }
}

// ---------------------------------------------------------------------------------------
// Vector arithmetic.

inline Q3 sub(const Q3& a, const Q3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Q3 cross(const Q3& a, const Q3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Q dot(const Q3& a, const Q3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline bool is_zero(const Q3& a) { return sgn(a[0]) == 0 && sgn(a[1]) == 0 && sgn(a[2]) == 0; }

// |e - d| <= |e - d'| for both neighbours d' of d, ties to even: d is e correctly rounded.
inline bool is_nearest_double(double d, const Q& e) {
  if (!std::isfinite(d)) return false;
  const Q err = abs(e - Q(d));
  for (double n : {std::nextafter(d, -INFINITY), std::nextafter(d, INFINITY)}) {
    if (!std::isfinite(n)) continue;
    const Q en = abs(e - Q(n));
    if (en < err) return false;
    if (en == err && (std::bit_cast<std::uint64_t>(std::fabs(d)) & 1) != 0) return false;  // tie: d must be even
  }
  return true;
}

// (b - a) x (c - a): the normal of the plane through a, b, c (zero when collinear).
inline Q3 normal(const Q3& a, const Q3& b, const Q3& c) { return cross(sub(b, a), sub(c, a)); }

// ---------------------------------------------------------------------------------------
// Exact signs. The determinants are taken over one common denominator: integer products
// only, much faster than rational arithmetic with a gcd after every operation.

struct ZPoint {
  std::array<mpz_class, 3> num;
  mpz_class den;  // positive
};

inline ZPoint common_denominator(const Q3& q) {
  ZPoint z;
  z.den = 1;
  for (const Q& c : q) mpz_lcm(z.den.get_mpz_t(), z.den.get_mpz_t(), c.get_den_mpz_t());
  for (int k = 0; k < 3; ++k) z.num[k] = q[k].get_num() * (z.den / q[k].get_den());
  return z;
}

// sign det[b-a; c-a; d-a]. Row i is x_i D_a - x_a D_i = D_a D_i (p_i - p_a), a positive
// multiple of the difference.
inline int orient3d(const ZPoint& a, const ZPoint& b, const ZPoint& c, const ZPoint& d) {
  const ZPoint* r[3] = {&b, &c, &d};
  mpz_class m[3][3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) m[i][k] = r[i]->num[k] * a.den - a.num[k] * r[i]->den;
  const mpz_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                        m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                        m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return sgn(det);
}

inline int orient3d(const Q3& a, const Q3& b, const Q3& c, const Q3& d) {
  return orient3d(common_denominator(a), common_denominator(b), common_denominator(c), common_denominator(d));
}

// The three projections of tritri's 2D predicates.
inline constexpr tritri::Plane kPlanes[3] = {tritri::Plane::XY, tritri::Plane::YZ, tritri::Plane::ZX};

// The projected coordinates of a plane: XY -> (x, y), YZ -> (y, z), ZX -> (z, x).
inline std::array<int, 2> projected_axes(tritri::Plane plane) {
  switch (plane) {
    case tritri::Plane::XY:
      return {0, 1};
    case tritri::Plane::YZ:
      return {1, 2};
    default:
      return {2, 0};
  }
}

// sign det[b-a; c-a] on the coordinates projected to `plane`.
inline int orient2d(const ZPoint& a, const ZPoint& b, const ZPoint& c, tritri::Plane plane) {
  const auto ax = projected_axes(plane);
  mpz_class m[2][2];
  const ZPoint* r[2] = {&b, &c};
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 2; ++k) m[i][k] = r[i]->num[ax[k]] * a.den - a.num[ax[k]] * r[i]->den;
  return sgn(mpz_class(m[0][0] * m[1][1] - m[0][1] * m[1][0]));
}

inline int orient2d(const Q3& a, const Q3& b, const Q3& c, tritri::Plane plane) {
  return orient2d(common_denominator(a), common_denominator(b), common_denominator(c), plane);
}

// Lexicographic (x, y, z) comparison.
inline int compare(const Q3& a, const Q3& b) {
  for (int k = 0; k < 3; ++k) {
    const int c = cmp(a[k], b[k]);
    if (c != 0) return c < 0 ? -1 : 1;
  }
  return 0;
}

inline bool collinear(const Q3& a, const Q3& b, const Q3& c) { return is_zero(normal(a, b, c)); }

// ---------------------------------------------------------------------------------------
// Projected areas and containment. area2 and projection_axis take Q3 or CGAL points.

template <class P>
using Coordinate = std::remove_cvref_t<decltype(std::declval<const P&>()[0])>;

// Twice the signed area of (a, b, c) projected along `axis` (coordinates axis+1, axis+2):
// component `axis` of the normal (b - a) x (c - a).
template <class P>
Coordinate<P> area2(const P& a, const P& b, const P& c, int axis) {
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  return (b[i] - a[i]) * (c[j] - a[j]) - (b[j] - a[j]) * (c[i] - a[i]);
}

// The axis along which the triangle's projection has the largest area (the first of
// equal ones); -1 when the triangle is degenerate.
template <class P>
int projection_axis(const P& a, const P& b, const P& c) {
  int best = -1;
  Coordinate<P> best_area = 0;
  for (int k = 0; k < 3; ++k) {
    Coordinate<P> area = area2(a, b, c, k);
    if (area < 0) area = -area;
    if (area != 0 && (best < 0 || area > best_area)) best = k, best_area = area;
  }
  return best;
}

// p in the closed triangle (a, b, c), all four coplanar, in the projection along `axis`.
inline bool in_closed_triangle(const Q3& a, const Q3& b, const Q3& c, const Q3& p, int axis) {
  const int s = sgn(area2(a, b, c, axis));
  return sgn(area2(a, b, p, axis)) * s >= 0 && sgn(area2(b, c, p, axis)) * s >= 0 && sgn(area2(c, a, p, axis)) * s >= 0;
}

// x strictly inside the open segment (p, q), p != q.
template <class P>
bool in_open_segment(const P& x, const P& p, const P& q) {
  return CGAL::collinear(p, q, x) && CGAL::collinear_are_strictly_ordered_along_line(p, x, q);
}

// x strictly inside the open face of the non-degenerate triangle t.
template <class P>
bool in_open_face(const P& x, const std::array<P, 3>& t) {
  if (CGAL::orientation(t[0], t[1], t[2], x) != CGAL::COPLANAR) return false;
  for (int i = 0; i < 3; ++i)
    if (CGAL::coplanar_orientation(t[i], t[(i + 1) % 3], t[(i + 2) % 3], x) != CGAL::POSITIVE) return false;
  return true;
}

// ---------------------------------------------------------------------------------------
// Implicit points from their definitions (not from the library's homogeneous coordinates).

using DoublePoint = std::array<double, 3>;
using DoubleTriple = std::array<DoublePoint, 3>;  // three points spanning a plane

// The line through p, q meets the plane of `plane`: p + (n.(r-p)) / (n.(q-p)) (q-p) with
// n the plane's normal; nullopt when n.(q-p) = 0 (also for p == q or a collinear triple).
inline std::optional<Q3> exact_lpi(const DoublePoint& p, const DoublePoint& q, const DoubleTriple& plane) {
  const Q3 P = exact(p), R = exact(plane[0]);
  const Q3 n = normal(R, exact(plane[1]), exact(plane[2]));
  const Q3 d = sub(exact(q), P);
  const Q den = dot(n, d);
  if (den == 0) return std::nullopt;
  const Q lambda = dot(n, sub(R, P)) / den;
  return Q3{P[0] + lambda * d[0], P[1] + lambda * d[1], P[2] + lambda * d[2]};
}

inline Q det3(const Q (&m)[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// The three planes meet: plane i is n_i . x = n_i . a_i; Cramer's rule; nullopt when the
// system is singular.
inline std::optional<Q3> exact_tpi(const std::array<DoubleTriple, 3>& planes) {
  Q m[3][3], k[3];
  for (int i = 0; i < 3; ++i) {
    const Q3 a = exact(planes[i][0]);
    const Q3 n = normal(a, exact(planes[i][1]), exact(planes[i][2]));
    for (int j = 0; j < 3; ++j) m[i][j] = n[j];
    k[i] = dot(n, a);
  }
  const Q det = det3(m);
  if (det == 0) return std::nullopt;
  Q3 x;
  for (int j = 0; j < 3; ++j) {
    Q mj[3][3];
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) mj[i][c] = c == j ? k[i] : m[i][c];
    x[j] = det3(mj) / det;
  }
  return x;
}

// ---------------------------------------------------------------------------------------
// Doubles and printing.

// True when the rational is a double (then `out` is that double).
inline bool representable(const Q& q, double& out) {
  out = q.get_d();
  return std::isfinite(out) && Q(out) == q;
}

inline std::string to_string(const Q3& q) {
  return "(" + q[0].get_str() + ", " + q[1].get_str() + ", " + q[2].get_str() + ")";
}

}  // namespace tritri_test
