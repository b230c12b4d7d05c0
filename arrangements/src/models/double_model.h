// arrangements/src/models/double_model.h
//
// DoubleModel: the pipeline's point model (point_model.h) for double input, the fast
// path: input vertices are exact doubles, new points are tritri::ImplicitPoint (LPI, TPI)
// over them, never rounded; predicates are tritri's filtered exact double and implicit
// predicates, with the certified bounds of tritri/point_bounds.h deciding most comparisons
// and point locations from a few flops. Every function forwards to tritri or to the
// pipeline's support/ headers: the stages written against the model compile to what they
// were before the model existed.
#pragma once

#include <optional>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

#include <tritri/double_kernel.h>
#include <tritri/double_predicates.h>
#include <tritri/implicit_point.h>
#include <tritri/implicit_predicates.h>
#include <tritri/plane_filter.h>
#include <tritri/point_bounds.h>
#include <tritri/projection.h>

#include "arrangements/triangle_soup.h"
#include "models/point_model.h"
#include "support/auxiliary_point.h"
#include "support/side_of_line.h"

namespace arrangements {

struct DoubleModel {
  using Input = Vec3;
  using Vertex = Vec3;
  using Point = tritri::ImplicitPoint;
  using Kernel = tritri::DoubleKernel;
  using Key = tritri::XBounds;
  using Box = tritri::BoxBounds;
  using PlaneCache = tritri::PlaneFilter;
  using Local = tritri::OffsetPoint;
  static constexpr bool kProjectionFirst = false;  // stage 2: see detect_pairs
  static constexpr bool kCanScale = true;

  // Conversions of any point: exact rationals, nearest doubles (correctly rounded).
  static ExactVec3 to_exact(const Point& p) { return tritri::to_exact(p); }
  static Vec3 to_double(const Point& p) { return tritri::to_double(p); }

  // Stage 1: -0.0 becomes +0.0 (equal positions, equal bits).
  static Vertex vertex(const Input& p) { return {p[0] + 0.0, p[1] + 0.0, p[2] + 0.0}; }
  static std::uint64_t hash_bits(std::uint64_t h, const Vertex& p) {
    for (double x : p) {
      std::uint64_t b = 0;
      std::memcpy(&b, &x, sizeof x);
      h = mix(h ^ b);
    }
    return h;
  }
  static std::uint64_t mix(std::uint64_t x) {  // splitmix64 finaliser
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
  }
  static std::uint64_t hash(const Vertex& p) { return hash_bits(0, p); }

  // Projections: the dominant plane first (best conditioned), checked exactly.
  static std::pair<tritri::Plane, int> projection(const Vertex& a, const Vertex& b, const Vertex& c) {
    return tritri::projection(Kernel{}, a, b, c, tritri::dominant_plane(a, b, c));
  }

  // Stage 2: boxes and cached planes.
  static void bounds(const Vertex& p, Vec3& lo, Vec3& hi) { lo = hi = p; }
  static PlaneCache plane_cache(const Vertex& a, const Vertex& b, const Vertex& c) {
    return tritri::plane_filter(a, b, c);
  }
  static tritri::Sign side_of_plane(const PlaneCache& f, const Vertex& a, const Vertex& b, const Vertex& c,
                                    const Vertex& d) {
    return tritri::side_of_plane(f, a, b, c, d);
  }
  // The same sign when the cached plane's filter alone certifies it (a: the first corner).
  static std::optional<tritri::Sign> certified_side_of_plane(const PlaneCache& f, const Vertex& a, const Vertex& d) {
    return f.certified_side(a, d);
  }

  // Stages 4 and 5: points.
  static Point explicit_point(const Vertex& p) { return Point::explicit_point(p); }
  static Vertex auxiliary_point(const Vertex& a, const Vertex& b, const Vertex& c) {
    return arrangements::auxiliary_point(a, b, c);
  }
  static Point lpi(const Vertex& p, const Vertex& q, const Vertex& r, const Vertex& s, const Vertex& t) {
    return Point::lpi(p, q, r, s, t);
  }
  static Point tpi(const Vertex& a0, const Vertex& a1, const Vertex& a2, const Vertex& b0, const Vertex& b1,
                   const Vertex& b2, const Vertex& c0, const Vertex& c1, const Vertex& c2) {
    return Point::tpi(a0, a1, a2, b0, b1, b2, c0, c1, c2);
  }
  static Key key(const Point& p) { return tritri::direction_bounds(p); }
  static int compare(const Point& p, const Key& kp, const Point& q, const Key& kq) {
    return tritri::compare_along_direction(p, kp, q, kq);
  }
  static int compare_xyz(const Point& p, const Point& q) { return tritri::compare_xyz(p, q); }
  static bool vertex_less(const Vertex& a, const Vertex& b) { return a < b; }
  static Box box(const Point& p) { return tritri::box_bounds(p); }
  static int side_bounded(const Vertex& a, const Vertex& b, const Box& x, tritri::Plane plane) {
    return tritri::orient2d_bounded(a, b, x, plane);
  }
  static int side_of_line(const Point& a, const Point& b, const Point& x, tritri::Plane plane,
                          const Point* third = nullptr) {
    return arrangements::side_of_line(a, b, x, plane, third);
  }
  static tritri::Sign orient3d(const Vertex& a, const Vertex& b, const Vertex& c, const Vertex& d) {
    return tritri::orient3d(a, b, c, d);
  }
  static tritri::Sign orient2d(const Vertex& a, const Vertex& b, const Vertex& c, tritri::Plane plane) {
    return tritri::orient2d(a, b, c, plane);
  }
  static Local local(const Point& p, const Vertex& origin) { return tritri::offset_point(p, origin); }
  static tritri::Sign orient2d_local(const Local& a, const Local& b, const Local& c, tritri::Plane plane) {
    return tritri::orient2d(a, b, c, plane);
  }

  // The point p of a model scaled by 2^k, in the unscaled model's frame: its defining
  // points scaled by 2^-k (exact: preprocessing only scales when that is exact both ways).
  static Point unscaled(const Point& p, int k) {
    auto back = [k](const Vec3& c) { return Vec3{std::ldexp(c[0], -k), std::ldexp(c[1], -k), std::ldexp(c[2], -k)}; };
    using Kind = Point::Kind;
    if (p.kind() == Kind::Explicit) return Point::explicit_point(back(p.approx()));
    Vec3 in[9];
    for (int i = 0; i < p.input_count(); ++i) in[i] = back(p.input(i));
    if (p.kind() == Kind::LPI) return Point::lpi(in[0], in[1], in[2], in[3], in[4]);
    return Point::tpi(in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7], in[8]);
  }
};

static_assert(PointModel<DoubleModel>);

}  // namespace arrangements
