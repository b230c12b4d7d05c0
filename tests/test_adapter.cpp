// The tritri adapter (arrangements/src/stages/3_classify_tritri.h): every tritri point type converted
// into the PairIntersection record. Hand-made pairs with dyadic coordinates check each
// record point (existing vertex or LPI key, locations) and each segment against points
// derived by hand; every LPI key is rebuilt with ImplicitPoint::try_lpi (negative plane ids
// meaning the auxiliary point of triangle -1 - id), must be defined and must equal the
// hand-derived point exactly. The native classifier must describe the same points and
// segments. Random small-integer pairs then check, with CGAL Epeck predicates on the exact
// coordinates, that every record point lies on the simplices its locations claim.
#include <gtest/gtest.h>

#include <tritri/tritri.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/auxiliary_point.h"
#include "stages/3_classify_native.h"
#include "stages/3_classify_tritri.h"
#include "support/exact_oracle.h"
#include "support/test_scale.h"

namespace {

using arrangements::Location;
using arrangements::PairIntersection;
using arrangements::PairPoint;
using arrangements::Tri;
using arrangements::Vec3;
using tritri::Type;

using tritri_test::exact;
using tritri_test::test_scale;
using EK = tritri_test::ExactKernel;
using EP = EK::Point_3;
using Exact = tritri_test::Q3;
using ExactSegment = std::pair<Exact, Exact>;

EP ep(const Exact& e) { return tritri_test::to_cgal<EK>(e); }
EP ep(const Vec3& v) { return tritri_test::to_cgal<EK>(v); }

std::string str(const Exact& e) { return tritri_test::to_string(e); }
std::string str(const Location& l) {
  const char* k[] = {"Outside", "Interior", "Edge", "Vertex"};
  return std::string(k[l.kind]) + "(" + std::to_string(l.id) + ")";
}

// The LPI of a record's key, rebuilt independently of the adapter.
std::optional<tritri::ImplicitPoint> lpi_of(const std::vector<Vec3>& V, const std::vector<Tri>& F,
                                            const arrangements::LpiKey& key) {
  std::array<Vec3, 5> c;
  for (int k = 0; k < 5; ++k) c[k] = key.v[k] >= 0 ? V[key.v[k]] : arrangements::auxiliary_point(V, F[-1 - key.v[k]]);
  return tritri::ImplicitPoint::try_lpi(c[0], c[1], c[2], c[3], c[4]);
}

// The exact point of a record point; fails the test (and returns nullopt) for an LPI that
// is undefined or a vertex id out of range.
std::optional<Exact> point_of(const std::vector<Vec3>& V, const std::vector<Tri>& F, const PairPoint& p) {
  if (p.vertex >= 0) {
    if (p.vertex >= static_cast<int>(V.size())) {
      ADD_FAILURE() << "vertex id " << p.vertex << " out of range";
      return std::nullopt;
    }
    return exact(V[p.vertex]);
  }
  for (int k = 0; k < 5; ++k)
    if (p.lpi.v[k] >= static_cast<int>(V.size()) || -1 - p.lpi.v[k] >= static_cast<int>(F.size())) {
      ADD_FAILURE() << "LPI key id " << p.lpi.v[k] << " out of range";
      return std::nullopt;
    }
  const auto q = lpi_of(V, F, p.lpi);
  if (!q) {
    ADD_FAILURE() << "undefined LPI, key (" << p.lpi.v[0] << ", " << p.lpi.v[1] << " | " << p.lpi.v[2] << ", "
                  << p.lpi.v[3] << ", " << p.lpi.v[4] << ")";
    return std::nullopt;
  }
  return exact(*q);
}

// What a record says, in exact terms: per point its coordinates, existing vertex id (or -1)
// and locations; segments as pairs of exact points.
struct Described {
  std::map<Exact, std::tuple<int, Location, Location>> points;
  std::set<ExactSegment> segments;
  bool coplanar = false;
  bool operator==(const Described&) const = default;
};

std::string str(const Described& d) {
  std::ostringstream os;
  os << "coplanar " << d.coplanar << "\n";
  for (const auto& [x, info] : d.points)
    os << "  point " << str(x) << " vertex " << std::get<0>(info) << " in A " << str(std::get<1>(info)) << " in B "
       << str(std::get<2>(info)) << "\n";
  for (const auto& s : d.segments) os << "  segment " << str(s.first) << " - " << str(s.second) << "\n";
  return os.str();
}

Described describe(const std::vector<Vec3>& V, const std::vector<Tri>& F, const PairIntersection& r) {
  Described d;
  d.coplanar = r.coplanar;
  std::vector<Exact> xs;
  for (const auto& p : r.points) {
    const auto x = point_of(V, F, p);
    if (!x) return d;
    EXPECT_TRUE(d.points.emplace(*x, std::tuple{p.vertex, p.in[0], p.in[1]}).second)
        << "two record points at " << str(*x);
    xs.push_back(*x);
  }
  for (const auto& s : r.segments) {
    if (s.p0 < 0 || s.p1 < 0 || s.p0 >= static_cast<int>(xs.size()) || s.p1 >= static_cast<int>(xs.size())) {
      ADD_FAILURE() << "segment index out of range";
      continue;
    }
    d.segments.insert(std::minmax(xs[s.p0], xs[s.p1]));
  }
  return d;
}

// ---------------------------------------------------------------------------------------
// Hand-made cases. A case is two triangles given by coordinates (equal coordinates become
// one vertex id, as after preprocessing) and the expected record, derived by hand.

struct ExpectedPoint {
  Exact x;
  Location in_a, in_b;  // an existing vertex iff one of them is a Vertex
};

struct Case {
  std::string name;
  std::array<Vec3, 3> a, b;
  std::vector<Type> types;  // tritri's point types, in its order (checks the case is what it says)
  bool coplanar = false;
  std::vector<ExpectedPoint> points;          // empty: the pair must be dropped
  std::vector<std::pair<int, int>> segments;  // indices into points
};

Location V(int i) { return {Location::Vertex, static_cast<std::int8_t>(i)}; }
Location E(int i) { return {Location::Edge, static_cast<std::int8_t>(i)}; }
const Location kFace{Location::Interior, -1};

Exact q(mpq_class x, mpq_class y, mpq_class z) { return {x, y, z}; }

Type mirror(Type t) {
  switch (t) {
    case Type::VA_ON_EB:
      return Type::VB_ON_EA;
    case Type::VB_ON_EA:
      return Type::VA_ON_EB;
    case Type::VA_ON_TB:
      return Type::VB_ON_TA;
    case Type::VB_ON_TA:
      return Type::VA_ON_TB;
    case Type::EA_CROSS_TB:
      return Type::EB_CROSS_TA;
    case Type::EB_CROSS_TA:
      return Type::EA_CROSS_TB;
    default:
      return t;
  }
}

// The same case with A and B exchanged.
Case swapped(const Case& c) {
  Case s = c;
  s.name += " (A and B exchanged)";
  std::swap(s.a, s.b);
  s.types.clear();
  for (Type t : c.types) s.types.push_back(mirror(t));
  for (auto& p : s.points) std::swap(p.in_a, p.in_b);
  return s;
}

// The same case mapped by the exact affine map (x, y, z) -> (x, y, z + x + 2y) (shear:
// keeps incidences, takes z = 0 to a tilted plane; exact for the small dyadics used).
Case sheared(const Case& c) {
  Case s = c;
  s.name += " (sheared)";
  for (auto* t : {&s.a, &s.b})
    for (Vec3& v : *t) v[2] = v[2] + v[0] + 2 * v[1];
  for (auto& p : s.points) p.x[2] = p.x[2] + p.x[0] + 2 * p.x[1];
  return s;
}

int vertex_id(std::vector<Vec3>& V, const Vec3& p) {
  for (std::size_t i = 0; i < V.size(); ++i)
    if (V[i] == p) return static_cast<int>(i);
  V.push_back(p);
  return static_cast<int>(V.size() - 1);
}

void check_case(const Case& c) {
  SCOPED_TRACE(c.name);
  // Triangle A is F[0], B is F[2], with an unrelated triangle between them (far away), so
  // that triangle ids and the auxiliary-point ids -1 - id are not all trivially 0 and 1.
  std::vector<Vec3> Vx;
  Tri a, b, far;
  for (int k = 0; k < 3; ++k) a[k] = vertex_id(Vx, c.a[k]);
  for (int k = 0; k < 3; ++k) far[k] = vertex_id(Vx, Vec3{100.0 + k, 100.0 + (k == 1), 100.0 + (k == 2)});
  for (int k = 0; k < 3; ++k) b[k] = vertex_id(Vx, c.b[k]);
  const std::vector<Tri> F = {a, far, b};

  const tritri::Result r = tritri::classify<tritri::DoubleKernel>(c.a[0], c.a[1], c.a[2], c.b[0], c.b[1], c.b[2]);
  std::vector<Type> types;
  for (const auto& p : r.points) types.push_back(p.type);
  ASSERT_EQ(types, c.types) << "the case does not exercise what it claims: " << r;
  ASSERT_EQ(r.coplanar, c.coplanar) << r;

  Described want;
  want.coplanar = c.coplanar;
  for (const auto& p : c.points) {
    int vertex = -1;
    if (p.in_a.kind == Location::Vertex)
      vertex = a[p.in_a.id];
    else if (p.in_b.kind == Location::Vertex)
      vertex = b[p.in_b.id];
    if (vertex >= 0) {
      ASSERT_EQ(exact(Vx[vertex]), p.x) << "expected point is not that vertex";
    }
    want.points.emplace(p.x, std::tuple{vertex, p.in_a, p.in_b});
  }
  for (const auto& [i, j] : c.segments) want.segments.insert(std::minmax(c.points[i].x, c.points[j].x));

  for (bool native : {false, true}) {
    SCOPED_TRACE(native ? "native" : "tritri adapter");
    PairIntersection rec;
    const bool hit = native ? arrangements::classify_pair_native(Vx, F, 0, 2, rec)
                            : arrangements::classify_pair_tritri(Vx, F, 0, 2, rec);
    ASSERT_EQ(hit, !c.points.empty());
    if (!hit) continue;
    EXPECT_EQ(rec.tri[0], 0);
    EXPECT_EQ(rec.tri[1], 2);
    EXPECT_EQ(rec.points.size(), c.points.size());
    EXPECT_EQ(rec.segments.size(), c.segments.size());
    const Described got = describe(Vx, F, rec);
    EXPECT_EQ(got, want) << "got:\n" << str(got) << "want:\n" << str(want);
    // New points never repeat an input vertex.
    for (const auto& p : rec.points)
      if (p.vertex < 0) {
        if (const auto x = point_of(Vx, F, p)) {
          for (const Vec3& v : Vx) EXPECT_NE(*x, exact(v)) << "an LPI at an input vertex";
        }
      }
  }
}

void check_all_variants(const Case& c) {
  check_case(c);
  check_case(swapped(c));
  check_case(sheared(c));
  check_case(swapped(sheared(c)));
}

// B in most cases: the right triangle with legs 2 in the plane z = 0.
const std::array<Vec3, 3> kFloor = {Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{0, 2, 0}};

TEST(Adapter, SharedVertexOrEdgeAloneIsNoIntersection) {
  // Non-coplanar, one shared vertex.
  check_all_variants(
      {"shared vertex", kFloor, {Vec3{0, 0, 0}, Vec3{0, 0, 1}, Vec3{-1, -1, 1}}, {Type::VA_ON_VB}, false, {}, {}});
  // Non-coplanar, one shared edge (two VA_ON_VB points).
  check_all_variants({"shared edge",
                      kFloor,
                      {Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{1, 0, 1}},
                      {Type::VA_ON_VB, Type::VA_ON_VB},
                      false,
                      {},
                      {}});
  // Coplanar neighbours across an edge (a flat region).
  check_all_variants({"coplanar shared edge",
                      kFloor,
                      {Vec3{2, 0, 0}, Vec3{2, 2, 0}, Vec3{0, 2, 0}},
                      {Type::VA_ON_VB, Type::VA_ON_VB},
                      true,
                      {},
                      {}});
  // Coplanar, touching at one shared vertex.
  check_all_variants({"coplanar shared vertex",
                      kFloor,
                      {Vec3{0, 0, 0}, Vec3{-1, 0, 0}, Vec3{0, -1, 0}},
                      {Type::VA_ON_VB},
                      true,
                      {},
                      {}});
}

TEST(Adapter, SharedVertexWithMoreContactIsRecordedAsThatVertex) {
  // B shares A's vertex 0 and its edge 1 pierces A's face: B's plane is x = y, which cuts A
  // along (0,0,0)-(1,1,0); B's edge 1 from (1/2,1/2,-1) to (1/2,1/2,1) meets z = 0 at
  // (1/2,1/2,0). The segment runs from the shared vertex to that LPI.
  check_all_variants({"shared vertex + edge through face",
                      kFloor,
                      {Vec3{0, 0, 0}, Vec3{0.5, 0.5, -1}, Vec3{0.5, 0.5, 1}},
                      {Type::VA_ON_VB, Type::EB_CROSS_TA},
                      false,
                      {{q(0, 0, 0), V(0), V(0)}, {q(mpq_class(1, 2), mpq_class(1, 2), 0), kFace, E(1)}},
                      {{0, 1}}});
  // Coplanar, sharing vertex 0, B a wedge from it: B's edge 0 (direction (3,1)) meets A's
  // edge 1 (x + y = 2) at (3/2, 1/2); B's edge 2 (direction (1,3)) at (1/2, 3/2).
  check_all_variants({"coplanar shared vertex + overlap",
                      kFloor,
                      {Vec3{0, 0, 0}, Vec3{3, 1, 0}, Vec3{1, 3, 0}},
                      {Type::VA_ON_VB, Type::EA_CROSS_EB, Type::EA_CROSS_EB},
                      true,
                      {{q(0, 0, 0), V(0), V(0)},
                       {q(mpq_class(3, 2), mpq_class(1, 2), 0), E(1), E(0)},
                       {q(mpq_class(1, 2), mpq_class(3, 2), 0), E(1), E(2)}},
                      {{0, 1}, {1, 2}, {2, 0}}});
}

TEST(Adapter, VertexOnEdgeRecordsTheVertexOnThatEdge) {
  // A in the plane x = 1: vertex 0 lies inside B's edge 0 (y = 0); A's edge 1 from
  // (1,1,1) to (1,1,-1) crosses z = 0 at (1,1,0), inside B's edge 1 (x + y = 2): a
  // non-coplanar edge-edge crossing. B cuts x = 1 along (1,0,0)-(1,1,0).
  check_all_variants({"vertex on edge + edge crosses edge",
                      {Vec3{1, 0, 0}, Vec3{1, 1, 1}, Vec3{1, 1, -1}},
                      kFloor,
                      {Type::VA_ON_EB, Type::EA_CROSS_EB},
                      false,
                      {{q(1, 0, 0), V(0), E(0)}, {q(1, 1, 0), E(1), E(1)}},
                      {{0, 1}}});
  // Only the vertex touches: A's other vertices are above z = 0.
  check_all_variants({"vertex on edge alone",
                      {Vec3{1, 0, 0}, Vec3{1, 1, 1}, Vec3{2, -1, 1}},
                      kFloor,
                      {Type::VA_ON_EB},
                      false,
                      {{q(1, 0, 0), V(0), E(0)}},
                      {}});
  // Coplanar: B's vertex 0 on A's edge 0 (y = 0), the rest of B below y = 0.
  check_all_variants({"coplanar vertex on edge alone",
                      kFloor,
                      {Vec3{1, 0, 0}, Vec3{2, -1, 0}, Vec3{0, -1, 0}},
                      {Type::VB_ON_EA},
                      true,
                      {{q(1, 0, 0), E(0), V(0)}},
                      {}});
}

TEST(Adapter, NonCoplanarEdgeCrossingWithAnEdgeInThePlaneIsWellDefined) {
  // A's edge 0 from (1,-1,0) to (1,1,0) lies in B's plane z = 0, so its line cannot define
  // the crossing with B's plane: it crosses B's edge 0 (y = 0) at (1,0,0) and ends at
  // (1,1,0) inside B's edge 1. A lies in the plane x = 1.
  check_all_variants({"edge in plane crosses edge",
                      {Vec3{1, -1, 0}, Vec3{1, 1, 0}, Vec3{1, 0, 1}},
                      kFloor,
                      {Type::VA_ON_EB, Type::EA_CROSS_EB},
                      false,
                      {{q(1, 1, 0), V(1), E(1)}, {q(1, 0, 0), E(0), E(0)}},
                      {{0, 1}}});
}

TEST(Adapter, VertexOnFaceRecordsTheVertexAsInterior) {
  // Only A's vertex 0 touches B, inside its face.
  check_all_variants({"vertex on face alone",
                      {Vec3{0.5, 0.5, 0}, Vec3{1, 3, 1}, Vec3{3, 1, 1}},
                      kFloor,
                      {Type::VA_ON_TB},
                      false,
                      {{q(mpq_class(1, 2), mpq_class(1, 2), 0), V(0), kFace}},
                      {}});
  // A's vertex 0 inside B's face and A's edge 1 from (1,1/4,1) to (1/4,1,-1) through B's
  // face at its midpoint (5/8, 5/8, 0).
  check_all_variants(
      {"vertex on face + edge through face",
       {Vec3{0.5, 0.5, 0}, Vec3{1, 0.25, 1}, Vec3{0.25, 1, -1}},
       kFloor,
       {Type::VA_ON_TB, Type::EA_CROSS_TB},
       false,
       {{q(mpq_class(1, 2), mpq_class(1, 2), 0), V(0), kFace}, {q(mpq_class(5, 8), mpq_class(5, 8), 0), E(1), kFace}},
       {{0, 1}}});
}

TEST(Adapter, EdgeThroughFaceIsAnLpi) {
  // A in the plane y = 1/2: its edge 0 (vertical through (1/4,1/2)) and its edge 2 from
  // (1,1/2,1) to (1/4,1/2,-1) (crossing z = 0 halfway, at x = 5/8) pierce B's face.
  check_all_variants(
      {"two edges through face",
       {Vec3{0.25, 0.5, -1}, Vec3{0.25, 0.5, 1}, Vec3{1, 0.5, 1}},
       kFloor,
       {Type::EA_CROSS_TB, Type::EA_CROSS_TB},
       false,
       {{q(mpq_class(1, 4), mpq_class(1, 2), 0), E(0), kFace}, {q(mpq_class(5, 8), mpq_class(1, 2), 0), E(2), kFace}},
       {{0, 1}}});
  // A = (-1,1/2,0) (3,1/2,1) (3,1/2,-1) in the plane y = 1/2 touches z = 0 along x in
  // [-1, 3] (its vertex 0 lies in B's plane, outside B); B = kFloor cuts y = 1/2 along x
  // in [0, 3/2]. Both ends of the overlap are where B's edges 1 (x + y = 2) and 2 (x = 0)
  // cross A's face, strictly inside it.
  check_all_variants({"two edges of B through A",
                      {Vec3{-1, 0.5, 0}, Vec3{3, 0.5, 1}, Vec3{3, 0.5, -1}},
                      kFloor,
                      {Type::EB_CROSS_TA, Type::EB_CROSS_TA},
                      false,
                      {{q(mpq_class(3, 2), mpq_class(1, 2), 0), kFace, E(1)}, {q(0, mpq_class(1, 2), 0), kFace, E(2)}},
                      {{0, 1}}});
}

TEST(Adapter, CoplanarEdgeCrossingIsAWellDefinedLpi) {
  // B = (1,-1) (1,3) (-1,1/2) in z = 0 over A = kFloor. The overlap is the pentagon
  //   A's vertex 0 (inside B),
  //   (1, 0)       B's edge 0 (x = 1) x A's edge 0 (y = 0),
  //   (1, 1)       B's edge 0 x A's edge 1 (x + y = 2),
  //   (1/9, 17/9)  B's edge 1 (y = 5x/4 + 7/4) x A's edge 1,
  //   (0, 7/4)     B's edge 1 x A's edge 2 (x = 0);
  // B's edge 2 (y = -1/4 - 3x/4) misses A.
  check_all_variants({"coplanar pentagon",
                      kFloor,
                      {Vec3{1, -1, 0}, Vec3{1, 3, 0}, Vec3{-1, 0.5, 0}},
                      {Type::VA_ON_TB, Type::EA_CROSS_EB, Type::EA_CROSS_EB, Type::EA_CROSS_EB, Type::EA_CROSS_EB},
                      true,
                      {{q(0, 0, 0), V(0), kFace},
                       {q(1, 0, 0), E(0), E(0)},
                       {q(1, 1, 0), E(1), E(0)},
                       {q(mpq_class(1, 9), mpq_class(17, 9), 0), E(1), E(1)},
                       {q(0, mpq_class(7, 4), 0), E(2), E(1)}},
                      {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 0}}});
  // Star of David: A = kFloor, B its point reflection through (2/3, 2/3): six crossings.
  // B = (4/3,4/3) (-2/3,4/3) (4/3,-2/3) is not dyadic; scale both by 3 instead:
  // A = (0,0) (6,0) (0,6), B = (4,4) (-2,4) (4,-2). Crossings: B's edge 0 (y = 4) with A's
  // edge 1 (x + y = 6) at (2,4) and with A's edge 2 (x = 0) at (0,4); B's edge 1 (from
  // (-2,4) to (4,-2), x + y = 2) with A's edge 2 at (0,2) and A's edge 0 (y = 0) at
  // (2,0); B's edge 2 (x = 4) with A's edge 0 at (4,0) and A's edge 1 at (4,2).
  check_all_variants({"coplanar hexagram",
                      {Vec3{0, 0, 0}, Vec3{6, 0, 0}, Vec3{0, 6, 0}},
                      {Vec3{4, 4, 0}, Vec3{-2, 4, 0}, Vec3{4, -2, 0}},
                      {Type::EA_CROSS_EB, Type::EA_CROSS_EB, Type::EA_CROSS_EB, Type::EA_CROSS_EB, Type::EA_CROSS_EB,
                       Type::EA_CROSS_EB},
                      true,
                      {{q(2, 4, 0), E(1), E(0)},
                       {q(0, 4, 0), E(2), E(0)},
                       {q(0, 2, 0), E(2), E(1)},
                       {q(2, 0, 0), E(0), E(1)},
                       {q(4, 0, 0), E(0), E(2)},
                       {q(4, 2, 0), E(1), E(2)}},
                      {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 0}}});
}

