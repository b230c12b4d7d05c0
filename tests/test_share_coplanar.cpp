// share_coplanar (stages/4_share_coplanar.h), the step of the intersection graph where
// coplanar partners share their points and segments, against a brute force written here
// from the step's definition. For every triangle t with coplanar partners, every id a
// partner lists (its corners and segment ends; its points inside and on its edges, the
// "points") is located in closed t with integer line equations on the id's exact rational
// coordinates (nothing of the library's predicates); a point inside t or strictly inside
// an edge of t is added there, and a partner's segment with both ends in closed t (its
// interior, open edges or t's own corners) is added to t's segments, all from the lists
// as they were before (the semantics of the brute force that the step replaced).
// The graph before the step comes from build_intersection_graph(..., share = false); the
// result must equal the reference list by list, and the pipeline's graph (step inside).
// Inputs: coplanar scenes that make the fast path's binary searches and segment look-up
// work (fans of long thin triangles, fans, sheets, three stacked layers) and its
// degenerate cases (collinear overlapping edges, T-junctions, shared corners, touching,
// nesting, near-common points), with triangles crossing the plane, each placed in five
// planes, scaled by 2^k and moved (all exact in doubles; support/coplanar_scenes.h);
// DoubleModel, and ExactModel on the smaller scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <iterator>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "arrangements/as_input.h"
#include "models/exact_model.h"
#include "stages/1_preprocess.h"
#include "stages/2_candidate_pairs.h"
#include "stages/3_classify_pairs.h"
#include "stages/4_intersection_graph.h"
#include "stages/4_share_coplanar.h"
#include "support/coplanar_scenes.h"
#include "support/exact_oracle.h"
#include "support/test_scale.h"

namespace {

using namespace arrangements;
using namespace tritri_test::coplanar;

// The crossing triangles' corners: uniform in [-2.5, 2.5]^2, y drawn before x (the order
// in which g++ evaluated the arguments when the scenes were written).
P2 crossing_corner(std::mt19937_64& rng) {
  const double y = -2.5 + 5 * unit(rng);
  return {-2.5 + 5 * unit(rng), y};
}

// 10 thin wedges whose edges nearly meet in two points (write_wedges).
Builder wedges() {
  Builder b;
  const int n = 10;
  for (int i = 0; i < n; ++i) {
    const double y = -1 + 2 * (i + 0.5) / n, d = 0.5 / n;
    b.triangle({-1, y}, {1, -y + d}, {1, -y - d});
  }
  return b;
}

std::vector<Scene> scenes() {
  SceneList list{std::mt19937_64(tritri_test::seed_for(4417)), crossing_corner, {}};
  for (int n : {10, 30, 60})
    if (n < 60 || !tritri_test::scaled_down()) list.add("strips n=" + std::to_string(n), strips(n), n == 60);
  list.add("fans, own apexes", fans(false, Apex::kFirst));
  list.add("fans, shared apex", fans(true, Apex::kFirst));
  list.add("sheets", two_sheets({0.37 * 0.75, 0.21 * 0.75}), true);
  list.add("three layers", three_sheets(), true);
  list.add("collinear edges, touching", contacts(false));
  list.add("T-junctions", t_junctions(), true);
  Builder corners = shared_corners();
  corners.triangle({-2, -2}, {-1, -2}, {-1, -1});  // identical to a triangle of the first grid
  list.add("shared corners", std::move(corners));
  list.add("nested", nested());
  list.add("wedges", wedges());
  for (int s = 0; s < 2; ++s) list.add("lattice " + std::to_string(s), lattice(list.rng, false), true);
  return std::move(list.scenes);
}

// z = 0 first, then every plane at every scale, moved or not in turn; large scenes (and
// all in the sanitizer runs) one scale per plane.
std::vector<Placement> placements(std::size_t scene, bool large) {
  std::vector<Placement> out = {{0, 0, false}};
  if (tritri_test::scaled_down() && large) return out;
  const int ks[3] = {-60, 0, 40};
  for (int plane = 0; plane < 5; ++plane)
    for (int i = 0; i < 3; ++i) {
      const std::size_t turn = static_cast<std::size_t>(plane + i) + scene;
      if ((large || tritri_test::scaled_down()) && static_cast<std::size_t>(i) != (plane + scene) % 3) continue;
      if (plane == 0 && ks[i] == 0 && turn % 2 == 0) continue;  // the first one
      out.push_back({plane, ks[i], turn % 2 == 1});
    }
  return out;
}

// ---------------------------------------------------------------------------------------
// The reference.

// Closed triangle (A, B, C) in exact integers: in the projection dropping the axis of the
// normal's largest component, side k of a point X is the sign of edge line k at X,
// positive inside (orient2d of edge k = (corner k, corner k + 1) and X, times the
// triangle's orientation).
struct ExactTriangle {
  static constexpr int kOutside = -1, kCorner = 4, kInterior = 3;  // else: strictly inside edge k
  Projection pr;
  EdgeLines lines;

