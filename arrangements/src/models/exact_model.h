// arrangements/src/models/exact_model.h
//
// ExactModel: the pipeline's point model (point_model.h) for exact rational input: any
// input coordinate may be a rational (ExactVec3, CGAL::Gmpq), e.g. a vertex of an exact
// arrangement read back from its file. Every point, input vertex or new (LPI, TPI,
// auxiliary), is a CGAL::Epeck point whose rational coordinates are computed when it is
// made (tritri/detail/homogeneous.h: the same formulas as the implicit points of the
// double path, evaluated in CGAL's exact rational type) and held with a certified
// interval approximation; predicates are Epeck's (EpeckKernel below): the intervals
// decide almost every sign, the rationals the rest. Exact for any rational
// input; thread-safe (CGAL >= 5.5 lazy objects are reference counted atomically and
// evaluated once).
// Cost: a new point costs one rational evaluation of its formula (numbers grow with the
// depth of construction: an LPI of rational points has coordinates a few times as long as
// its inputs'); predicates cost an interval evaluation when it decides.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include <tritri/kernel_concept.h>
#include <tritri/double_predicates.h>
#include <tritri/detail/homogeneous.h>
#include <tritri/point_bounds.h>
#include <tritri/projection.h>

#include "arrangements/triangle_soup.h"
#include "models/point_model.h"

namespace arrangements {

// tritri's kernel concept on Epeck points, without constructions: orient2d and orient3d
// evaluate their determinant on the points' cached intervals and, when that cannot decide,
// on their rationals, as integers: each row of differences is scaled by the product of its
// denominators (positive, so the sign is kept), which avoids the gcd of every rational
// operation (an exact zero, coplanar or collinear points, is the common case there).
// equal and less are Epeck's filtered predicates.
struct EpeckKernel {
  using Point = CGAL::Epeck::Point_3;
  using Rational = std::decay_t<decltype(std::declval<const Point&>().exact().x())>;
  static_assert(std::is_same_v<Rational, mpq_class>, "EpeckKernel expects CGAL built with GMPXX");

  static tritri::Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    {
      CGAL::Protect_FPU_rounding<true> upward;
      const auto &A = a.approx(), &B = b.approx(), &C = c.approx(), &D = d.approx();
      const auto u0 = B[0] - A[0], u1 = B[1] - A[1], u2 = B[2] - A[2];
      const auto v0 = C[0] - A[0], v1 = C[1] - A[1], v2 = C[2] - A[2];
      const auto w0 = D[0] - A[0], w1 = D[1] - A[1], w2 = D[2] - A[2];
      const auto det = u0 * (v1 * w2 - v2 * w1) - u1 * (v0 * w2 - v2 * w0) + u2 * (v0 * w1 - v1 * w0);
      if (det.inf() > 0) return tritri::Sign::Positive;
      if (det.sup() < 0) return tritri::Sign::Negative;
    }
    const auto &A = a.exact(), &B = b.exact(), &C = c.exact(), &D = d.exact();
    std::array<double, 3> da, db, dc, dd;
    if (as_doubles(A, da) && as_doubles(B, db) && as_doubles(C, dc) && as_doubles(D, dd))
      return tritri::orient3d(da, db, dc, dd);  // input vertices: tritri's exact double predicate
    // Per-thread integers: their limbs are reused from call to call (no allocation).
    thread_local Scratch<3> s;
    integer_row<3>(A, B, {0, 1, 2}, s, 0);
    integer_row<3>(A, C, {0, 1, 2}, s, 1);
    integer_row<3>(A, D, {0, 1, 2}, s, 2);
    const auto& m = s.row;
    s.t[0] = m[1][1] * m[2][2];
    s.t[1] = m[1][2] * m[2][1];
    s.t[0] -= s.t[1];
    s.det = m[0][0] * s.t[0];
    s.t[0] = m[1][0] * m[2][2];
    s.t[1] = m[1][2] * m[2][0];
    s.t[0] -= s.t[1];
    s.t[1] = m[0][1] * s.t[0];
    s.det -= s.t[1];
    s.t[0] = m[1][0] * m[2][1];
    s.t[1] = m[1][1] * m[2][0];
    s.t[0] -= s.t[1];
    s.t[1] = m[0][2] * s.t[0];
    s.det += s.t[1];
    return to_sign(sgn(s.det));
  }
  static tritri::Sign orient2d(const Point& a, const Point& b, const Point& c, tritri::Plane plane) {
    const int i = static_cast<int>(plane), j = (i + 1) % 3;  // XY: (x, y), YZ: (y, z), ZX: (z, x)
    {
      CGAL::Protect_FPU_rounding<true> upward;
      const auto &A = a.approx(), &B = b.approx(), &C = c.approx();
      const auto d = (B[i] - A[i]) * (C[j] - A[j]) - (B[j] - A[j]) * (C[i] - A[i]);
      if (d.inf() > 0) return tritri::Sign::Positive;
      if (d.sup() < 0) return tritri::Sign::Negative;
    }
    const auto &A = a.exact(), &B = b.exact(), &C = c.exact();
    std::array<double, 3> da, db, dc;
    if (as_doubles(A, da) && as_doubles(B, db) && as_doubles(C, dc)) return tritri::orient2d(da, db, dc, plane);
    thread_local Scratch<2> s;
    integer_row<2>(A, B, {i, j}, s, 0);
    integer_row<2>(A, C, {i, j}, s, 1);
    s.det = s.row[0][0] * s.row[1][1];
    s.t[0] = s.row[0][1] * s.row[1][0];
    s.det -= s.t[0];
    return to_sign(sgn(s.det));
  }
  static bool equal(const Point& a, const Point& b) { return a == b; }
  static bool less(const Point& a, const Point& b) { return CGAL::compare_xyz(a, b) == CGAL::SMALLER; }