// Direct look at the coplanar key: the plane is B's crossing edge plus B's auxiliary point
// (a negative id naming triangle B), and its line is A's crossing edge.
TEST(Adapter, CoplanarCrossingKeyUsesTheOtherEdgeAndItsAuxiliaryPoint) {
  std::vector<Vec3> Vx = {{0, 0, 0}, {6, 0, 0}, {0, 6, 0}, {4, 4, 0}, {-2, 4, 0}, {4, -2, 0}};
  const std::vector<Tri> F = {{0, 1, 2}, {3, 4, 5}};
  PairIntersection rec;
  ASSERT_TRUE(arrangements::classify_pair_tritri(Vx, F, 0, 1, rec));
  ASSERT_EQ(rec.points.size(), 6u);
  for (const auto& p : rec.points) {
    ASSERT_EQ(p.vertex, -1);
    ASSERT_EQ(p.in[0].kind, Location::Edge);
    ASSERT_EQ(p.in[1].kind, Location::Edge);
    const int ea = p.in[0].id, eb = p.in[1].id;
    const auto want = arrangements::make_lpi_key(F[0][ea], F[0][(ea + 1) % 3], F[1][eb], F[1][(eb + 1) % 3], -2);
    EXPECT_EQ(p.lpi, want) << "A edge " << ea << ", B edge " << eb;
    // The plane through B's edge and the auxiliary point is transverse to z = 0.
    const Vec3 aux = arrangements::auxiliary_point(Vx, F[1]);
    EXPECT_NE(aux[2], 0.0);
    EXPECT_TRUE(lpi_of(Vx, F, p.lpi).has_value());
    // Control: the line of A's edge with the common plane (what an undefined construction
    // would use) gives no point, since the line lies in that plane.
    EXPECT_FALSE(
        tritri::ImplicitPoint::try_lpi(Vx[F[0][ea]], Vx[F[0][(ea + 1) % 3]], Vx[F[1][0]], Vx[F[1][1]], Vx[F[1][2]])
            .has_value())
        << "control: the LPI on B's own plane is undefined";
  }
}

