// Hand-derived cases for tritri::classify: each expected Result below was worked out on
// paper from the coordinates (the reasoning is in the comments), never by running the code.
// Every case is checked with DoubleKernel and with CgalKernel over Epick, Epeck and
// Simple_cartesian<Gmpq>.
//
// Unless stated otherwise A = (0,0,0), (4,0,0), (0,4,0) in the plane z = 0:
//   edge 0 = A0A1 (y = 0), edge 1 = A1A2 (x + y = 4), edge 2 = A2A0 (x = 0).
#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <type_traits>

#include <tritri/tritri.h>

namespace {

using P = std::array<double, 3>;
using Tri = std::array<P, 3>;
using tritri::IntersectionPoint;
using tritri::Result;
using tritri::Segment;
using tritri::Type;

const Tri kA = {P{0, 0, 0}, P{4, 0, 0}, P{0, 4, 0}};

constexpr double kDenormMin = std::numeric_limits<double>::denorm_min();

Result expected(std::initializer_list<IntersectionPoint> points, std::initializer_list<Segment> segments,
                bool coplanar) {
  Result r;
  for (const auto& p : points) r.points.push_back(p);
  for (const auto& s : segments) r.segments.push_back(s);
  r.coplanar = coplanar;
  return r;
}

template <class K>
Result classify_with(const Tri& a, const Tri& b) {
  using KP = typename K::Point;
  auto pt = [](const P& v) {
    if constexpr (std::is_same_v<KP, P>) {
      return v;
    } else {
      return KP(v[0], v[1], v[2]);
    }
  };
  return tritri::classify<K>(pt(a[0]), pt(a[1]), pt(a[2]), pt(b[0]), pt(b[1]), pt(b[2]));
}

// Checks the expected Result with every backend.
void expect_classification(const Tri& a, const Tri& b, const Result& want) {
  EXPECT_EQ(classify_with<tritri::DoubleKernel>(a, b), want) << "DoubleKernel";
  EXPECT_EQ(classify_with<tritri::CgalKernel<CGAL::Epick>>(a, b), want) << "Epick";
  EXPECT_EQ(classify_with<tritri::CgalKernel<CGAL::Epeck>>(a, b), want) << "Epeck";
  EXPECT_EQ((classify_with<tritri::CgalKernel<CGAL::Simple_cartesian<CGAL::Gmpq>>>(a, b)), want)
      << "Simple_cartesian<Gmpq>";
}

const Result kNoIntersection = expected({}, {}, false);

// ---------------------------------------------------------------------------------------
// Each type alone.

TEST(ClassifyHand, VertexOnVertexAlone) {
  // B0 = A0; B1, B2 have z > 0, so B meets z = 0 only at B0.
  const Tri b = {P{0, 0, 0}, P{-1, -1, 1}, P{-1, -2, 3}};
  expect_classification(kA, b, expected({{Type::VA_ON_VB, 0, 0}}, {}, false));
}

TEST(ClassifyHand, VertexOfAOnEdgeOfBAlone) {
  // B lies in the plane x + y = 0; its edge 0 from (-1,1,0) to (1,-1,0) is B's only part in
  // z = 0 and meets A (x, y >= 0) only at A0, its midpoint. A1, A2 have x + y = 4 > 0.
  const Tri b = {P{-1, 1, 0}, P{1, -1, 0}, P{0, 0, 5}};
  expect_classification(kA, b, expected({{Type::VA_ON_EB, 0, 0}}, {}, false));
}

TEST(ClassifyHand, VertexOfBOnEdgeOfAAlone) {
  // B0 = (2,0,0) is the midpoint of A's edge 0; B1, B2 have z > 0.
  const Tri b = {P{2, 0, 0}, P{2, -1, 3}, P{3, 1, 2}};
  expect_classification(kA, b, expected({{Type::VB_ON_EA, 0, 0}}, {}, false));
}

TEST(ClassifyHand, VertexOfAInFaceOfBAlone) {
  // A' = (1,1,0) is strictly inside B = kA (x, y > 0, x + y < 4); its other vertices z > 0.
  const Tri a = {P{1, 1, 0}, P{1, 1, 3}, P{2, 0, 5}};
  expect_classification(a, kA, expected({{Type::VA_ON_TB, 0, -1}}, {}, false));
}

TEST(ClassifyHand, VertexOfBInFaceOfAAlone) {
  const Tri b = {P{1, 1, 0}, P{1, 1, 3}, P{2, 0, 5}};
  expect_classification(kA, b, expected({{Type::VB_ON_TA, 0, -1}}, {}, false));
}

TEST(ClassifyHand, EdgeCrossesEdgeAlone) {
  // B lies in x = 2. B meets z = 0 in the segment (2,0,0)-(2,-2,0) (edge 0 at its midpoint,
  // edge 1 at t = 1/2; edge 2 has z = 1). A meets x = 2 in (2,0,0)-(2,2,0). Common: (2,0,0),
  // inside A's open edge 0 and B's open edge 0.
  const Tri b = {P{2, 1, 1}, P{2, -1, -1}, P{2, -3, 1}};
  expect_classification(kA, b, expected({{Type::EA_CROSS_EB, 0, 0}}, {}, false));
}

TEST(ClassifyHand, EdgesOfACrossFaceOfBOnly) {
  // A' stands in y = 0 and dips below z = 0: its edges 0 and 2 cross z = 0 at (0.5,0,0) and
  // (-0.5,0,0) (both at t = 1/2), deep inside the big B. B meets y = 0 in x in [-5, 5].
  const Tri a = {P{0, 0, -1}, P{1, 0, 1}, P{-1, 0, 1}};
  const Tri b = {P{-10, -10, 0}, P{10, -10, 0}, P{0, 10, 0}};
  expect_classification(a, b, expected({{Type::EA_CROSS_TB, 0, -1}, {Type::EA_CROSS_TB, 2, -1}}, {{0, 1}}, false));
}

TEST(ClassifyHand, EdgesOfBCrossFaceOfAOnly) {
  // The previous case with A and B swapped.
  const Tri a = {P{-10, -10, 0}, P{10, -10, 0}, P{0, 10, 0}};
  const Tri b = {P{0, 0, -1}, P{1, 0, 1}, P{-1, 0, 1}};
  expect_classification(a, b, expected({{Type::EB_CROSS_TA, 0, -1}, {Type::EB_CROSS_TA, 2, -1}}, {{0, 1}}, false));
}

// ---------------------------------------------------------------------------------------
// Shared vertices and edges.

TEST(ClassifyHand, SharedVertexNonCoplanar) {
  // B1 = A1; B0, B2 have z > 0.
  const Tri b = {P{5, 1, 1}, P{4, 0, 0}, P{5, -1, 2}};
  expect_classification(kA, b, expected({{Type::VA_ON_VB, 1, 1}}, {}, false));
}

TEST(ClassifyHand, SharedVertexCoplanar) {
  // B is the reflection of A through the origin: only A0 = B0 is common.
  const Tri b = {P{0, 0, 0}, P{-4, 0, 0}, P{0, -4, 0}};
  expect_classification(kA, b, expected({{Type::VA_ON_VB, 0, 0}}, {}, true));
}

TEST(ClassifyHand, SharedEdgeNonCoplanar) {
  // B stands on A's edge 0 in the plane y = 0, with B2 above.
  const Tri b = {P{0, 0, 0}, P{4, 0, 0}, P{2, 0, 3}};
  expect_classification(kA, b, expected({{Type::VA_ON_VB, 0, 0}, {Type::VA_ON_VB, 1, 1}}, {{0, 1}}, false));
}

TEST(ClassifyHand, SharedEdgeReversedNonCoplanar) {
  // B0 = A1, B1 = A0, B2 above z = 0 and behind y = 0.
  const Tri b = {P{4, 0, 0}, P{0, 0, 0}, P{2, -3, 3}};
  expect_classification(kA, b, expected({{Type::VA_ON_VB, 0, 1}, {Type::VA_ON_VB, 1, 0}}, {{0, 1}}, false));
}

TEST(ClassifyHand, SharedEdgeCoplanarOppositeSides) {
  // As above but B2 in z = 0 on the other side of y = 0: the overlap is the edge.
  const Tri b = {P{4, 0, 0}, P{0, 0, 0}, P{2, -3, 0}};
  expect_classification(kA, b, expected({{Type::VA_ON_VB, 0, 1}, {Type::VA_ON_VB, 1, 0}}, {{0, 1}}, true));
}

TEST(ClassifyHand, SharedEdgeCoplanarSameSide) {
  // B2 = (1,1,0) is inside A, so B is inside A: corners A0 = B0, A1 = B1, B2.
  // Segments: (0,1) on A's edge 0, (0,2) on B's edge 2, (1,2) on B's edge 1.
  const Tri b = {P{0, 0, 0}, P{4, 0, 0}, P{1, 1, 0}};
  expect_classification(kA, b,
                        expected({{Type::VA_ON_VB, 0, 0}, {Type::VA_ON_VB, 1, 1}, {Type::VB_ON_TA, 2, -1}},
                                 {{0, 1}, {0, 2}, {1, 2}}, true));
}

// ---------------------------------------------------------------------------------------
// Coplanar polygons.

// Star of David: A = (0,0),(6,0),(3,6) and B = its mirror image y -> 4 - y.
// Lines: A0A1 y = 0, A1A2 y = 12 - 2x, A2A0 y = 2x; B0B1 y = 4, B1B2 y = 2x - 8,
// B2B0 y = 4 - 2x. Crossings (all inside both open edges):
//   p0 EA_CROSS_EB(0,1) = (4,0)   p1 EA_CROSS_EB(0,2) = (2,0)
//   p2 EA_CROSS_EB(1,0) = (4,4)   p3 EA_CROSS_EB(1,1) = (5,2)
//   p4 EA_CROSS_EB(2,0) = (2,4)   p5 EA_CROSS_EB(2,2) = (1,2)
// (A1A2 || B2B0, A2A0 || B1B2, A0A1 || B0B1.) No vertex is inside the other triangle.
// Hexagon p0 p3 p2 p4 p5 p1: segments (0,1) (0,3) (1,5) (2,3) (2,4) (4,5).
const Result kStarOfDavid = expected({{Type::EA_CROSS_EB, 0, 1},
                                      {Type::EA_CROSS_EB, 0, 2},
                                      {Type::EA_CROSS_EB, 1, 0},
                                      {Type::EA_CROSS_EB, 1, 1},
                                      {Type::EA_CROSS_EB, 2, 0},
                                      {Type::EA_CROSS_EB, 2, 2}},
                                     {{0, 1}, {0, 3}, {1, 5}, {2, 3}, {2, 4}, {4, 5}}, true);

TEST(ClassifyHand, StarOfDavidInAxisPlane) {
  const Tri a = {P{0, 0, 0}, P{6, 0, 0}, P{3, 6, 0}};
  const Tri b = {P{0, 4, 0}, P{6, 4, 0}, P{3, -2, 0}};
  expect_classification(a, b, kStarOfDavid);
}

TEST(ClassifyHand, StarOfDavidInTiltedPlane) {
  // The same figure lifted to the plane z = x + y (an affine map: same combinatorics).
  const Tri a = {P{0, 0, 0}, P{6, 0, 6}, P{3, 6, 9}};
  const Tri b = {P{0, 4, 4}, P{6, 4, 10}, P{3, -2, 1}};
  expect_classification(a, b, kStarOfDavid);
}

TEST(ClassifyHand, CoplanarPentagonWithVertexOnEdge) {
  // B = (2,-1),(2,2),(-1,2): B1 = (2,2) is on A's edge 1 (x + y = 4). A ∩ B is
  // {x, y >= 0, x <= 2, y <= 2, x + y >= 1} with corners
  //   p0 VB_ON_EA(1,1) = (2,2)      p1 EA_CROSS_EB(0,0) = (2,0)   [y = 0 with x = 2]
  //   p2 EA_CROSS_EB(0,2) = (1,0)   [y = 0 with x + y = 1]
  //   p3 EA_CROSS_EB(2,1) = (0,2)   [x = 0 with y = 2]
  //   p4 EA_CROSS_EB(2,2) = (0,1)   [x = 0 with x + y = 1]
  // Pentagon p2 p1 p0 p3 p4: segments (0,1) (0,3) (1,2) (2,4) (3,4).
  const Tri b = {P{2, -1, 0}, P{2, 2, 0}, P{-1, 2, 0}};
  expect_classification(kA, b,
                        expected({{Type::VB_ON_EA, 1, 1},
                                  {Type::EA_CROSS_EB, 0, 0},
                                  {Type::EA_CROSS_EB, 0, 2},
                                  {Type::EA_CROSS_EB, 2, 1},
                                  {Type::EA_CROSS_EB, 2, 2}},
                                 {{0, 1}, {0, 3}, {1, 2}, {2, 4}, {3, 4}}, true));
}

TEST(ClassifyHand, CoplanarBStrictlyInsideA) {
  const Tri b = {P{1, 1, 0}, P{2, 1, 0}, P{1, 2, 0}};  // x, y > 0 and x + y < 4
  expect_classification(kA, b,
                        expected({{Type::VB_ON_TA, 0, -1}, {Type::VB_ON_TA, 1, -1}, {Type::VB_ON_TA, 2, -1}},
                                 {{0, 1}, {0, 2}, {1, 2}}, true));
}

TEST(ClassifyHand, CoplanarAStrictlyInsideB) {
  const Tri a = {P{1, 1, 0}, P{2, 1, 0}, P{1, 2, 0}};
  expect_classification(a, kA,
                        expected({{Type::VA_ON_TB, 0, -1}, {Type::VA_ON_TB, 1, -1}, {Type::VA_ON_TB, 2, -1}},
                                 {{0, 1}, {0, 2}, {1, 2}}, true));
}

TEST(ClassifyHand, IdenticalTriangles) {
  expect_classification(kA, kA,
                        expected({{Type::VA_ON_VB, 0, 0}, {Type::VA_ON_VB, 1, 1}, {Type::VA_ON_VB, 2, 2}},
                                 {{0, 1}, {0, 2}, {1, 2}}, true));
}

TEST(ClassifyHand, IdenticalTrianglesRotatedOrder) {
  // B = (A1, A2, A0): A0 = B2, A1 = B0, A2 = B1.
  const Tri b = {kA[1], kA[2], kA[0]};
  expect_classification(kA, b,
                        expected({{Type::VA_ON_VB, 0, 2}, {Type::VA_ON_VB, 1, 0}, {Type::VA_ON_VB, 2, 1}},
                                 {{0, 1}, {0, 2}, {1, 2}}, true));
}

TEST(ClassifyHand, IdenticalTrianglesReversedOrder) {
  // B = (A0, A2, A1): A0 = B0, A1 = B2, A2 = B1.
  const Tri b = {kA[0], kA[2], kA[1]};
  expect_classification(kA, b,
                        expected({{Type::VA_ON_VB, 0, 0}, {Type::VA_ON_VB, 1, 2}, {Type::VA_ON_VB, 2, 1}},
                                 {{0, 1}, {0, 2}, {1, 2}}, true));
}

// ---------------------------------------------------------------------------------------
// Near misses one ulp away, next to the exact touching configuration.

TEST(ClassifyHand, VertexOneUlpOutsideEdgeMisses) {
  // B0 = (2, y, 0) with B1, B2 above z = 0: only B0 can touch A.
  auto b = [](double y) { return Tri{P{2, y, 0}, P{2, -1, 3}, P{3, 1, 2}}; };
  expect_classification(kA, b(-kDenormMin), kNoIntersection);                                // y < 0: outside
  expect_classification(kA, b(0), expected({{Type::VB_ON_EA, 0, 0}}, {}, false));            // on edge 0
  expect_classification(kA, b(kDenormMin), expected({{Type::VB_ON_TA, 0, -1}}, {}, false));  // inside
}

TEST(ClassifyHand, VertexOneUlpPastEndOfEdgeMisses) {
  // B0 = (x, 0, 0) near A1 = (4,0,0) on the line of A's edge 0; B1, B2 above z = 0.
  auto b = [](double x) { return Tri{P{x, 0, 0}, P{4, -1, 3}, P{5, 1, 2}}; };
  expect_classification(kA, b(std::nextafter(4.0, 5.0)), kNoIntersection);
  expect_classification(kA, b(4), expected({{Type::VA_ON_VB, 1, 0}}, {}, false));
  expect_classification(kA, b(std::nextafter(4.0, 3.0)), expected({{Type::VB_ON_EA, 0, 0}}, {}, false));
}

TEST(ClassifyHand, VertexOneUlpAboveFaceMisses) {
  // A' = (1,1,z), (1,1,3), (2,0,5) against B = kA in z = 0.
  auto a = [](double z) { return Tri{P{1, 1, z}, P{1, 1, 3}, P{2, 0, 5}}; };
  expect_classification(a(kDenormMin), kA, kNoIntersection);
  expect_classification(a(0), kA, expected({{Type::VA_ON_TB, 0, -1}}, {}, false));
  // z < 0: edge 0 (vertical) crosses z = 0 exactly at (1,1,0); edge 2 crosses it at
  // (2 - t, t, 0) with t = 5 / (5 - z) != 1, a different point, also inside B.
  expect_classification(a(-kDenormMin), kA,
                        expected({{Type::EA_CROSS_TB, 0, -1}, {Type::EA_CROSS_TB, 2, -1}}, {{0, 1}}, false));
}

TEST(ClassifyHand, EdgeOneUlpBesideEdgeMisses) {
  // B = (2,1,1), (2,-1,z), (2,-3,1) in the plane x = 2; z = -1 is EdgeCrossesEdgeAlone.
  auto b = [](double z) { return Tri{P{2, 1, 1}, P{2, -1, z}, P{2, -3, 1}}; };
  expect_classification(kA, b(-1), expected({{Type::EA_CROSS_EB, 0, 0}}, {}, false));
  // z = -1 + d: B's edge 0 crosses z = 0 at y = -d / (2 - d) < 0, edge 1 at y < -1:
  // B ∩ {z = 0} is outside A (y < 0).
  expect_classification(kA, b(std::nextafter(-1.0, 0.0)), kNoIntersection);
  // z = -1 - d: edge 0 crosses z = 0 at (2, e, 0), e = d / (2 + d) > 0, inside A's face;
  // B ∩ {z = 0} then runs down through (2,0,0), where A's edge 0 crosses B's face.
  expect_classification(kA, b(std::nextafter(-1.0, -2.0)),
                        expected({{Type::EA_CROSS_TB, 0, -1}, {Type::EB_CROSS_TA, 0, -1}}, {{0, 1}}, false));
}

TEST(ClassifyHand, CoplanarOneUlpApartMisses) {
  // B = (x,0,0), (-4,0,0), (x,-4,0): x = 0 touches A at A0 only.
  auto b = [](double x) { return Tri{P{x, 0, 0}, P{-4, 0, 0}, P{x, -4, 0}}; };
  expect_classification(kA, b(-kDenormMin), expected({}, {}, true));  // B in x < 0
  expect_classification(kA, b(0), expected({{Type::VA_ON_VB, 0, 0}}, {}, true));
  // x = d > 0: A ∩ B = the segment [0, d] of the x axis: A0 inside B's edge 0, B0 inside A's
  // edge 0.
  expect_classification(kA, b(kDenormMin), expected({{Type::VA_ON_EB, 0, 0}, {Type::VB_ON_EA, 0, 0}}, {{0, 1}}, true));
}

TEST(ClassifyHand, NearMissesAtHugeAndTinyScales) {
  // EdgeOneUlpBesideEdgeMisses scaled by 2^600 and 2^-600 (exact): the same answers.
  for (int k : {600, -600}) {
    auto s = [k](const Tri& t) {
      Tri r;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i][j] = std::ldexp(t[i][j], k);
      return r;
    };
    auto b = [](double z) { return Tri{P{2, 1, 1}, P{2, -1, z}, P{2, -3, 1}}; };
    expect_classification(s(kA), s(b(-1)), expected({{Type::EA_CROSS_EB, 0, 0}}, {}, false));
    expect_classification(s(kA), s(b(std::nextafter(-1.0, 0.0))), kNoIntersection);
    expect_classification(s(kA), s(b(std::nextafter(-1.0, -2.0))),
                          expected({{Type::EA_CROSS_TB, 0, -1}, {Type::EB_CROSS_TA, 0, -1}}, {{0, 1}}, false));
  }
}

TEST(ClassifyHand, SeparatedTrianglesDoNotIntersect) {
  const Tri b = {P{0, 0, 1}, P{4, 0, 1}, P{0, 4, 1}};  // A shifted up: parallel planes
  expect_classification(kA, b, kNoIntersection);
  const Tri c = {P{5, 5, -1}, P{5, 5, 1}, P{6, 4, 0}};  // crosses z = 0 beyond edge 1
  expect_classification(kA, c, kNoIntersection);
}

TEST(ClassifyHand, IntersectsAndPrinting) {
  const Result r = classify_with<tritri::DoubleKernel>(kA, {P{2, 0, 0}, P{2, -1, 3}, P{3, 1, 2}});
  EXPECT_TRUE(r.intersects());
  EXPECT_FALSE(kNoIntersection.intersects());
  std::ostringstream os;
  os << r;
  EXPECT_NE(os.str().find("VB_ON_EA(0,0)"), std::string::npos) << os.str();
}

}  // namespace
