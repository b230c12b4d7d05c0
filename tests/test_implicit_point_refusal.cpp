// tests/test_implicit_point_refusal.cpp
//
// Undefined and invalid implicit points (implicit_point.h): generated undefined LPIs (line
// parallel to the plane or in it, p == q, collinear plane triple) and TPIs (parallel or
// repeated planes, planes through one line or parallel to one direction, collinear
// triples), mapped by random exact transforms, are refused exactly: try_lpi / try_tpi
// give nothing and lpi / tpi throw std::domain_error, whether the arguments are arrays or
// explicit points (support/exact_oracle.h confirms they are undefined). Non-finite
// coordinates and implicit arguments throw std::invalid_argument.
// Counts scale with TRITRI_TEST_SCALE; TRITRI_TEST_SEED changes the seeds.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <initializer_list>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <tritri/tritri.h>

#include "support/implicit_recipes.h"
#include "support/pair_generators.h"
#include "support/test_scale.h"

namespace {

using tritri::ImplicitPoint;
using tritri_test::Point;
using tritri_test::Recipe;
using tritri_test::Rng;
using tritri_test::Triple;

constexpr int kMaxReports = 10;  // failures printed in full per test

// ---------------------------------------------------------------------------------------
// Undefined and invalid constructions.

// Inputs of one undefined LPI, mapped by a random exact transform.
struct LpiInputs {
  Point p, q, r, s, t;
  const char* why;
};

// A point of the integer grid [-4, 4]^3.
Point grid_point(Rng& rng) { return tritri_test::grid_point(rng, -4, 4); }
Point combo(const Point& o, const Point& u, double a, const Point& v, double b) {
  return {o[0] + a * u[0] + b * v[0], o[1] + a * u[1] + b * v[1], o[2] + a * u[2] + b * v[2]};
}

// Maps all points by t, or none of them if some image is not exact.
void map_all(const tritri_test::Transform& t, std::initializer_list<Point*> pts) {
  std::vector<Point> out;
  for (Point* p : pts) {
    Point q;
    if (!tritri_test::apply(t, *p, q)) return;
    out.push_back(q);
  }
  std::size_t i = 0;
  for (Point* p : pts) *p = out[i++];
}

template <class F>
void expect_refused(F make, const std::string& what, long long& failures) {
  bool threw_domain = false;
  try {
    (void)make(false);
  } catch (const std::domain_error&) {
    threw_domain = true;
  } catch (...) {
  }
  bool threw_domain_points = false;
  try {
    (void)make(true);
  } catch (const std::domain_error&) {
    threw_domain_points = true;
  } catch (...) {
  }
  if ((!threw_domain || !threw_domain_points) && ++failures <= kMaxReports)
    ADD_FAILURE() << "no std::domain_error for " << what;
}

TEST(ImplicitPoint, UndefinedLpiIsRefused) {
  Rng rng(tritri_test::seed_for(31));
  long long cases = 0, failures = 0;
  for (long long n = tritri_test::scaled_count(20000); n > 0; --n) {
    Point r = grid_point(rng), s = grid_point(rng), t = grid_point(rng);
    const Point u = tritri_test::sub(s, r), v = tritri_test::sub(t, r);
    if (tritri_test::is_zero(tritri_test::cross_d(u, v))) continue;
    LpiInputs in{grid_point(rng), {}, r, s, t, ""};
    const double a = rng.uniform(-2, 2), b = rng.uniform(-2, 2) + (a == 0 ? 1 : 0);
    switch (rng.uniform(0, 3)) {
      case 0:  // the line is parallel to the plane
        in.q = combo(in.p, u, a, v, b);
        in.why = "line parallel to the plane";
        break;
      case 1:  // the line lies in the plane
        in.p = combo(r, u, rng.uniform(-2, 2), v, rng.uniform(-2, 2));
        in.q = combo(in.p, u, a, v, b);
        in.why = "line in the plane";
        break;
      case 2:
        in.q = in.p;
        in.why = "p == q";
        break;
      default:  // collinear r, s, t
        in.q = grid_point(rng);
        in.t = combo(r, u, rng.uniform(-3, 3), v, 0);
        in.why = "collinear r, s, t";
        break;
    }
    const tritri_test::Transform tf = tritri_test::random_transform(rng, true);
    map_all(tf, {&in.p, &in.q, &in.r, &in.s, &in.t});
    const Recipe rec = tritri_test::lpi_recipe(in.p, in.q, {in.r, in.s, in.t});
    if (tritri_test::exact_point(rec)) {
      ADD_FAILURE() << "generator: defined " << tritri_test::describe(rec);
      continue;
    }
    ++cases;
    const std::string what = std::string(in.why) + ": " + tritri_test::describe(rec);
    if ((tritri_test::build(rec, false) || tritri_test::build(rec, true)) && ++failures <= kMaxReports)
      ADD_FAILURE() << "try_lpi built " << what;
    expect_refused(
        [&](bool as_points) {
          if (!as_points) return ImplicitPoint::lpi(in.p, in.q, in.r, in.s, in.t);
          auto e = [](const Point& x) { return ImplicitPoint::explicit_point(x); };
          return ImplicitPoint::lpi(e(in.p), e(in.q), e(in.r), e(in.s), e(in.t));
        },
        what, failures);
  }
  std::cout << "[ cases    ] " << cases << " undefined LPIs\n";
  EXPECT_EQ(failures, 0);
}

TEST(ImplicitPoint, UndefinedTpiIsRefused) {
  Rng rng(tritri_test::seed_for(32));
  long long cases = 0, failures = 0;
  auto plane = [&] {
    for (;;) {
      Triple t{grid_point(rng), grid_point(rng), grid_point(rng)};
      if (!tritri_test::is_zero(tritri_test::cross_d(tritri_test::sub(t[1], t[0]), tritri_test::sub(t[2], t[0]))))
        return t;
    }
  };
  for (long long n = tritri_test::scaled_count(20000); n > 0; --n) {
    std::array<Triple, 3> planes = {plane(), plane(), plane()};
    const char* why = "";
    switch (rng.uniform(0, 4)) {
      case 0: {  // two parallel planes
        const Point d = grid_point(rng);
        for (int i = 0; i < 3; ++i) planes[1][i] = combo(planes[0][i], d, 1, d, 0);
        planes[1] = tritri_test::reordered(planes[1], rng);
        why = "two parallel planes";
        break;
      }
      case 1:  // one plane twice
        planes[1] = tritri_test::reordered(planes[0], rng);
        why = "one plane twice";
        break;
      case 2: {  // three planes through one line
        const Point a = grid_point(rng), b = grid_point(rng);
        if (a == b) continue;
        for (Triple& t : planes) t = tritri_test::reordered({a, b, grid_point(rng)}, rng);
        why = "three planes through one line";
        break;
      }
      case 3: {  // three planes parallel to one direction (a prism)
        const Point d = grid_point(rng);
        if (tritri_test::is_zero(d)) continue;
        for (Triple& t : planes) {
          const Point x = grid_point(rng);
          t = tritri_test::reordered({x, combo(x, d, rng.uniform(1, 2), d, 0), grid_point(rng)}, rng);
        }
        why = "three planes parallel to one direction";
        break;
      }
      default: {  // a collinear triple
        const Point a = grid_point(rng), d = grid_point(rng);
        planes[0] = {a, combo(a, d, 1, d, 0), combo(a, d, -2, d, 0)};
        why = "a collinear triple";
        break;
      }
    }
    tritri_test::shuffle(planes.data(), 3, rng);
    const tritri_test::Transform tf = tritri_test::random_transform(rng, true);
    map_all(tf, {&planes[0][0], &planes[0][1], &planes[0][2], &planes[1][0], &planes[1][1], &planes[1][2],
                 &planes[2][0], &planes[2][1], &planes[2][2]});
    const Recipe rec = tritri_test::tpi_recipe(planes);
    if (tritri_test::exact_point(rec)) {
      ADD_FAILURE() << "generator: defined " << tritri_test::describe(rec);
      continue;
    }
    ++cases;
    const std::string what = std::string(why) + ": " + tritri_test::describe(rec);
    if ((tritri_test::build(rec, false) || tritri_test::build(rec, true)) && ++failures <= kMaxReports)
      ADD_FAILURE() << "try_tpi built " << what;
    expect_refused(
        [&](bool as_points) {
          const auto& v = rec.in;
          if (!as_points) return ImplicitPoint::tpi(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]);
          std::array<ImplicitPoint, 9> e;
          for (int i = 0; i < 9; ++i) e[i] = ImplicitPoint::explicit_point(v[i]);
          return ImplicitPoint::tpi(e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8]);
        },
        what, failures);
  }
  std::cout << "[ cases    ] " << cases << " undefined TPIs\n";
  EXPECT_EQ(failures, 0);
  EXPECT_GT(cases, tritri_test::scaled_count(20000) / 2);
}

