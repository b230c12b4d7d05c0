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
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include <tritri/cgal_kernel.h>
#include <tritri/detail/homogeneous.h>
#include <tritri/point_bounds.h>
#include <tritri/projection.h>

#include "arrangements/triangle_soup.h"
#include "models/point_model.h"

namespace arrangements {

// tritri's kernel concept on Epeck points, without constructions: orient3d, equal and
// less are Epeck's filtered predicates; orient2d evaluates the projected determinant on
// the points' intervals and, when that cannot decide, on their rationals (CGAL's
// projection traits would construct lazy 2D points for every call).
struct EpeckKernel {
  using Point = CGAL::Epeck::Point_3;
  static tritri::Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    return tritri::CgalKernel<CGAL::Epeck>::orient3d(a, b, c, d);
  }
  static tritri::Sign orient2d(const Point& a, const Point& b, const Point& c, tritri::Plane plane) {
    const int i = plane == tritri::Plane::XY ? 0 : (plane == tritri::Plane::YZ ? 1 : 2), j = (i + 1) % 3;
    {
      CGAL::Protect_FPU_rounding<true> upward;
      const auto &A = a.approx(), &B = b.approx(), &C = c.approx();
      const auto d = (B[i] - A[i]) * (C[j] - A[j]) - (B[j] - A[j]) * (C[i] - A[i]);
      if (d.inf() > 0) return tritri::Sign::Positive;
      if (d.sup() < 0) return tritri::Sign::Negative;
    }
    const auto &A = a.exact(), &B = b.exact(), &C = c.exact();
    using ET = std::decay_t<decltype(A[0])>;  // named: gmpxx expression templates must not outlive their operands
    const ET d = (B[i] - A[i]) * (C[j] - A[j]) - (B[j] - A[j]) * (C[i] - A[i]);
    return d > 0 ? tritri::Sign::Positive : (d < 0 ? tritri::Sign::Negative : tritri::Sign::Zero);
  }
  static bool equal(const Point& a, const Point& b) { return a == b; }
  static bool less(const Point& a, const Point& b) { return CGAL::compare_xyz(a, b) == CGAL::SMALLER; }
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
    const auto n = tritri::detail::cross(tritri::detail::difference<ET>(eb, ea), tritri::detail::difference<ET>(ec, ea));
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
