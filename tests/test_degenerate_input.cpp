// Degenerate input: a triangle with repeated or collinear vertices.
//
// Specification (classify.h): when the degenerate triangle is not strictly on one side of
// the other triangle's plane (it touches the other triangle, lies in its plane, or crosses
// it), the result has degenerate == true and no points; when it is strictly on one side,
// the result has no points (the flag may be either). Checked in both argument positions,
// under all 48 axis permutations / sign flips, and with every backend.
//
// T = (0,0,0), (4,0,0), (0,4,0) in the plane z = 0 is the non-degenerate partner.
#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <array>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

#include <tritri/tritri.h>

#include "support/pair_generators.h"
#include "support/test_scale.h"

namespace {

using tritri::Result;
using tritri_test::Pair;
using tritri_test::Point;
using tritri_test::Triangle;

const Triangle kT = {Point{0, 0, 0}, Point{4, 0, 0}, Point{0, 4, 0}};

template <class K>
Result classify_with(const Pair& p) {
  using KP = typename K::Point;
  auto pt = [](const Point& v) {
    if constexpr (std::is_same_v<KP, Point>) {
      return v;
    } else {
      return KP(v[0], v[1], v[2]);
    }
  };
  return tritri::classify<K>(pt(p.a[0]), pt(p.a[1]), pt(p.a[2]), pt(p.b[0]), pt(p.b[1]), pt(p.b[2]));
}

enum class Expect { Flagged, EmptyEitherFlag };

// The result for `pair` must have no points and no segments, must not be coplanar, and
// must be flagged degenerate when `expect` says so; with every backend.
void check_result(const Pair& pair, Expect expect, const std::string& where) {
  const Result results[] = {
      classify_with<tritri::DoubleKernel>(pair),
      classify_with<tritri::CgalKernel<CGAL::Epick>>(pair),
      classify_with<tritri::CgalKernel<CGAL::Epeck>>(pair),
      classify_with<tritri::CgalKernel<CGAL::Simple_cartesian<CGAL::Gmpq>>>(pair),
  };
  const char* backends[] = {"DoubleKernel", "Epick", "Epeck", "Simple_cartesian<Gmpq>"};
  for (int i = 0; i < 4; ++i) {
    const Result& r = results[i];
    const bool ok =
        r.points.empty() && r.segments.empty() && !r.coplanar && (expect == Expect::EmptyEitherFlag || r.degenerate);
    EXPECT_TRUE(ok) << where << " [" << backends[i] << "]: got " << r << "\n" << tritri_test::describe(pair);
  }
}

// Checks the degenerate triangle d against t in both positions and under every axis
// permutation and sign flip.
void check_degenerate(const Triangle& d, const Triangle& t, Expect expect) {
  for (int perm = 0; perm < 6; ++perm)
    for (int flips = 0; flips < 8; ++flips) {
      const Pair p = tritri_test::permute_axes(Pair{d, t}, perm, flips);
      const std::string where = "perm " + std::to_string(perm) + " flips " + std::to_string(flips);
      check_result(p, expect, where + ", degenerate triangle as A");
      check_result(tritri_test::swapped(p), expect, where + ", degenerate triangle as B");
    }
}

// The three placements of a repeated vertex: (p,p,q), (p,q,p), (q,p,p).
std::vector<Triangle> repeated_vertex_triangles(const Point& p, const Point& q) {
  return {{p, p, q}, {p, q, p}, {q, p, p}};
}

// The six orders of three collinear points.
std::vector<Triangle> orders(const Point& x, const Point& y, const Point& z) {
  return {{x, y, z}, {x, z, y}, {y, x, z}, {y, z, x}, {z, x, y}, {z, y, x}};
}

// ---------------------------------------------------------------------------------------
// All three vertices equal (a point).

TEST(DegenerateInput, PointTriangleTouchingIsFlagged) {
  for (const Point& p : {Point{1, 1, 0}, Point{0, 0, 0}, Point{2, 0, 0}, Point{2, 2, 0}})
    check_degenerate({p, p, p}, kT, Expect::Flagged);  // in the face, at a vertex, on edges
}

TEST(DegenerateInput, PointTriangleInPlaneOutsideIsFlagged) {
  check_degenerate({Point{5, 5, 0}, Point{5, 5, 0}, Point{5, 5, 0}}, kT, Expect::Flagged);
  check_degenerate({Point{-1, 0, 0}, Point{-1, 0, 0}, Point{-1, 0, 0}}, kT, Expect::Flagged);
}

TEST(DegenerateInput, PointTriangleOffThePlaneIsEmpty) {
  check_degenerate({Point{1, 1, 1}, Point{1, 1, 1}, Point{1, 1, 1}}, kT, Expect::EmptyEitherFlag);
  const double tiny = std::nextafter(0.0, 1.0);
  check_degenerate({Point{1, 1, -tiny}, Point{1, 1, -tiny}, Point{1, 1, -tiny}}, kT, Expect::EmptyEitherFlag);
}

// ---------------------------------------------------------------------------------------
// Two equal vertices (a segment).

TEST(DegenerateInput, RepeatedVertexSegmentPiercingFaceIsFlagged) {
  for (const Triangle& d : repeated_vertex_triangles({1, 1, -1}, {1, 1, 1})) check_degenerate(d, kT, Expect::Flagged);
}

TEST(DegenerateInput, RepeatedVertexSegmentTouchingVertexOrEdgeIsFlagged) {
  for (const Triangle& d : repeated_vertex_triangles({0, 0, 0}, {1, 1, 1})) check_degenerate(d, kT, Expect::Flagged);
  for (const Triangle& d : repeated_vertex_triangles({2, 0, 0}, {-1, 3, 5})) check_degenerate(d, kT, Expect::Flagged);
}

TEST(DegenerateInput, RepeatedVertexSegmentInPlaneIsFlagged) {
  for (const Triangle& d : repeated_vertex_triangles({-1, 1, 0}, {5, 1, 0})) check_degenerate(d, kT, Expect::Flagged);
  for (const Triangle& d : repeated_vertex_triangles({5, 0, 0}, {7, 0, 0}))  // edge 0's line, outside
    check_degenerate(d, kT, Expect::Flagged);
}

TEST(DegenerateInput, RepeatedVertexSegmentCrossingPlaneOutsideIsFlagged) {
  for (const Triangle& d : repeated_vertex_triangles({5, 5, -1}, {5, 5, 1})) check_degenerate(d, kT, Expect::Flagged);
}

TEST(DegenerateInput, RepeatedVertexSegmentOffThePlaneIsEmpty) {
  for (const Triangle& d : repeated_vertex_triangles({1, 1, 1}, {2, 2, 3}))
    check_degenerate(d, kT, Expect::EmptyEitherFlag);
  for (const Triangle& d : repeated_vertex_triangles({-3, 1, -2}, {1, 1, -0.5}))
    check_degenerate(d, kT, Expect::EmptyEitherFlag);
}

// ---------------------------------------------------------------------------------------
// Three distinct collinear vertices.

TEST(DegenerateInput, CollinearThroughFaceIsFlagged) {
  for (const Triangle& d : orders({1, 1, -1}, {1, 1, 0}, {1, 1, 1})) check_degenerate(d, kT, Expect::Flagged);
  // (0,0,-1) + 1/4 ((4,4,3) - (0,0,-1)) = (1,1,0): the middle vertex is in the face.
  for (const Triangle& d : orders({0, 0, -1}, {1, 1, 0}, {4, 4, 3})) check_degenerate(d, kT, Expect::Flagged);
  // No vertex in the plane: the segment crosses the face at (1,1,0).
  for (const Triangle& d : orders({0, 0, -1}, {2, 2, 1}, {3, 3, 2})) check_degenerate(d, kT, Expect::Flagged);
}

TEST(DegenerateInput, CollinearInPlaneIsFlagged) {
  for (const Triangle& d : orders({-1, 2, 0}, {1, 2, 0}, {3, 2, 0})) check_degenerate(d, kT, Expect::Flagged);
  for (const Triangle& d : orders({5, 0, 0}, {6, 0, 0}, {7, 0, 0})) check_degenerate(d, kT, Expect::Flagged);
  for (const Triangle& d : orders({0, 0, 0}, {2, 0, 0}, {4, 0, 0}))  // exactly T's edge 0
    check_degenerate(d, kT, Expect::Flagged);
}

TEST(DegenerateInput, CollinearCrossingPlaneOutsideIsFlagged) {
  for (const Triangle& d : orders({5, 5, -1}, {6, 6, 0}, {7, 7, 1})) check_degenerate(d, kT, Expect::Flagged);
  for (const Triangle& d : orders({5, 5, -2}, {6, 6, -1}, {8, 8, 1})) check_degenerate(d, kT, Expect::Flagged);
}

TEST(DegenerateInput, CollinearOffThePlaneIsEmpty) {
  for (const Triangle& d : orders({0, 0, 1}, {1, 1, 2}, {2, 2, 3})) check_degenerate(d, kT, Expect::EmptyEitherFlag);
  for (const Triangle& d : orders({1, 1, -0x1p-60}, {1, 1, -1}, {1, 1, -2}))
    check_degenerate(d, kT, Expect::EmptyEitherFlag);
}

TEST(DegenerateInput, CollinearAtExtremeScalesIsFlagged) {
  for (int k : {-1000, -500, 500, 1000}) {
    Pair p;
    ASSERT_TRUE(tritri_test::scale_by_power_of_two(Pair{{Point{1, 1, -1}, Point{1, 1, 0}, Point{1, 1, 1}}, kT}, k, p));
    check_degenerate(p.a, p.b, Expect::Flagged);
  }
}

// ---------------------------------------------------------------------------------------
// Both triangles degenerate: the other triangle has no plane to be on one side of.

TEST(DegenerateInput, BothDegenerateIsFlaggedWithoutPoints) {
  const Triangle point = {Point{1, 1, 0}, Point{1, 1, 0}, Point{1, 1, 0}};
  const Triangle segment = {Point{0, 0, 0}, Point{1, 1, 0}, Point{2, 2, 0}};
  const Triangle far = {Point{5, 5, 5}, Point{5, 5, 5}, Point{6, 7, 8}};
  check_degenerate(point, segment, Expect::Flagged);
  check_degenerate(segment, segment, Expect::Flagged);
  check_degenerate(point, far, Expect::Flagged);
}

// ---------------------------------------------------------------------------------------
// Nearly degenerate but valid: one ulp away from collinear is a real triangle.

TEST(DegenerateInput, SliverOneUlpFromCollinearIsClassified) {
  // S = (1,1,-1), (1,1,1), (x,1,0) in the plane y = 1. For x = 1 it is collinear. For
  // x = 1 + ulp, S meets z = 0 in the segment from (1,1,0) (its edge 0 crossing T's face)
  // to S2 = (x,1,0) (inside T's face).
  const Triangle degenerate = {Point{1, 1, -1}, Point{1, 1, 1}, Point{1, 1, 0}};
  check_degenerate(degenerate, kT, Expect::Flagged);

  const Triangle sliver = {Point{1, 1, -1}, Point{1, 1, 1}, Point{std::nextafter(1.0, 2.0), 1, 0}};
  Result want;
  want.points.push_back({tritri::Type::VB_ON_TA, 2, -1});
  want.points.push_back({tritri::Type::EB_CROSS_TA, 0, -1});
  want.segments.push_back({0, 1});
  EXPECT_EQ(classify_with<tritri::DoubleKernel>(Pair{kT, sliver}), want);
  EXPECT_EQ(classify_with<tritri::CgalKernel<CGAL::Epeck>>(Pair{kT, sliver}), want);
}

// Generated degenerate triangles (collinear grid points, repeated vertices) against
// generated partners: never a point, and flagged whenever they touch the partner's plane.
TEST(DegenerateInput, GeneratedDegenerateTrianglesFollowTheSpecification) {
  tritri_test::Rng rng(2024);
  const long long n = tritri_test::scaled_count(20'000);
  long long flagged = 0;
  for (long long i = 0; i < n; ++i) {
    // Degenerate d: points x + s*v for integer s (collinear), sometimes repeated.
    const Point x = tritri_test::grid_point(rng, -3, 3);
    Point v = tritri_test::grid_point(rng, -2, 2);
    if (rng.percent(10)) v = {0, 0, 0};
    Triangle d;
    for (Point& q : d) q = tritri_test::add(x, tritri_test::mul(rng.uniform(-2, 2), v));
    Triangle t = tritri_test::grid_triangle(rng, -3, 3);
    // t must be non-degenerate; plane signs decide the expectation.
    const tritri_test::Point e1 = tritri_test::sub(t[1], t[0]), e2 = tritri_test::sub(t[2], t[0]);
    const Point n3 = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    if (n3[0] == 0 && n3[1] == 0 && n3[2] == 0) continue;
    int pos = 0, neg = 0;
    for (const Point& q : d) {
      const Point w = tritri_test::sub(q, t[0]);
      const double s = n3[0] * w[0] + n3[1] * w[1] + n3[2] * w[2];  // exact: small integers
      pos += s > 0;
      neg += s < 0;
    }
    const bool one_side = pos == 3 || neg == 3;
    flagged += !one_side;
    const Pair p = tritri_test::random_symmetry(Pair{d, t}, rng);
    const Result r = classify_with<tritri::DoubleKernel>(p);
    const bool ok = r.points.empty() && r.segments.empty() && !r.coplanar && (one_side || r.degenerate);
    if (!ok) {
      ADD_FAILURE() << "got " << r << "\n" << tritri_test::describe(p);
      break;
    }
  }
  if (n >= 1000) {
    EXPECT_GT(flagged, n / 4);
  }
}

}  // namespace
