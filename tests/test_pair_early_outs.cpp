// Specification of the pair early-outs of the arrangement pipeline's detection stage: tritri/plane_filter.h
// (PlaneFilter, side_of_plane, PlaneCachedKernel) and the sufficient tests of tritri/shared_vertices.h, against exact
// references on generated inputs.
//   1. PlaneFilter::certified_side(a, d), when it answers, is the exact sign of orient3d(a, b, c, d); side_of_plane
//      always is. A triangle with a coordinate outside the expansion-safe range (nonzero magnitude below 2^-280 or
//      above 2^280) gets err = +inf and is never decided. The filter is useful: it decides over 99% of well-
//      conditioned random cases, and every sliver of relative width ~1e-9 whose point lies about an edge length off its
//      plane. Cases: random triangles, far and tiny points, slivers (relative widths 1e-3 .. 1e-15), points exactly on
//      the plane (integer grids), a few ulps off it, at dyadic distances 2^-k, on the float grid; offsets 1 .. 1e200
//      and scalings 2^k from the subnormal range to 2^1000. The reference tritri::orient3d is itself sampled against
//      GMP.
//   2. tritri::classify with a PlaneCachedKernel, whose planes are registered for the very point objects classified,
//      gives exactly DoubleKernel's Result (points, segments, coplanar, degenerate), and really goes through the cached
//      planes; so does its orient3d_each.
//   3. meet_only_in_shared, separated_by_plane, meet_in_shared_in_projection, separated_in_projection and
//      touches_only_in_shared, called only where their preconditions hold, answer true only when classify reports no
//      point or only VA_ON_VB points at vertex pairs shared by index (the "separated" ones: no point at all); each
//      fires often on the generated set; meet_only_in_shared_by_sides with exact (or cached-plane) signs equals
//      meet_only_in_shared and asks each sign at most once. Pairs: integer grids {0..3} and {0..4} (free, flat, and
//      touching one plane), sharing 0, 1 or 2 vertices by index, mapped by integer matrices, scaled by 2^k and
//      translated, all exactly. Pairs whose triangle repeats an index get false from every index-based early-out.
// Cases at TRITRI_TEST_SCALE=1: 3M plane sides, 300k classified pairs, 1M neighbour pairs.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include <tritri/plane_filter.h>
#include <tritri/tritri.h>

#include "support/exact_oracle.h"
#include "support/pair_generators.h"
#include "support/test_scale.h"