 private:
  // Whether every coordinate of p is a double (a dyadic rational with at most 53
  // significant bits, in range; vertices read from files usually are), and its value.
  template <class P>
  static bool as_doubles(const P& p, std::array<double, 3>& out) {
    for (int k = 0; k < 3; ++k) {
      const mpz_srcptr num = p[k].get_num_mpz_t(), den = p[k].get_den_mpz_t();
      const std::size_t den_bits = mpz_sizeinbase(den, 2);
      if (mpz_scan1(den, 0) != den_bits - 1 || den_bits > 1075) return false;  // not a power of two, or too small
      const std::size_t num_bits = mpz_sgn(num) == 0 ? 0 : mpz_sizeinbase(num, 2);
      // Canonical: a numerator over 2^e > 1 is odd, so its bits are all significant; the
      // highest one, at num_bits - 1 - e, must be at most 1023.
      if (num_bits > 53 || num_bits > 1023 + den_bits) return false;
      // Exact: a numerator of at most 53 bits is a double, and so is its value.
      out[k] = std::ldexp(mpz_get_d(num), -static_cast<int>(den_bits - 1));
    }
    return true;
  }
  static tritri::Sign to_sign(int s) {
    return s > 0 ? tritri::Sign::Positive : (s < 0 ? tritri::Sign::Negative : tritri::Sign::Zero);
  }
  template <int N>
  struct Scratch {
    std::array<std::array<mpz_class, N>, N> row;
    std::array<mpz_class, N> num, den;
    mpz_class lcm, det;
    std::array<mpz_class, 2> t;
  };
  // Row r of s: q - p on the given axes, times the least common multiple of its entries'
  // denominators (positive; equal denominators, the common case, cost no gcd).
  template <int N, class P>
  static void integer_row(const P& p, const P& q, std::array<int, N> axes, Scratch<N>& s, int r) {
    for (int k = 0; k < N; ++k) {
      const Rational &x = q[axes[k]], &y = p[axes[k]];
      if (x.get_den() == y.get_den()) {
        s.num[k] = x.get_num() - y.get_num();
        s.den[k] = x.get_den();
      } else {
        s.num[k] = x.get_num() * y.get_den();
        s.t[0] = y.get_num() * x.get_den();
        s.num[k] -= s.t[0];
        s.den[k] = x.get_den() * y.get_den();
      }
    }
    s.lcm = s.den[0];
    for (int k = 1; k < N; ++k)
      if (s.den[k] != s.lcm) mpz_lcm(s.lcm.get_mpz_t(), s.lcm.get_mpz_t(), s.den[k].get_mpz_t());
    for (int k = 0; k < N; ++k) {
      if (s.den[k] == s.lcm) {
        s.row[r][k] = s.num[k];
      } else {
        mpz_divexact(s.row[r][k].get_mpz_t(), s.lcm.get_mpz_t(), s.den[k].get_mpz_t());
        s.row[r][k] *= s.num[k];
      }
    }
  }
};