TEST(ImplicitPoint, NonFiniteCoordinatesThrowInvalidArgument) {
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(), INFINITY, -INFINITY};
  const std::array<Point, 9> good = {Point{0, 0, 0}, Point{1, 2, 3}, Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1},
                                     Point{0, 0, 0}, Point{0, 1, 1}, Point{2, 0, 1}, Point{1, 1, 5}};
  for (double x : bad)
    for (int k = 0; k < 3; ++k) {
      Point p{0.5, 0.5, 0.5};
      p[k] = x;
      EXPECT_THROW(ImplicitPoint::explicit_point(p), std::invalid_argument);
      EXPECT_THROW(ImplicitPoint::explicit_point(p[0], p[1], p[2]), std::invalid_argument);
      for (int pos = 0; pos < 9; ++pos) {
        std::array<Point, 9> v = good;
        v[pos] = p;
        if (pos < 5) {
          EXPECT_THROW(ImplicitPoint::lpi(v[0], v[1], v[2], v[3], v[4]), std::invalid_argument) << "position " << pos;
          EXPECT_THROW(ImplicitPoint::try_lpi(v[0], v[1], v[2], v[3], v[4]), std::invalid_argument)
              << "position " << pos;
        }
        EXPECT_THROW(ImplicitPoint::tpi(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]), std::invalid_argument)
            << "position " << pos;
        EXPECT_THROW(ImplicitPoint::try_tpi(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]),
                     std::invalid_argument)
            << "position " << pos;
      }
    }
  // The good inputs themselves are fine (so the throws above come from the bad value).
  EXPECT_TRUE(ImplicitPoint::try_lpi(good[0], good[1], good[2], good[3], good[4]).has_value());
  EXPECT_TRUE(ImplicitPoint::try_tpi(good[0], good[1], good[2], good[3], good[4], good[5], good[6], good[7], good[8])
                  .has_value());
}