namespace {

using tritri::Sign;
using tritri_test::Pair, tritri_test::Point, tritri_test::Rng, tritri_test::Triangle;
using tritri_test::scaled_count, tritri_test::seed_for, tritri_test::to_hex;
using Ids = std::array<int, 3>;

bool safe_triangle(const Triangle& t) {
  for (const Point& p : t)
    for (double x : p)
      if (!tritri::detail::expansion_safe(x)) return false;
  return true;
}

Point add(const Point& p, double s, const Point& v) { return {p[0] + s * v[0], p[1] + s * v[1], p[2] + s * v[2]}; }
Point sub(const Point& p, const Point& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }
Point cross(const Point& u, const Point& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
double dot(const Point& u, const Point& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }
double norm(const Point& u) { return std::sqrt(dot(u, u)); }
Point unit(const Point& u) { return add({0, 0, 0}, 1 / norm(u), u); }
Point random_point(Rng& rng) { return {rng.symmetric_unit(), rng.symmetric_unit(), rng.symmetric_unit()}; }
double uniform01(Rng& rng) { return 0.5 * (rng.symmetric_unit() + 1); }

std::string describe(const Triangle& t, const Point& d) { return "t = " + to_hex(t) + ", d = " + to_hex(d); }

// ---------------------------------------------------------------------------------------
// 1. Plane sides.

enum Kind { kRandom, kFarPoint, kSliver, kSliverOff, kOnPlane, kNearPlane, kDyadic, kFloatGrid, kOutOfRange, kKinds };
constexpr const char* kKindNames[kKinds] = {"random",     "far point", "sliver",     "sliver, point off", "on plane",
                                            "near plane", "at 2^-k",   "float grid", "out of range"};
constexpr double kOffsets[] = {0, 1, 1e3, 1e6, 1e9, 1e15, 1e30, 1e100, 1e200};

// Where a local configuration (coordinates about 1) goes: o + L p, rounded.
struct Placement {
  Point o{0, 0, 0};
  double L = 1;
  Point at(const Point& p) const { return add(o, L, p); }
};

Placement random_placement(Rng& rng, int max_offset_index = 8) {
  const double off = kOffsets[rng.uniform(0, max_offset_index)];
  Placement pl;
  for (double& x : pl.o) x = off * (rng.percent(50) ? 1 : -1) * (1 + rng.uniform(0, 7) * 0.125);
  if (off != 0) {
    pl.L = off * std::ldexp(1.0, -rng.uniform(0, 40));
    return pl;
  }
  static constexpr int kRanges[4][2] = {{-20, 20}, {-300, 300}, {-1070, -900}, {900, 1000}};
  const auto& r = kRanges[rng.uniform(0, 3)];
  pl.L = std::ldexp(1.0, rng.uniform(r[0], r[1]));
  return pl;
}

struct Frame {
  Point e1, e2, e3;  // roughly orthonormal
};

Frame random_frame(Rng& rng) {
  Frame f;
  f.e1 = unit(random_point(rng));
  const Point r = random_point(rng);
  f.e2 = unit(add(r, -dot(r, f.e1), f.e1));
  f.e3 = cross(f.e1, f.e2);
  return f;
}

// A long thin triangle: edge a-b of length len along e1, c at relative distance `width`.
Triangle local_sliver(Rng& rng, const Frame& f, double width, double len) {
  const Point a = add({0, 0, 0}, 0.5, random_point(rng));
  const double t = -0.2 + 1.4 * uniform01(rng);
  return {a, add(a, len, f.e1), add(add(a, t * len, f.e1), width * len, f.e2)};
}

// Integer points a, b, c and d = a + i (b - a) + j (c - a): exactly coplanar.
std::array<Point, 4> integer_coplanar(Rng& rng) {
  static constexpr int kRadius[] = {3, 1000, 1 << 20};
  const int r = kRadius[rng.uniform(0, 2)];
  std::array<Point, 4> q;
  for (int v = 0; v < 3; ++v) q[v] = tritri_test::grid_point(rng, -r, r);
  const int i = rng.uniform(-3, 3), j = rng.uniform(-3, 3);
  q[3] = add(add(q[0], i, sub(q[1], q[0])), j, sub(q[2], q[0]));
  return q;
}

// Scales by 2^k and translates, keeping each step only when it is exact (so the incidences
// survive whenever the numbers allow).
void scale_and_offset(Rng& rng, std::array<Point, 4>& q) {
  Pair p{{q[0], q[1], q[2]}, {q[3], q[3], q[3]}}, s;
  static constexpr int kScales[] = {-1074, -1060, -1030, -1000, -600, -300, 0, 0, 30, 300, 600, 960};
  const int k = rng.percent(50) ? kScales[rng.uniform(0, 11)] : rng.uniform(-60, 60);
  if (tritri_test::scale_by_power_of_two(p, k, s)) p = s;
  const double off = kOffsets[rng.uniform(0, 8)];
  Point d;
  for (double& x : d) x = rng.percent(30) ? 0.0 : (rng.percent(50) ? off : -off) * (1 + rng.uniform(0, 3) * 0.25);
  if (rng.percent(30)) d = {std::ldexp(rng.uniform(-64, 64), k + 20), 0, std::ldexp(rng.uniform(-64, 64), k + 40)};
  if (tritri_test::translate_exactly(p, d, s)) p = s;
  q = {p.a[0], p.a[1], p.a[2], p.b[0]};
}

struct SideCase {
  Triangle t;
  Point d;
  bool must_decide = false;
};

SideCase make_side_case(Rng& rng, Kind kind) {
  SideCase c;
  switch (kind) {
    case kRandom:
    case kFarPoint: {
      const Placement pl = random_placement(rng);
      for (Point& v : c.t) v = pl.at(random_point(rng));
      c.d = pl.at(random_point(rng));
      if (kind == kFarPoint)
        for (double& x : c.d) x = std::ldexp(rng.symmetric_unit(), rng.uniform(-1074, 1023));
      break;
    }
    case kSliver: {
      const Frame f = random_frame(rng);
      const double width = std::pow(10.0, -rng.uniform(3, 15)), len = 1 + uniform01(rng);
      const Triangle s = local_sliver(rng, f, width, len);
      Point d = add(add(s[0], rng.symmetric_unit() * len, f.e1), rng.symmetric_unit() * len, f.e2);  // in plane
      if (rng.percent(50)) d = add(d, rng.symmetric_unit() * std::pow(10.0, -rng.uniform(0, 20)), f.e3);
      if (rng.percent(20)) d = random_point(rng);
      const Placement pl = random_placement(rng);
      for (int v = 0; v < 3; ++v) c.t[v] = pl.at(s[v]);
      c.d = pl.at(d);
      break;
    }
    case kSliverOff: {
      // Width 1e-9, the point an edge length off the plane, offsets at most ~1e3 lengths:
      // rounding keeps the shape, and the cached plane must certify every one.
      const Frame f = random_frame(rng);
      const double len = 1 + uniform01(rng);
      const Triangle s = local_sliver(rng, f, 1e-9 * (1 + uniform01(rng)), len);
      const double h = (rng.percent(50) ? 1 : -1) * (0.5 + 0.5 * uniform01(rng));
      const Point d =
          add(add(add(s[0], rng.symmetric_unit() * len, f.e1), rng.symmetric_unit() * len, f.e2), h * len, f.e3);
      Placement pl;
      const double off = kOffsets[rng.uniform(0, 6)];
      if (off == 0) {
        pl.L = std::ldexp(1.0, rng.uniform(-250, 250));
      } else {
        for (double& x : pl.o) x = off * rng.symmetric_unit();
        pl.L = off * std::ldexp(1.0, -rng.uniform(0, 8));
      }
      for (int v = 0; v < 3; ++v) c.t[v] = pl.at(s[v]);
      c.d = pl.at(d);
      c.must_decide = safe_triangle(c.t);
      break;
    }
    case kOnPlane:
    case kNearPlane:
    case kDyadic: {
      std::array<Point, 4> q = integer_coplanar(rng);
      if (kind == kDyadic) {
        const int j = rng.uniform(1, 60);
        Point g = tritri_test::grid_point(rng, -3, 3);
        if (g == Point{0, 0, 0}) g = {1, 0, 0};
        q[3] = add(q[3], std::ldexp(1.0, -j), g);
      }
      scale_and_offset(rng, q);
      if (kind == kNearPlane)
        for (int n = rng.uniform(1, 3); n > 0; --n) {
          double& x = rng.percent(70) ? q[3][rng.uniform(0, 2)] : q[rng.uniform(0, 2)][rng.uniform(0, 2)];
          x = tritri_test::nudge(x, rng.percent(50) ? rng.uniform(1, 4) : -rng.uniform(1, 4));
        }
      c.t = {q[0], q[1], q[2]};
      c.d = q[3];
      break;
    }
    case kFloatGrid: {
      Placement pl = random_placement(rng, 3);
      if (pl.o[0] == 0) pl.L = std::ldexp(1.0, rng.uniform(-100, 100));  // within float range
      auto to_float = [](Point p) {
        for (double& x : p) x = static_cast<float>(x);
        return p;
      };
      for (Point& v : c.t) v = to_float(pl.at(random_point(rng)));
      c.d = rng.percent(50) ? to_float(pl.at(random_point(rng)))
                            : to_float(add(add(c.t[0], rng.symmetric_unit(), sub(c.t[1], c.t[0])), rng.symmetric_unit(),
                                           sub(c.t[2], c.t[0])));
      break;
    }
    default: {  // kOutOfRange: one coordinate (or the whole triangle) beyond 2^280 or below 2^-280
      const int k = rng.percent(50) ? rng.uniform(281, 1020) : -rng.uniform(281, 1074);
      for (Point& v : c.t) v = random_point(rng);
      c.d = random_point(rng);
      if (rng.percent(50)) {
        for (Point& v : c.t)
          for (double& x : v) x = std::ldexp(x, k);
        for (double& x : c.d) x = std::ldexp(x, k);
      }
      c.t[rng.uniform(0, 2)][rng.uniform(0, 2)] = (rng.percent(50) ? 1 : -1) * std::ldexp(1.0 + uniform01(rng), k);
      break;
    }
  }
  if (kind == kRandom && safe_triangle(c.t)) {  // well-conditioned: not a sliver, d well off the plane
    const Point u = sub(c.t[1], c.t[0]), v = sub(c.t[2], c.t[0]), w = sub(c.d, c.t[0]), n = cross(u, v);
    const double e = std::max({norm(u), norm(v), norm(sub(v, u))});
    c.must_decide = norm(n) >= 0.05 * e * e && std::fabs(dot(n, w)) >= 0.05 * norm(n) * norm(w) &&
                    norm(n) * norm(w) >= 0x1p-880 && std::isfinite(norm(n) * norm(w));
  }
  return c;
}

TEST(PlaneFilter, CertifiedSidesAreExactAndDecideTheWellConditionedCases) {
  Rng rng(seed_for(0x9a1e));
  const long long n = scaled_count(3'000'000);
  long long cases[kKinds] = {}, decided[kKinds] = {}, zeros[kKinds] = {}, must[kKinds] = {}, must_decided[kKinds] = {};
  long long failures = 0, oracle_checked = 0;
  for (long long i = 0; i < n; ++i) {
    const Kind kind = static_cast<Kind>(i % kKinds);
    const SideCase c = make_side_case(rng, kind);
    const Triangle& t = c.t;
    const tritri::PlaneFilter f = tritri::plane_filter(t[0], t[1], t[2]);
    const Sign exact = tritri::orient3d(t[0], t[1], t[2], c.d);
    const std::optional<Sign> cert = f.certified_side(t[0], c.d);
    const Sign side = tritri::side_of_plane(f, t[0], t[1], t[2], c.d);
    ++cases[kind];
    decided[kind] += cert.has_value();
    zeros[kind] += exact == Sign::Zero;
    if (c.must_decide) {
      ++must[kind];
      must_decided[kind] += cert.has_value();
    }
    bool bad = (cert && *cert != exact) || side != exact;
    if (!safe_triangle(t)) bad |= cert.has_value() || !(f.err == std::numeric_limits<double>::infinity());
    if (kind == kOutOfRange) bad |= safe_triangle(t);
    if (i % 32 == 0) {  // the reference itself, against GMP
      namespace o = tritri_test;
      ++oracle_checked;
      bad |= o::orient3d(o::exact(t[0]), o::exact(t[1]), o::exact(t[2]), o::exact(c.d)) != tritri::to_int(exact);
    }
    if (bad && ++failures <= 10)
      ADD_FAILURE() << kKindNames[kind] << " case " << i << ": orient3d " << tritri::to_int(exact) << ", certified "
                    << (cert ? tritri::to_int(*cert) : 99) << ", side_of_plane " << tritri::to_int(side) << ", err "
                    << f.err << "\n  " << describe(t, c.d);
  }
  EXPECT_EQ(failures, 0);
  std::printf("%-18s %9s %9s %9s %12s\n", "plane sides", "cases", "decided", "zeros", "must/decided");
  for (int k = 0; k < kKinds; ++k)
    std::printf("%-18s %9lld %9lld %9lld %6lld/%lld\n", kKindNames[k], cases[k], decided[k], zeros[k], must[k],
                must_decided[k]);
  std::printf("reference orient3d checked against GMP: %lld\n", oracle_checked);
  // Useful: nearly every well-conditioned random case, and every sliver with its point well off.
  EXPECT_GT(must[kRandom], cases[kRandom] / 10);
  EXPECT_GT(must_decided[kRandom], 0.99 * must[kRandom]);
  EXPECT_GT(must[kSliverOff], cases[kSliverOff] * 9 / 10);
  EXPECT_EQ(must_decided[kSliverOff], must[kSliverOff]);
  // The exact zeros are really there (so undecided-on-the-plane is exercised), and nothing
  // out of range is ever decided.
  EXPECT_GT(zeros[kOnPlane], cases[kOnPlane] / 3);
  EXPECT_GT(zeros[kNearPlane], 0);
  EXPECT_EQ(decided[kOutOfRange], 0);
}

// ---------------------------------------------------------------------------------------
// 2. PlaneCachedKernel inside classify.

using P = tritri::DoubleKernel::Point;

// PlaneCachedKernel, counting the orient3d calls that hit a registered triangle.
class ProbeKernel : public tritri::PlaneCachedKernel {
 public:
  ProbeKernel(const P* const (&a)[3], const tritri::PlaneFilter& fa, const P* const (&b)[3],
              const tritri::PlaneFilter& fb, long long& hits)
      : PlaneCachedKernel(a, fa, b, fb), tri_{{a[0], a[1], a[2]}, {b[0], b[1], b[2]}}, hits_(&hits) {}
  Sign orient3d(const P& a, const P& b, const P& c, const P& d) const {
    for (const auto& t : tri_) *hits_ += &a == t[0] && &b == t[1] && &c == t[2];
    return PlaneCachedKernel::orient3d(a, b, c, d);
  }
  // Deleted, so that classify's plane-side signs come through orient3d above, counted.
  void orient3d_each(const P&, const P&, const P&, const P&, const P&, const P&, Sign (&)[3]) const = delete;

 private:
  const P* tri_[2][3];
  long long* hits_;
};

// Two slivers (or a sliver and a triangle) crossing near each other.
Pair sliver_pair(Rng& rng) {
  const Frame f = random_frame(rng);
  const double width = std::pow(10.0, -rng.uniform(3, 15)), len = 1 + uniform01(rng);
  const Triangle s = local_sliver(rng, f, width, len);
  Pair p;
  p.a = s;
  for (Point& v : p.b)
    v = add(add(add(s[0], (-0.2 + 1.4 * uniform01(rng)) * len, f.e1), 10 * width * rng.symmetric_unit(), f.e2),
            rng.symmetric_unit() * std::pow(10.0, -rng.uniform(0, 12)), f.e3);
  const Placement pl = random_placement(rng, 3);
  for (Triangle* t : {&p.a, &p.b})
    for (Point& v : *t) v = pl.at(v);
  return p;
}

TEST(PlaneCachedKernel, ClassifiesExactlyAsDoubleKernel) {
  Rng rng(seed_for(0xcace));
  const long long n = scaled_count(300'000);
  long long hits = 0, classify_hits = 0, failures = 0, intersecting = 0;
  for (long long i = 0; i < n; ++i) {
    const Pair p = rng.percent(25)
                       ? sliver_pair(rng)
                       : tritri_test::random_symmetry(
                             tritri_test::pair_generators()[tritri_test::pick_generator(rng)].make(rng), rng);
    const P* const pa[3] = {&p.a[0], &p.a[1], &p.a[2]};
    const P* const pb[3] = {&p.b[0], &p.b[1], &p.b[2]};
    const tritri::PlaneFilter fa = tritri::plane_filter(p.a[0], p.a[1], p.a[2]);
    const tritri::PlaneFilter fb = tritri::plane_filter(p.b[0], p.b[1], p.b[2]);
    const tritri::Result expected =
        tritri::classify<tritri::DoubleKernel>(p.a[0], p.a[1], p.a[2], p.b[0], p.b[1], p.b[2]);
    const ProbeKernel k(pa, fa, pb, fb, hits);
    const ProbeKernel swapped(pb, fb, pa, fa, hits);  // registration order does not matter
    const long long hits_before = hits;  // count only classify's calls below
    const tritri::Result got = tritri::classify(k, p.a[0], p.a[1], p.a[2], p.b[0], p.b[1], p.b[2]);
    const tritri::Result got_swapped = tritri::classify(swapped, p.a[0], p.a[1], p.a[2], p.b[0], p.b[1], p.b[2]);
    classify_hits += hits - hits_before;
    const tritri::PlaneCachedKernel plain(pa, fa, pb, fb);  // as the pipeline runs it: with orient3d_each
    intersecting += expected.intersects();
    bool bad = !(got == expected) || !(got_swapped == expected) ||
               !(tritri::classify(plain, p.a[0], p.a[1], p.a[2], p.b[0], p.b[1], p.b[2]) == expected);
    Sign e[2][3];  // orient3d_each, registered and not (rotated)
    plain.orient3d_each(p.a[0], p.a[1], p.a[2], p.b[0], p.b[1], p.b[2], e[0]);
    plain.orient3d_each(p.a[1], p.a[2], p.a[0], p.b[0], p.b[1], p.b[2], e[1]);
    for (int j = 0; j < 3; ++j)
      bad |= e[0][j] != tritri::orient3d(p.a[0], p.a[1], p.a[2], p.b[j]) ||
             e[1][j] != tritri::orient3d(p.a[1], p.a[2], p.a[0], p.b[j]);
    // Direct calls: registered (cached) and not registered (a rotated order, a copy).
    const Point copy = p.a[0];
    for (const Point& x : {p.b[0], p.b[1], p.b[2], p.a[0]}) {
      bad |= k.orient3d(p.a[0], p.a[1], p.a[2], x) != tritri::orient3d(p.a[0], p.a[1], p.a[2], x);
      bad |= k.orient3d(p.a[1], p.a[2], p.a[0], x) != tritri::orient3d(p.a[1], p.a[2], p.a[0], x);
      bad |= k.orient3d(copy, p.a[1], p.a[2], x) != tritri::orient3d(copy, p.a[1], p.a[2], x);
    }
    if (bad && ++failures <= 10)
      ADD_FAILURE() << "pair " << i << ": expected " << expected << "\n  got " << got << "\n  swapped " << got_swapped
                    << "\n" << tritri_test::describe(p);
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GE(classify_hits, 6 * n);  // B's corners against the cached plane(A), in both classify calls per pair
  std::printf("cached-plane classify: %lld pairs, %lld intersecting, %lld orient3d through a cached plane\n", n,
              intersecting, hits);
}

// ---------------------------------------------------------------------------------------
// 3. The early-outs of shared_vertices.h against classify.

struct Neighbours {
  Triangle a, b;
  Ids ia, ib;
  bool by_position;  // indices from positions (else from the construction: equal points may differ)
};

// Integer corners in {0..hi}^3: free, all in one plane, or b touching a's plane from one
// side; b shares 0, 1 or 2 of a's corners; then an integer linear map, 2^k and a
// translation, each kept when exact.
Neighbours make_neighbours(Rng& rng) {
  const int hi = rng.percent(50) ? 3 : 4;
  const int mode = rng.uniform(0, 99) < 40 ? 0 : (rng.percent(40) ? 1 : 2);  // free, flat, touching
  const int side = rng.percent(50) ? 1 : -1;
  std::array<Point, 6> q;
  for (Point& v : q) {
    v = tritri_test::grid_point(rng, 0, hi);
    if (mode == 1) v[2] = 0;
  }
  if (mode == 2) {
    for (int v = 0; v < 3; ++v) q[v][2] = 0;
    for (int v = 3; v < 6; ++v) q[v][2] = rng.percent(40) ? 0 : side * rng.uniform(1, hi);
  }
  int source[6] = {0, 1, 2, 3, 4, 5};  // construction index of each point
  for (int s = rng.uniform(0, 2), taken = 0; taken < s;) {
    const int i = rng.uniform(0, 2), j = rng.uniform(3, 5);
    if (source[j] != j) continue;
    bool used = false;
    for (int m = 3; m < 6; ++m) used |= source[m] == i;
    if (used) continue;
    source[j] = i;
    q[j] = q[i];
    ++taken;
  }
  // An integer linear map with nonzero determinant (exact, keeps every incidence).
  if (rng.percent(60)) {
    for (;;) {
      int m[3][3];
      for (auto& r : m)
        for (int& x : r) x = rng.uniform(-2, 2);
      const int det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                      m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                      m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
      if (det == 0) continue;
      for (Point& v : q) {
        const Point w = v;
        for (int r = 0; r < 3; ++r) v[r] = m[r][0] * w[0] + m[r][1] * w[1] + m[r][2] * w[2];
      }
      break;
    }
  } else {
    const int perm = rng.uniform(0, 5), flips = rng.uniform(0, 7);
    for (Point& v : q) v = tritri_test::permute_axes(v, perm, flips);
  }
  Pair p{{q[0], q[1], q[2]}, {q[3], q[4], q[5]}}, s;
  static constexpr int kScales[] = {-1060, -1000, -600, -300, 300, 600, 1000};
  const int k = rng.percent(40) ? 0 : (rng.percent(50) ? kScales[rng.uniform(0, 6)] : rng.uniform(-60, 60));
  if (tritri_test::scale_by_power_of_two(p, k, s)) p = s;
  if (rng.percent(50)) {
    const double off = kOffsets[rng.uniform(0, 8)];
    const Point d = rng.percent(50) ? Point{off, -off, off * 0.5}
                                    : Point{std::ldexp(rng.uniform(-1 << 20, 1 << 20), k),
                                            std::ldexp(rng.uniform(-1 << 20, 1 << 20), k + 10), 0};
    if (tritri_test::translate_exactly(p, d, s)) p = s;
  }
  Neighbours nb;
  nb.a = p.a;
  nb.b = p.b;
  nb.by_position = rng.percent(85);
  const std::array<Point, 6> all = {p.a[0], p.a[1], p.a[2], p.b[0], p.b[1], p.b[2]};
  int id[6];
  for (int v = 0; v < 6; ++v) {
    id[v] = source[v];
    if (nb.by_position)
      for (int w = 0; w < v; ++w)
        if (all[w] == all[v]) {
          id[v] = id[w];
          break;
        }
  }
  nb.ia = {id[0], id[1], id[2]};
  nb.ib = {id[3], id[4], id[5]};
  return nb;
}

bool proper(const Triangle& t) { return tritri::projection(tritri::DoubleKernel{}, t[0], t[1], t[2]).second != 0; }

// No point, or only VA_ON_VB points at vertex pairs shared by index.
bool only_shared(const tritri::Result& r, const Ids& ia, const Ids& ib) {
  for (const auto& p : r.points)
    if (p.type != tritri::Type::VA_ON_VB || ia[p.id0] != ib[p.id1]) return false;
  return true;
}

std::string describe(const Neighbours& nb, const tritri::Result& r) {
  std::ostringstream os;
  os << "A = " << to_hex(nb.a) << " ia = {" << nb.ia[0] << ", " << nb.ia[1] << ", " << nb.ia[2]
     << "}\n  B = " << to_hex(nb.b) << " ib = {" << nb.ib[0] << ", " << nb.ib[1] << ", " << nb.ib[2]
     << "}\n  classify: " << r;
  return os.str();
}

enum EarlyOut { kMeet, kSeparated, kProjectionMeet, kProjectionSeparated, kTouches, kEarlyOuts };
constexpr const char* kEarlyOutNames[kEarlyOuts] = {"meet_only_in_shared", "separated_by_plane",
                                                    "meet_in_shared_in_projection", "separated_in_projection",
                                                    "touches_only_in_shared"};

TEST(SharedVertexEarlyOuts, AnswerTrueOnlyWhenClassifyReportsNothingButSharedVertices) {
  Rng rng(seed_for(0x5eed));
  const tritri::DoubleKernel k;
  const long long n = scaled_count(1'000'000);
  long long asked[kEarlyOuts] = {}, fired[kEarlyOuts] = {}, coincident_pairs = 0, touches_projected = 0;
  long long checked = 0, coplanar = 0, failures = 0, unsound_pairs = 0;
  long long shared_count[3] = {};
  auto check = [&](EarlyOut e, bool answer, bool sound, const Neighbours& nb, const tritri::Result& r) {
    ++asked[e];
    if (!answer) return;
    ++fired[e];
    if (!sound && ++failures <= 10) ADD_FAILURE() << kEarlyOutNames[e] << " answered true:\n  " << describe(nb, r);
  };
  for (long long i = 0; i < n; ++i) {
    const Neighbours nb = make_neighbours(rng);
    const Triangle &a = nb.a, &b = nb.b;
    Sign sa[3], sb[3];
    for (int c = 0; c < 3; ++c) {
      sb[c] = tritri::orient3d(a[0], a[1], a[2], b[c]);
      sa[c] = tritri::orient3d(b[0], b[1], b[2], a[c]);
    }
    // A repeated index (degenerate; ia = {0, 1, 2}, ib = {0, 0, 5} once read b[3]): false.
    if (tritri::detail::repeats_an_index(nb.ia) || tritri::detail::repeats_an_index(nb.ib)) {
      ASSERT_FALSE(tritri::meet_only_in_shared(k, a, nb.ia, b, nb.ib) ||
                   tritri::meet_in_shared_in_projection(k, a, nb.ia, b, nb.ib));
      ASSERT_FALSE(tritri::touches_only_in_shared(k, a, nb.ia, b, nb.ib, sb));
      continue;
    }
    // The by-sides form equals the kernel form (exact and cached-plane signs), each sign asked once.
    int calls[2][3] = {};
    const bool meet = tritri::meet_only_in_shared(k, a, nb.ia, b, nb.ib);
    const bool by_sides = tritri::meet_only_in_shared_by_sides(nb.ia, nb.ib, [&](int t, int c) {
      ++calls[t][c];
      return t == 0 ? sb[c] : sa[c];
    });
    const tritri::PlaneFilter fa = tritri::plane_filter(a[0], a[1], a[2]), fb = tritri::plane_filter(b[0], b[1], b[2]);
    const bool by_planes = tritri::meet_only_in_shared_by_sides(nb.ia, nb.ib, [&](int t, int c) {
      return t == 0 ? tritri::side_of_plane(fa, a[0], a[1], a[2], b[c])
                    : tritri::side_of_plane(fb, b[0], b[1], b[2], a[c]);
    });
    bool once = true;
    for (const auto& row : calls)
      for (int c : row) once &= c <= 1;
    if ((by_sides != meet || by_planes != meet || !once) && ++failures <= 10)
      ADD_FAILURE() << "by-sides form differs: kernel " << meet << ", exact sides " << by_sides << ", planes "
                    << by_planes << ", asked once " << once << "\n  " << describe(nb, tritri::Result{});
    if (!proper(a) || !proper(b)) continue;
    ++checked;
    const tritri::Result r = tritri::classify<tritri::DoubleKernel>(a[0], a[1], a[2], b[0], b[1], b[2]);
    const bool sound = !r.degenerate && only_shared(r, nb.ia, nb.ib), empty = !r.degenerate && r.points.empty();
    int shared = 0;
    for (int x : nb.ia)
      for (int y : nb.ib) shared += x == y;
    ++shared_count[std::min(shared, 2)];
    unsound_pairs += !sound;  // pairs where a wrong "true" would be caught
    bool coincident = false;  // equal points under different indices: they meet, nothing may answer true
    for (int x = 0; x < 3; ++x)
      for (int y = 0; y < 3; ++y) coincident |= a[x] == b[y] && nb.ia[x] != nb.ib[y];
    coincident_pairs += coincident;
    auto side = [&](int t, int c) { return t == 0 ? sb[c] : sa[c]; };
    check(kMeet, meet, sound, nb, r);
    check(kSeparated, tritri::separated_by_plane(side), empty, nb, r);
    coplanar += sb[0] == Sign::Zero && sb[1] == Sign::Zero && sb[2] == Sign::Zero;
    check(kProjectionMeet, tritri::meet_in_shared_in_projection(k, a, nb.ia, b, nb.ib), sound, nb, r);  // any pair
    check(kProjectionMeet, tritri::meet_in_shared_in_projection(k, b, nb.ib, a, nb.ia), sound, nb, r);
    check(kProjectionSeparated, tritri::separated_in_projection(k, a, b), empty, nb, r);  // any pair, coplanar or not
    check(kProjectionSeparated, tritri::separated_in_projection(k, b, a), empty, nb, r);
    // touches_only_in_shared, and how often it answers through the projection (its zero
    // corners not all shared), not just by index.
    auto touches = [&](const Triangle& t, const Ids& it, const Triangle& o, const Ids& io, const Sign(&so)[3]) {
      const bool answer = tritri::touches_only_in_shared(k, t, it, o, io, so);
      check(kTouches, answer, sound, nb, r);
      bool all_shared = true;
      for (int c = 0; c < 3; ++c)
        if (so[c] == Sign::Zero) all_shared &= io[c] == it[0] || io[c] == it[1] || io[c] == it[2];
      touches_projected += answer && !all_shared;
    };
    touches(a, nb.ia, b, nb.ib, sb);
    touches(b, nb.ib, a, nb.ia, sa);
  }
  EXPECT_EQ(failures, 0);
  std::printf("neighbour pairs: %lld generated, %lld proper (sharing 0/1/2: %lld/%lld/%lld), %lld coplanar\n", n,
              checked, shared_count[0], shared_count[1], shared_count[2], coplanar);
  for (int e = 0; e < kEarlyOuts; ++e)
    std::printf("  %-30s asked %9lld, true %9lld\n", kEarlyOutNames[e], asked[e], fired[e]);
  std::printf(
      "  pairs classify would refute: %lld; true through the projection (touches): %lld; pairs with "
      "equal points under different indices: %lld\n",
      unsound_pairs, touches_projected, coincident_pairs);
  // Each early-out really fires (the test would notice one becoming trivially false).
  EXPECT_GT(fired[kMeet], checked / 10);
  EXPECT_GT(fired[kSeparated], checked / 10);
  EXPECT_GT(fired[kProjectionMeet], coplanar / 20);
  EXPECT_GT(fired[kProjectionMeet], checked / 10);
  EXPECT_GT(fired[kProjectionSeparated], checked / 20);
  EXPECT_GT(fired[kTouches], checked / 50);
  EXPECT_GT(touches_projected, checked / 200);
  EXPECT_GT(coincident_pairs, checked / 100);
  EXPECT_GT(unsound_pairs, checked / 4);
}

}  // namespace