// ---------------------------------------------------------------------------------------
// Random small-integer pairs.

bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) { return CGAL::collinear(ep(a), ep(b), ep(c)); }

// Does exact point x lie where location l claims, in triangle t (Epeck predicates)?
bool lies_at(const Exact& x, const Location& l, const std::array<Vec3, 3>& t) {
  const EP p = ep(x);
  const std::array<EP, 3> v = {ep(t[0]), ep(t[1]), ep(t[2])};
  switch (l.kind) {
    case Location::Vertex:
      return l.id >= 0 && l.id < 3 && p == v[l.id];
    case Location::Edge:
      return l.id >= 0 && l.id <= 2 && tritri_test::in_open_segment(p, v[l.id], v[(l.id + 1) % 3]);
    default:
      return tritri_test::in_open_face(p, v);
  }
}

struct RandomStats {
  long pairs = 0, hits = 0, new_points = 0, coplanar_crossings = 0, vertex_points = 0;
};

void check_random_pair(const std::array<Vec3, 6>& p, RandomStats& st) {
  if (collinear(p[0], p[1], p[2]) || collinear(p[3], p[4], p[5])) return;
  std::vector<Vec3> Vx;
  Tri a, b;
  for (int k = 0; k < 3; ++k) a[k] = vertex_id(Vx, p[k]);
  for (int k = 0; k < 3; ++k) b[k] = vertex_id(Vx, p[3 + k]);
  if (std::set<int>(a.begin(), a.end()) == std::set<int>(b.begin(), b.end())) return;  // duplicates
  const std::vector<Tri> F = {a, b};
  const std::array<Vec3, 3> ta = {p[0], p[1], p[2]}, tb = {p[3], p[4], p[5]};
  ++st.pairs;

  PairIntersection rt, rn;
  const bool ht = arrangements::classify_pair_tritri(Vx, F, 0, 1, rt);
  const bool hn = arrangements::classify_pair_native(Vx, F, 0, 1, rn);
  std::ostringstream pair;
  for (const auto& v : p) pair << "(" << v[0] << "," << v[1] << "," << v[2] << ") ";
  ASSERT_EQ(ht, hn) << pair.str();
  if (!ht) return;
  ++st.hits;
  for (const auto& q : rt.points) {
    const auto x = point_of(Vx, F, q);
    ASSERT_TRUE(x) << pair.str();
    EXPECT_TRUE(lies_at(*x, q.in[0], ta)) << pair.str() << " point " << str(*x) << " not at A " << str(q.in[0]);
    EXPECT_TRUE(lies_at(*x, q.in[1], tb)) << pair.str() << " point " << str(*x) << " not at B " << str(q.in[1]);
    const bool on_vertex = q.in[0].kind == Location::Vertex || q.in[1].kind == Location::Vertex;
    EXPECT_EQ(q.vertex >= 0, on_vertex) << pair.str();
    if (q.vertex >= 0) {
      ++st.vertex_points;
    } else {
      ++st.new_points;
      if (rt.coplanar) ++st.coplanar_crossings;
    }
  }
  // Segments lie in both closed triangles: their ends do (checked above) and they are
  // distinct points; the two classifiers describe the same points, locations and segments.
  const Described dt = describe(Vx, F, rt), dn = describe(Vx, F, rn);
  EXPECT_EQ(dt, dn) << pair.str() << "\ntritri:\n" << str(dt) << "native:\n" << str(dn);
  for (const auto& s : dt.segments) EXPECT_NE(s.first, s.second) << pair.str();
}