  ExactTriangle(const Q3& A, const Q3& B, const Q3& C) : pr(projection_of(A, B, C)), lines(edge_lines(A, B, C, pr)) {}

  int locate(const ZPoint& x) const {
    int zeros = 0, zero = -1;
    for (int k = 0; k < 3; ++k) {
      const int s = sgn(lines.at(k, x, pr));
      if (s < 0) return kOutside;
      if (s == 0) ++zeros, zero = k;
    }
    return zeros == 0 ? kInterior : zeros == 1 ? zero : kCorner;
  }
};

template <class T>
void sort_unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

template <class Point>
void reference_share(const std::vector<Tri>& F, BasicIntersectionGraph<Point>& g) {
  std::vector<Q3> q;
  std::vector<ZPoint> z;
  for (const Point& p : g.points) {
    q.push_back(tritri_test::exact(p));
    z.push_back(tritri_test::common_denominator(q.back()));
  }
  std::vector<std::vector<int>> inside(F.size());
  std::vector<std::array<int, 2>> on_edge;  // (edge, point)
  std::vector<std::vector<std::array<int, 2>>> segments(F.size());
  std::vector<int> stamp(g.points.size(), -1), where(g.points.size());
  std::vector<char> is_point(g.points.size());
  std::vector<int> ids;
  for (std::size_t t = 0; t < F.size(); ++t) {
    const auto& partners = g.coplanar_partners[t];
    if (partners.empty()) continue;
    const ExactTriangle tri(q[F[t][0]], q[F[t][1]], q[F[t][2]]);
    ids.clear();
    auto visit = [&](int x, bool point) {
      if (stamp[x] != static_cast<int>(t)) {
        stamp[x] = static_cast<int>(t);
        is_point[x] = 0;
        ids.push_back(x);
      }
      if (point) is_point[x] = 1;
    };
    for (int u : partners) {
      for (int k = 0; k < 3; ++k) {
        // The location is in t's plane: a partner must lie in it.
        EXPECT_EQ(tritri_test::orient3d(z[F[t][0]], z[F[t][1]], z[F[t][2]], z[F[u][k]]), 0) << t << ", " << u;
        visit(F[u][k], false);
      }
      for (int x : g.triangle_points[u]) visit(x, true);
      for (int k = 0; k < 3; ++k)
        for (int x : g.edge_points[g.triangle_edges[u][k]]) visit(x, true);
      for (const auto& s : g.triangle_segments[u]) visit(s[0], false), visit(s[1], false);
    }
    for (int k = 0; k < 3; ++k) {  // edge k of t runs from corner k to corner k + 1
      const auto& e = g.edges[g.triangle_edges[t][k]];
      EXPECT_EQ(e, (std::array<int, 2>{std::min(F[t][k], F[t][(k + 1) % 3]), std::max(F[t][k], F[t][(k + 1) % 3])}));
    }
    for (int x : ids) {
      // At a corner of t: in closed t when it is that corner (for the segments; t's
      // corners are not points to add); another id there would be a duplicate point.
      where[x] = tri.locate(z[x]);
      if (where[x] == ExactTriangle::kCorner) {
        EXPECT_TRUE(x == F[t][0] || x == F[t][1] || x == F[t][2]) << "point " << x << " at a corner of " << t;
        if (x != F[t][0] && x != F[t][1] && x != F[t][2]) where[x] = ExactTriangle::kOutside;
      }
      if (!is_point[x]) continue;
      if (where[x] == ExactTriangle::kInterior) inside[t].push_back(x);
      else if (where[x] >= 0 && where[x] < 3) on_edge.push_back({g.triangle_edges[t][where[x]], x});
    }
    for (int u : partners)
      for (const auto& s : g.triangle_segments[u])
        if (where[s[0]] != ExactTriangle::kOutside && where[s[1]] != ExactTriangle::kOutside)
          segments[t].push_back(s);
  }
  for (std::size_t t = 0; t < F.size(); ++t) {
    g.triangle_points[t].insert(g.triangle_points[t].end(), inside[t].begin(), inside[t].end());
    sort_unique(g.triangle_points[t]);
    g.triangle_segments[t].insert(g.triangle_segments[t].end(), segments[t].begin(), segments[t].end());
    sort_unique(g.triangle_segments[t]);
  }
  for (const auto& [e, x] : on_edge) g.edge_points[e].push_back(x);
  for (auto& list : g.edge_points) sort_unique(list);
}

// ---------------------------------------------------------------------------------------
// Comparison.

std::string str(int x) { return std::to_string(x); }
std::string str(const std::array<int, 2>& s) { return "(" + std::to_string(s[0]) + ", " + std::to_string(s[1]) + ")"; }

// Lists equal index by index; the first difference is reported with its index, both sizes
// and one entry that only one side has.
template <class T, class Label>
void same_lists(const std::vector<std::vector<T>>& got, const std::vector<std::vector<T>>& want, const char* name,
                const Label& label, const std::string& what) {
  if (got.size() != want.size()) {
    ADD_FAILURE() << what << ": " << got.size() << " " << name << " lists, expected " << want.size();
    return;
  }
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (got[i] == want[i]) continue;
    std::vector<T> extra, missing;
    std::set_difference(got[i].begin(), got[i].end(), want[i].begin(), want[i].end(), std::back_inserter(extra));
    std::set_difference(want[i].begin(), want[i].end(), got[i].begin(), got[i].end(), std::back_inserter(missing));
    ADD_FAILURE() << what << ": " << name << "[" << i << "]" << label(i) << " has " << got[i].size()
                  << " entries, expected " << want[i].size()
                  << (extra.empty() ? "" : "; extra " + str(extra[0]))
                  << (missing.empty() ? "" : "; missing " + str(missing[0]))
                  << (extra.empty() && missing.empty() ? "; not sorted and unique" : "");
    return;
  }
}