struct ExactModel {
  using Input = ExactVec3;
  using Vertex = CGAL::Epeck::Point_3;
  using Point = Vertex;
  using Kernel = EpeckKernel;
  struct Key {};
  using Box = tritri::BoxBounds;
  struct PlaneCache {};
  using Local = Point;
  static constexpr bool kProjectionFirst = true;  // stage 2: see detect_pairs
  static constexpr bool kCanScale = false;

  using FT = CGAL::Epeck::FT;
  using ET = std::decay_t<decltype(std::declval<const FT&>().exact())>;
  using ExactPoint = std::decay_t<decltype(std::declval<const Point&>().exact())>;

  // Conversions between the public rationals (CGAL::Gmpq) and CGAL's exact type (GMP's
  // mpq_class or CGAL::Gmpq, as CGAL was configured).
  static ET to_et(const CGAL::Gmpq& q) { return convert<ET>(q); }
  static CGAL::Gmpq to_gmpq(const ET& e) { return convert<CGAL::Gmpq>(e); }
  static Point make(const ET& x, const ET& y, const ET& z) { return Point(FT(x), FT(y), FT(z)); }
  static Input to_input(const Point& p) {
    const ExactPoint& e = p.exact();
    return {to_gmpq(e.x()), to_gmpq(e.y()), to_gmpq(e.z())};
  }

  // Conversions of any point: exact rationals, nearest doubles (correctly rounded).
  static ExactVec3 to_exact(const Point& p) { return to_input(p); }
  static Vec3 to_double(const Point& p) { return tritri::to_double(to_input(p)); }

  // Stage 1. Equal rationals have equal certified intervals (computed from the rational),
  // so hashing the interval ends is consistent with exact equality.
  static Vertex vertex(const Input& p) { return make(to_et(p[0]), to_et(p[1]), to_et(p[2])); }
  static std::uint64_t hash(const Vertex& p) {
    std::uint64_t h = 0;
    const auto& a = p.approx();
    for (int k = 0; k < 3; ++k)
      for (double x : {a[k].inf(), a[k].sup()}) {
        std::uint64_t b = 0;
        x += 0.0;  // -0.0 and +0.0
        std::memcpy(&b, &x, sizeof x);
        h ^= b + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
      }
    return h;
  }

  static std::pair<tritri::Plane, int> projection(const Vertex& a, const Vertex& b, const Vertex& c) {
    return tritri::projection(Kernel{}, a, b, c, tritri::dominant_plane(a, b, c));
  }

  // Stage 2: conservative boxes from the intervals; planes are not cached.
  static void bounds(const Vertex& p, Vec3& lo, Vec3& hi) {
    const auto& a = p.approx();
    for (int k = 0; k < 3; ++k) {
      lo[k] = a[k].inf();
      hi[k] = a[k].sup();
    }
  }
  static PlaneCache plane_cache(const Vertex&, const Vertex&, const Vertex&) { return {}; }
  static tritri::Sign side_of_plane(const PlaneCache&, const Vertex& a, const Vertex& b, const Vertex& c,
                                    const Vertex& d) {
    return Kernel::orient3d(a, b, c, d);
  }