TEST(Adapter, RandomIntegerPairsGiveDefinedPointsOnTheirSimplices) {
  std::mt19937 rng(2024);
  const long n = std::max(1L, static_cast<long>(6000 * test_scale()));
  RandomStats st;
  for (int grid : {1, 2, 3}) {
    std::uniform_int_distribution<int> d(0, grid);
    for (long it = 0; it < n / 3; ++it) {
      std::array<Vec3, 6> p;
      for (auto& v : p)
        for (auto& c : v) c = d(rng);
      check_random_pair(p, st);
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
  std::printf("3d grid pairs: %ld classified, %ld intersecting, %ld new points, %ld vertex points\n", st.pairs, st.hits,
              st.new_points, st.vertex_points);
  EXPECT_GT(st.hits, st.pairs / 10);
  EXPECT_GT(st.new_points, 0);
}

TEST(Adapter, RandomCoplanarPairsGiveDefinedPointsOnTheirSimplices) {
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> d(-3, 3);
  const long n = std::max(1L, static_cast<long>(6000 * test_scale()));
  RandomStats st;
  for (long it = 0; it < n; ++it) {
    std::array<Vec3, 6> p;
    for (auto& v : p) {
      v = {double(d(rng)), double(d(rng)), 0.0};
      v[2] = 0.5 * v[0] - 0.25 * v[1] + 1;  // one exact tilted plane
    }
    if (it % 2) p[3] = p[it % 3];                          // a shared vertex
    if (it % 4 == 1) p[4] = p[(it / 4) % 3 == 0 ? 1 : 2];  // sometimes a shared edge
    check_random_pair(p, st);
    if (::testing::Test::HasFatalFailure()) return;
  }
  std::printf("coplanar pairs: %ld classified, %ld intersecting, %ld coplanar crossings, %ld vertex points\n", st.pairs,
              st.hits, st.coplanar_crossings, st.vertex_points);
  EXPECT_GT(st.hits, st.pairs / 10);
  EXPECT_GT(st.coplanar_crossings, 0);
}

}  // namespace