template <class Point>
void expect_same_graph(const BasicIntersectionGraph<Point>& got, const BasicIntersectionGraph<Point>& want,
                       const std::string& what) {
  auto none = [](std::size_t) { return std::string(); };
  auto edge = [&](std::size_t e) { return " (edge " + str(want.edges[e]) + ")"; };
  same_lists(got.triangle_points, want.triangle_points, "triangle_points", none, what);
  same_lists(got.edge_points, want.edge_points, "edge_points", edge, what);
  same_lists(got.triangle_segments, want.triangle_segments, "triangle_segments", none, what);
  EXPECT_EQ(got.points.size(), want.points.size()) << what;
  EXPECT_EQ(got.coplanar_partners, want.coplanar_partners) << what;
}

struct Counts {
  std::size_t coplanar_pairs = 0, inside = 0, on_edge = 0, segments = 0;
  std::size_t added() const { return inside + on_edge + segments; }
};

std::string str(const Counts& c) {
  return std::to_string(c.coplanar_pairs) + " coplanar pairs, added " + std::to_string(c.inside) + " inside, " +
         std::to_string(c.on_edge) + " on edges, " + std::to_string(c.segments) + " segments";
}

template <class Point>
std::size_t total(const std::vector<std::vector<Point>>& lists) {
  std::size_t n = 0;
  for (const auto& l : lists) n += l.size();
  return n;
}

// The step against the reference and against the pipeline's graph; the additions counted.
template <class M>
Counts check_share(const std::vector<typename M::Vertex>& V, const std::vector<Tri>& F, const PairRecords& records,
                   const std::string& what) {
  const auto before = build_intersection_graph<M>(V, F, records, false);
  auto got = before;
  share_coplanar<M>(V, F, got);
  auto want = before;
  reference_share(F, want);
  expect_same_graph(got, want, what + ": share_coplanar against the reference");
  expect_same_graph(got, build_intersection_graph<M>(V, F, records), what + ": share_coplanar against the pipeline");
  return {before.coplanar_pairs, total(want.triangle_points) - total(before.triangle_points),
          total(want.edge_points) - total(before.edge_points),
          total(want.triangle_segments) - total(before.triangle_segments)};
}