  // Stages 4 and 5.
  static Point explicit_point(const Vertex& p) { return p; }
  // a plus the exact normal: orient3d(a, b, c, a + n) = |n|^2 > 0 for a proper triangle.
  static Vertex auxiliary_point(const Vertex& a, const Vertex& b, const Vertex& c) {
    const ExactPoint &ea = a.exact(), &eb = b.exact(), &ec = c.exact();
    const auto n =
        tritri::detail::cross(tritri::detail::difference<ET>(eb, ea), tritri::detail::difference<ET>(ec, ea));
    if (n[0] == 0 && n[1] == 0 && n[2] == 0) throw std::logic_error("auxiliary_point: degenerate triangle");
    return make(ea.x() + n[0], ea.y() + n[1], ea.z() + n[2]);
  }
  static Point lpi(const Vertex& p, const Vertex& q, const Vertex& r, const Vertex& s, const Vertex& t) {
    return from_homogeneous(tritri::detail::lpi_homogeneous<ET>(p.exact(), q.exact(), r.exact(), s.exact(), t.exact()));
  }
  static Point tpi(const Vertex& a0, const Vertex& a1, const Vertex& a2, const Vertex& b0, const Vertex& b1,
                   const Vertex& b2, const Vertex& c0, const Vertex& c1, const Vertex& c2) {
    const std::array<ExactPoint, 9> in = {a0.exact(), a1.exact(), a2.exact(), b0.exact(), b1.exact(),
                                          b2.exact(), c0.exact(), c1.exact(), c2.exact()};
    return from_homogeneous(tritri::detail::tpi_homogeneous<ET>(std::span<const ExactPoint, 9>(in)));
  }
  // The order is lexicographic (x, y, z): total, and monotone along any line.
  static Key key(const Point&) { return {}; }
  static int compare(const Point& p, const Key&, const Point& q, const Key&) { return compare_xyz(p, q); }
  static int compare_xyz(const Point& p, const Point& q) { return static_cast<int>(CGAL::compare_xyz(p, q)); }
  static bool vertex_less(const Vertex& a, const Vertex& b) { return compare_xyz(a, b) < 0; }
  static Box box(const Point& p) {
    Box b;
    const auto& a = p.approx();
    for (int k = 0; k < 3; ++k) b[k] = {a[k].inf(), a[k].sup()};
    return b;
  }
  // No bounded shortcut: Epeck's own interval filter is the fast path here.
  static int side_bounded(const Vertex&, const Vertex&, const Box&, tritri::Plane) { return tritri::kUndecided; }
  static int side_of_line(const Point& a, const Point& b, const Point& x, tritri::Plane plane,
                          const Point* = nullptr) {
    return tritri::to_int(Kernel::orient2d(a, b, x, plane));
  }
  static tritri::Sign orient3d(const Vertex& a, const Vertex& b, const Vertex& c, const Vertex& d) {
    return Kernel::orient3d(a, b, c, d);
  }
  static tritri::Sign orient2d(const Vertex& a, const Vertex& b, const Vertex& c, tritri::Plane plane) {
    return Kernel::orient2d(a, b, c, plane);
  }
  static Local local(const Point& p, const Vertex&) { return p; }
  static tritri::Sign orient2d_local(const Local& a, const Local& b, const Local& c, tritri::Plane plane) {
    return Kernel::orient2d(a, b, c, plane);
  }
  static Point unscaled(const Point& p, int k) {
    if (k != 0) throw std::logic_error("ExactModel: exact input is never scaled");
    return p;
  }

 private:
  template <class To, class From>
  static To convert(const From& x) {
    if constexpr (std::is_same_v<To, From>) {
      return x;
    } else if constexpr (std::is_same_v<To, CGAL::Gmpq>) {
      return CGAL::Gmpq(x.get_mpq_t());
    } else {
      To e;
      mpq_set(e.get_mpq_t(), x.mpq());
      return e;
    }
  }
  static Point from_homogeneous(const tritri::detail::Homogeneous<ET>& h) {
    if (h.w == 0) throw std::logic_error("ExactModel: undefined intersection point");
    return make(h.x / h.w, h.y / h.w, h.z / h.w);
  }
};

static_assert(PointModel<ExactModel>);

}  // namespace arrangements
