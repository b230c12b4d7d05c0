// The native pair classifier (arrangements/src/stages/3_classify_native.h) against tritri::classify,
// an independent implementation: on every pair, the points (as pairs of locations in the
// two triangles), the segments and the coplanar flag must be equal, and a pair whose
// only contact is shared mesh vertices must be dropped.
#include <gtest/gtest.h>

#include <tritri/tritri.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <random>
#include <set>

#include "stages/3_classify_native.h"
#include "support/test_scale.h"

namespace {

using arrangements::Location;
using arrangements::PairIntersection;
using arrangements::Tri;
using arrangements::Vec3;
using tritri_test::test_scale;
using LocPair = std::pair<std::pair<int, int>, std::pair<int, int>>;  // ((kindA, idA), (kindB, idB))

LocPair locations_of(const tritri::IntersectionPoint& p) {
  using T = tritri::Type;
  const int V = Location::Vertex, E = Location::Edge, I = Location::Interior;
  switch (p.type) {
    case T::VA_ON_VB:
      return {{V, p.id0}, {V, p.id1}};
    case T::VA_ON_EB:
      return {{V, p.id0}, {E, p.id1}};
    case T::VB_ON_EA:
      return {{E, p.id1}, {V, p.id0}};
    case T::VA_ON_TB:
      return {{V, p.id0}, {I, -1}};
    case T::VB_ON_TA:
      return {{I, -1}, {V, p.id0}};
    case T::EA_CROSS_EB:
      return {{E, p.id0}, {E, p.id1}};
    case T::EA_CROSS_TB:
      return {{E, p.id0}, {I, -1}};
    default:
      return {{I, -1}, {E, p.id0}};
  }
}

LocPair locations_of(const arrangements::PairPoint& p) {
  return {{p.in[0].kind, p.in[0].id}, {p.in[1].kind, p.in[1].id}};
}

struct Summary {
  std::set<LocPair> points;
  std::set<std::pair<LocPair, LocPair>> segments;
  bool coplanar = false;
  bool operator==(const Summary&) const = default;
};

template <class Points, class Segments>
Summary summarize(const Points& pts, const Segments& segs, bool coplanar) {
  Summary s;
  s.coplanar = coplanar;
  std::vector<LocPair> locs;
  for (const auto& p : pts) locs.push_back(locations_of(p));
  s.points.insert(locs.begin(), locs.end());
  for (const auto& g : segs) s.segments.insert(std::minmax(locs[g.p0], locs[g.p1]));
  return s;
}

// Merges equal coordinates into one vertex id, as preprocessing does.
int vertex_id(std::vector<Vec3>& V, const Vec3& p) {
  for (std::size_t i = 0; i < V.size(); ++i)
    if (V[i] == p) return static_cast<int>(i);
  V.push_back(p);
  return static_cast<int>(V.size() - 1);
}

bool degenerate(const Vec3& a, const Vec3& b, const Vec3& c) {
  return tritri::projection(tritri::DoubleKernel{}, a, b, c).second == 0;
}

void check_pair(const Vec3 (&p)[6], long& compared, long& intersecting) {
  if (degenerate(p[0], p[1], p[2]) || degenerate(p[3], p[4], p[5])) return;
  std::vector<Vec3> V;
  Tri a, b;
  for (int k = 0; k < 3; ++k) a[k] = vertex_id(V, p[k]);
  for (int k = 0; k < 3; ++k) b[k] = vertex_id(V, p[3 + k]);
  std::vector<Tri> F = {a, b};
  if (std::set<int>(a.begin(), a.end()) == std::set<int>(b.begin(), b.end())) return;  // duplicates

  const tritri::Result r = tritri::classify<tritri::DoubleKernel>(p[0], p[1], p[2], p[3], p[4], p[5]);
  // Expected: tritri's points, unless they are all vertices shared by both triangles.
  bool only_shared = true;
  for (const auto& q : r.points) only_shared &= q.type == tritri::Type::VA_ON_VB;
  const bool expect_hit = r.intersects() && !only_shared;

  PairIntersection rec;
  const bool hit = arrangements::classify_pair_native(V, F, 0, 1, rec);
  ++compared;
  ASSERT_EQ(hit, expect_hit) << "pair " << r;
  if (!hit) return;
  ++intersecting;
  EXPECT_EQ(summarize(rec.points, rec.segments, rec.coplanar), summarize(r.points, r.segments, r.coplanar))
      << "tritri: " << r;
  // Point identities: vertices where a location is a vertex, new points otherwise.
  for (const auto& q : rec.points) {
    const bool on_vertex = q.in[0].kind == Location::Vertex || q.in[1].kind == Location::Vertex;
    EXPECT_EQ(q.vertex >= 0, on_vertex);
    if (q.in[0].kind == Location::Vertex) {
      EXPECT_EQ(q.vertex, a[q.in[0].id]);
    } else if (q.in[1].kind == Location::Vertex) {
      EXPECT_EQ(q.vertex, b[q.in[1].id]);
    }
  }
}

TEST(ClassifyNative, AgreesWithTritriOnIntegerGrids) {
  std::mt19937 rng(7);
  const long n = static_cast<long>(200000 * test_scale());
  long compared = 0, intersecting = 0;
  for (int grid : {1, 2, 3}) {
    std::uniform_int_distribution<int> d(0, grid);
    for (long it = 0; it < n / 3; ++it) {
      Vec3 p[6];
      for (auto& v : p)
        for (auto& c : v) c = d(rng);
      check_pair(p, compared, intersecting);
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
  EXPECT_GT(intersecting, compared / 10);
}

TEST(ClassifyNative, AgreesWithTritriOnCoplanarAndSharedVertexPairs) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> d(-3, 3);
  const long n = static_cast<long>(100000 * test_scale());
  long compared = 0, intersecting = 0;
  for (long it = 0; it < n; ++it) {
    Vec3 p[6];
    for (auto& v : p) {
      v = {double(d(rng)), double(d(rng)), 0.0};
      v[2] = 0.5 * v[0] - 0.25 * v[1];  // one exact plane
    }
    if (it % 2) p[3] = p[it % 3];                          // a shared vertex
    if (it % 4 == 1) p[4] = p[(it / 4) % 3 == 0 ? 1 : 2];  // sometimes a shared edge
    check_pair(p, compared, intersecting);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(intersecting, compared / 10);
}

TEST(ClassifyNative, AgreesWithTritriOnRandomPairs) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(0, 1);
  const long n = static_cast<long>(100000 * test_scale());
  long compared = 0, intersecting = 0;
  for (long it = 0; it < n; ++it) {
    Vec3 p[6];
    for (auto& v : p)
      for (auto& c : v) c = u(rng);
    if (it % 3 == 0) p[3] = p[0];
    check_pair(p, compared, intersecting);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(intersecting, 0);
}

}  // namespace