// Every fourth record dropped: a graph as valid for the step as a full one (each
// triangle's lists are consistent), where t misses points that its partners hold on t's
// edges. With every pair classified t's own pairs find those, so only here do the edge
// additions have work.
PairRecords thinned(const PairRecords& records) {
  PairRecordChunk kept;
  std::size_t i = 0;
  for (const PairIntersection& r : records)
    if (i++ % 4 != 1) kept.push_back(r);
  return PairRecords(std::vector<PairRecordChunk>{kept});
}

// The step on all records and on thinned ones.
template <class M>
std::array<Counts, 2> check_both(const std::vector<typename M::Vertex>& V, const std::vector<Tri>& F,
                                 const PairRecords& records, const std::string& what) {
  return {check_share<M>(V, F, records, what), check_share<M>(V, F, thinned(records), what + " (thinned)")};
}

std::array<Counts, 2> run_double(const TriangleSoup& input, Classifier classifier, const std::string& what) {
  PreprocessStats stats;
  const TriangleSoup soup = preprocess(input, PreprocessOptions{}, stats);
  const auto& V = soup.vertices;
  const auto& F = soup.triangles;
  return check_both<DoubleModel>(V, F, classify_pairs(V, F, candidate_pairs(V, F), classifier), what);
}

TEST(ShareCoplanar, DoubleModelMatchesBruteForce) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Scene> all = scenes();
  std::array<Counts, 2> sum;
  std::size_t runs = 0;
  for (std::size_t s = 0; s < all.size(); ++s) {
    const Scene& scene = all[s];
    const auto scene_start = std::chrono::steady_clock::now();
    std::array<Counts, 2> first;
    const std::vector<Placement> where = placements(s, scene.large);
    for (std::size_t p = 0; p < where.size(); ++p) {
      const std::string what = scene.name + ", " + where[p].name();
      // Both classifiers (their records should make the same graph).
      const auto c = run_double(place(scene.soup, where[p]), p % 2 == 0 ? Classifier::Native : Classifier::Tritri, what);
      ++runs;
      for (int h = 0; h < 2; ++h)
        sum[h].coplanar_pairs += c[h].coplanar_pairs, sum[h].inside += c[h].inside, sum[h].on_edge += c[h].on_edge,
            sum[h].segments += c[h].segments;
      if (p == 0) {
        first = c;
        // Not vacuous: coplanar pairs, and something to share.
        EXPECT_GT(c[0].coplanar_pairs, 0u) << what;
        EXPECT_GT(c[0].added(), 0u) << what;
      } else {
        // Exact maps of the plane change no incidence, so neither what is shared.
        EXPECT_EQ(str(c[0]), str(first[0])) << what;
        EXPECT_EQ(str(c[1]), str(first[1])) << what << " (thinned)";
      }
    }
    std::printf("%-25s %s; thinned: %s; %zu placements, %.2f s\n", scene.name.c_str(), str(first[0]).c_str(),
                str(first[1]).c_str(), where.size(), seconds_since(scene_start));
  }
  std::printf("%zu scenes, %zu placements; all records: %s; thinned: %s; %.2f s\n", all.size(), runs,
              str(sum[0]).c_str(), str(sum[1]).c_str(), seconds_since(start));
  // Every kind of addition happened somewhere.
  EXPECT_GT(sum[0].inside, 0u);
  EXPECT_GT(sum[0].segments, 0u);
  EXPECT_GT(sum[1].on_edge, 0u);
}

// The exact path on the scenes without the large ones: z = 0, and z = x + y moved and
// scaled by 2^-60. Its additions are those of the double path (the same geometry).
TEST(ShareCoplanar, ExactModelMatchesBruteForce) {
  const auto start = std::chrono::steady_clock::now();
  std::size_t runs = 0;
  for_each_exact_run(scenes(), [&](const std::string& what, const TriangleSoup& input, const auto& soup) {
    const auto& V = soup.vertices;
    const auto& F = soup.triangles;
    const auto pairs = detect_pairs<ExactModel>(V, F, 0).pairs;
    const auto c = check_both<ExactModel>(V, F, classify_pairs<ExactModel>(V, F, pairs, Classifier::Native), what);
    ++runs;
    EXPECT_GT(c[0].added(), 0u) << what;
    const auto d = run_double(input, Classifier::Native, what);
    EXPECT_EQ(str(c[0]), str(d[0])) << what;
    EXPECT_EQ(str(c[1]), str(d[1])) << what << " (thinned)";
  });
  EXPECT_GT(runs, 0u);
  std::printf("%zu exact placements; %.2f s\n", runs, seconds_since(start));
}

}  // namespace