TEST(ImplicitPoint, ImplicitArgumentsThrowInvalidArgument) {
  const std::array<Point, 9> good = {Point{0, 0, 0}, Point{1, 2, 3}, Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1},
                                     Point{0, 0, 0}, Point{0, 1, 1}, Point{2, 0, 1}, Point{1, 1, 5}};
  std::array<ImplicitPoint, 9> e;
  for (int i = 0; i < 9; ++i) e[i] = ImplicitPoint::explicit_point(good[i]);
  const ImplicitPoint lpi = ImplicitPoint::lpi(e[0], e[1], e[2], e[3], e[4]);
  const ImplicitPoint tpi = ImplicitPoint::tpi(e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8]);
  for (const ImplicitPoint& x : {lpi, tpi})
    for (int pos = 0; pos < 9; ++pos) {
      std::array<ImplicitPoint, 9> v = e;
      v[pos] = x;
      if (pos < 5) {
        EXPECT_THROW(ImplicitPoint::lpi(v[0], v[1], v[2], v[3], v[4]), std::invalid_argument) << "position " << pos;
        EXPECT_THROW(ImplicitPoint::try_lpi(v[0], v[1], v[2], v[3], v[4]), std::invalid_argument) << "position " << pos;
      }
      EXPECT_THROW(ImplicitPoint::tpi(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]), std::invalid_argument)
          << "position " << pos;
      EXPECT_THROW(ImplicitPoint::try_tpi(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]), std::invalid_argument)
          << "position " << pos;
    }
}

}  // namespace
