// tests/test_triangulate_cluster.cpp
//
// Stage 5's whole-cluster path (stages/5_triangulate_cluster.h): a cluster of mutually
// overlapping coplanar triangles where per-triangle splitting would repeat most of its
// work is triangulated once, and each soup triangle keeps the local triangles it covers.
// The old per-triangle path (TriangulationInfo::per_triangle_only) is the reference: both
// must give the same arrangement. Per scene and placement, run both ways, and check:
//   - the new path really ran (whole_clusters is the scene's number of clusters; 0 with
//     per_triangle_only), so that nothing below is vacuous;
//   - the new path's output tiles every soup triangle with triangles in its orientation,
//     owned by the smallest covering triangle, labelled with the union of the covering
//     triangles' labels (tiling_problems); keeps the graph (graph_problems), and each
//     cluster's segments are chains of edges of the cluster's own output triangles (no
//     T-junction hidden by a crossing triangle's edges along the same line); on small
//     outputs no two output triangles meet improperly (all_pairs_problems);
//   - the two paths agree exactly: the same output vertices (exact rationals), the same
//     number of triangles, and per soup triangle the same number of triangles with the
//     same label sets (every soup triangle has a label of its own, so a label set names
//     the covering triangles). The local triangulations may differ (no Delaunay flips:
//     edges depend on insertion order), but the number of triangles of a region with
//     given vertices and constraints does not (Euler);
//   - one and two threads give the same output (arrange()).
// Scenes (local coordinates, placed exactly in five planes, scaled by 2^k, moved by 2^20:
// support/coplanar_scenes.h): 32 thin wedges through one region, the same crossed by
// non-coplanar triangles (new TPIs and segments inside the cluster), layered jittered
// tessellations of one square (plain, a third of the triangles flipped, crossed), stacked
// fans sharing edges, two clusters in two planes crossing each other, and as a control
// two coplanar strip fans (each fan tiles its polygon, so the repetition stays below
// kWholeFrom: split per triangle, the output identical both ways). DoubleModel, and
// ExactModel on the smaller scenes (exact rationals compared with the double model's).
// A scene must exceed kWholeMinWork and kWholeFrom x its distinct work to be clustered:
// thin wedges only do from about 32 (their edge points, not repeated, dominate).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "arrangements/arrange.h"
#include "arrangements/as_input.h"
#include "models/exact_model.h"
#include "stages/1_preprocess.h"
#include "stages/2_candidate_pairs.h"
#include "stages/3_classify_pairs.h"
#include "stages/4_intersection_graph.h"
#include "stages/5_triangulate.h"
#include "stages/5_triangulate_cluster.h"
#include "support/coplanar_scenes.h"
#include "support/exact_oracle.h"
#include "support/test_scale.h"
#include "support/triangulation_checks.h"

namespace {

using namespace arrangements;
using namespace tritri_test::coplanar;
namespace ta = tritri_test::arrangement;
using tritri_test::exact;

// ---------------------------------------------------------------------------------------
// Scenes.

struct Scene {
  std::string name;
  TriangleSoup soup;     // local coordinates: the clusters' plane is w = 0 (or x = const)
  std::size_t clusters;  // triangulated whole (0: the control)
  bool crossed = false;  // non-coplanar triangles through the cluster: new TPIs expected
  bool exact = false;    // also with ExactModel
  std::vector<Placement> where;
};

using At = std::array<double, 3> (*)(double, double);
std::array<double, 3> in_w0(double u, double v) { return {u, v, 0}; }
// A second plane, x = 0.375, through the middle of the first.
std::array<double, 3> in_x(double u, double v) { return {0.375, 0.75 * u, 0.75 * v}; }

// n thin wedges through one region (test_hostile_polygons' write_wedges, doubled): wedge i
// from (-2, y_i) to the short segment x = 2, y in -y_i -+ 1/n, placed by at; every
// flip_every-th one turned the other way round.
void wedges(Builder& b, int n, At at, int flip_every = 0, double width = 1) {
  for (int i = 0; i < n; ++i) {
    const double y = -2 + 4 * (i + 0.5) / n, d = width / n;
    const auto p = at(-2, y), q = at(2, -y + d), r = at(2, -y - d);
    const int a = b.vertex(p[0], p[1], p[2]), c = b.vertex(q[0], q[1], q[2]), e = b.vertex(r[0], r[1], r[2]);
    if (flip_every > 0 && i % flip_every == 0)
      b.triangle(a, e, c);
    else
      b.triangle(a, c, e);
  }
}

// `layers` m x m grids of the square [-2, 2]^2 placed by at, the inner vertices of each
// moved by up to 0.3 of a cell (the border ones are shared, so border edges overlap
// collinearly); the diagonals alternate from layer to layer.
void layered(Builder& b, int layers, int m, std::mt19937_64& rng, At at = in_w0) {
  const double cell = 4.0 / m;
  for (int l = 0; l < layers; ++l) {
    const int first = static_cast<int>(b.soup.vertices.size());
    for (int j = 0; j <= m; ++j)
      for (int i = 0; i <= m; ++i) {
        const bool inner = i > 0 && i < m && j > 0 && j < m;
        const double dx = inner ? 0.6 * cell * (unit(rng) - 0.5) : 0, dy = inner ? 0.6 * cell * (unit(rng) - 0.5) : 0;
        const auto p = at(-2 + cell * i + dx, -2 + cell * j + dy);
        b.vertex(p[0], p[1], p[2]);
      }
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const int a = first + j * (m + 1) + i, c = a + m + 2, d = a + m + 1;
        if (l % 2 == 0)
          b.triangle(a, a + 1, c), b.triangle(a, c, d);
        else
          b.triangle(a, a + 1, d), b.triangle(a + 1, c, d);
      }
  }
}

// `fans` closed fans of k triangles (shared edges), each around its own apex near the
// origin over one rim of radius 2 (turned by `turn` degrees per fan; 0: the rim edges are
// shared by all the fans): every fan over the others.
void fan_stack(Builder& b, int fans, int k, std::mt19937_64& rng, double turn = 0) {
  for (int f = 0; f < fans; ++f) {
    const P2 apex = {unit(rng) - 0.5, unit(rng) - 0.5};
    apex_fan(b, apex, rim({0, 0}, 2, k, turn * f), Apex::kFirst);
  }
}

// Every `every`-th triangle so far turned the other way round.
void flip_some(Builder& b, int every) {
  for (std::size_t t = 0; t < b.soup.triangles.size(); t += every) std::swap(b.soup.triangles[t][1], b.soup.triangles[t][2]);
}

// Vertical walls whose traces cross each other inside the wedges (new TPIs), and generic
// triangles through the plane (crossing(), corners in [-1.5, 1.5]^2).
void cross_through(Builder& b, std::mt19937_64& rng) {
  wall(b, {-1.5, -1.25}, {1.5, 1.0});
  wall(b, {-1.25, 1.5}, {1.0, -1.5});
  wall(b, {0.25, -2}, {-0.375, 2});
  crossing(b, [&] { return P2{3 * unit(rng) - 1.5, 3 * unit(rng) - 1.5}; });
}

// Every soup triangle a label of its own: a label set then names its covering triangles.
TriangleSoup labelled(Builder b) {
  TriangleSoup s = std::move(b.soup);
  s.label_sets.clear();
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    s.label_sets.push_back({static_cast<std::uint32_t>(t)});
    s.label_set[t] = static_cast<int>(t);
  }
  return s;
}

// The placements (support/coplanar_scenes.h) spread over the scenes: every plane, the
// scalings 2^-60, 2^0 and 2^40, with and without the offset 2^20. Sanitizer runs: the
// first of each scene only.
std::vector<Scene> scenes() {
  std::mt19937_64 rng(tritri_test::seed_for(3607));
  std::vector<Scene> out;
  auto add = [&](std::string name, Builder b, std::size_t clusters, bool crossed, bool exact,
                 std::vector<Placement> where) {
    if (crossed) cross_through(b, rng);
    if (tritri_test::scaled_down()) where.resize(1);
    out.push_back({std::move(name), labelled(std::move(b)), clusters, crossed, exact, std::move(where)});
  };
  // 32 wedges: about the fewest that take the new path (its work >= 4 x its distinct
  // work); their axes all pass exactly through the origin, so many edges meet at points.
  for (const bool crossed : {false, true}) {
    Builder b;
    wedges(b, 32, in_w0);
    add(crossed ? "wedges, crossed" : "wedges", std::move(b), 1, crossed, false,
        {crossed ? Placement{2, -60, false} : Placement{0, 0, false}});
    if (crossed && tritri_test::scaled_down()) out.pop_back();  // the longest (after add: the same random numbers)
  }
  {
    Builder b;
    layered(b, 8, 2, rng);
    add("layers", std::move(b), 1, false, true, {{0, 0, false}, {1, 40, true}});
  }
  {
    Builder b;
    layered(b, 8, 2, rng);
    flip_some(b, 3);
    add("layers, a third flipped", std::move(b), 1, false, true, {{0, 0, false}, {3, -60, false}});
  }
  {
    Builder b;
    layered(b, 8, 2, rng);
    add("layers, crossed", std::move(b), 1, true, true, {{0, 0, false}, {2, 0, true}});
  }
  {
    Builder b;
    fan_stack(b, 8, 6, rng);
    flip_some(b, 5);
    add("stacked fans", std::move(b), 1, false, false, {{0, 0, false}, {4, -60, true}});
  }
  {
    Builder b;
    layered(b, 8, 2, rng);
    layered(b, 8, 2, rng, in_x);
    add("two clusters, two planes", std::move(b), 2, true, true, {{3, 40, true}});
  }
  add("strip fans (control)", strips(24), 0, false, false, {{0, 0, false}, {4, 0, false}});
  return out;
}

// ---------------------------------------------------------------------------------------
// An arrangement as the comparison sees it.

struct Arrangement {
  std::set<Q3> vertices;  // the exact positions of the vertices the triangles use
  std::size_t used = 0;   // how many vertex ids they use (== vertices.size(): no duplicates)
  std::size_t triangles = 0;
  std::map<std::int64_t, std::vector<LabelSet>> labels_of;  // per source: its triangles' label sets, sorted
  std::size_t against_owner = 0;  // degenerate, or oriented against the soup triangle emitting it
};

// X: exact positions by vertex id; per output triangle, its owner's corners and its label set.
template <class Corners, class Labels>
Arrangement arrangement_of(const std::vector<Q3>& X, const std::vector<Tri>& F, const std::vector<std::int64_t>& source,
                           Corners&& corners_of, Labels&& labels_of) {
  Arrangement a;
  std::set<int> ids;
  for (std::size_t t = 0; t < F.size(); ++t) {
    const Tri& T = F[t];
    for (int v : T) ids.insert(v), a.vertices.insert(X[v]);
    const std::array<Q3, 3> U = corners_of(t);
    const int axis = tritri_test::projection_axis(U[0], U[1], U[2]);
    a.against_owner += axis < 0 || sgn(tritri_test::area2(X[T[0]], X[T[1]], X[T[2]], axis)) !=
                                       sgn(tritri_test::area2(U[0], U[1], U[2], axis));
    a.labels_of[source[t]].push_back(labels_of(t));
  }
  for (auto& [s, l] : a.labels_of) std::sort(l.begin(), l.end());
  a.used = ids.size();
  a.triangles = F.size();
  return a;
}

// The stage-by-stage double run, in the graph's numbering (owner = preprocessed soup triangle).
Arrangement arrangement_of(const ta::Pipeline& p) {
  const ta::Triangulated& tr = p.tr;
  std::vector<Q3> X(tr.points.size());
  for (std::size_t i = 0; i < tr.points.size(); ++i) X[i] = exact(tr.points[i]);
  std::vector<std::int64_t> source;
  for (int o : tr.owner) source.push_back(p.soup.source[o]);
  return arrangement_of(
      X, tr.triangles, source,
      [&](std::size_t t) {
        const Tri& u = p.soup.triangles[tr.owner[t]];
        return std::array<Q3, 3>{exact(p.soup.vertices[u[0]]), exact(p.soup.vertices[u[1]]),
                                 exact(p.soup.vertices[u[2]])};
      },
      [&](std::size_t t) { return tr.label_sets[tr.label_set[t]]; });
}

// An exact output mesh of the exact soup it came from.
Arrangement arrangement_of(const BasicTriangleSoup<ExactModel::Vertex>& soup, const BasicOutputMesh<ExactModel::Point>& m) {
  std::vector<Q3> X;
  for (const auto& v : m.vertices) X.push_back(exact(v));
  std::map<std::int64_t, int> triangle_of;
  for (std::size_t t = 0; t < soup.source.size(); ++t) triangle_of[soup.source[t]] = static_cast<int>(t);
  return arrangement_of(
      X, m.triangles, m.source,
      [&](std::size_t t) {
        const Tri& u = soup.triangles[triangle_of.at(m.source[t])];
        return std::array<Q3, 3>{exact(soup.vertices[u[0]]), exact(soup.vertices[u[1]]), exact(soup.vertices[u[2]])};
      },
      [&](std::size_t t) { return m.label_sets[m.label_set[t]]; });
}

void expect_same(const Arrangement& a, const Arrangement& b, const std::string& what) {
  EXPECT_EQ(a.used, a.vertices.size()) << what << ": two output vertices at one position (first)";
  EXPECT_EQ(b.used, b.vertices.size()) << what << ": two output vertices at one position (second)";
  EXPECT_EQ(a.against_owner, 0u) << what << ": triangles against their owner (first)";
  EXPECT_EQ(b.against_owner, 0u) << what << ": triangles against their owner (second)";
  EXPECT_EQ(a.vertices.size(), b.vertices.size()) << what << ": output vertices";
  if (a.vertices != b.vertices) {
    std::vector<Q3> only_a, only_b;
    std::set_difference(a.vertices.begin(), a.vertices.end(), b.vertices.begin(), b.vertices.end(),
                        std::back_inserter(only_a));
    std::set_difference(b.vertices.begin(), b.vertices.end(), a.vertices.begin(), a.vertices.end(),
                        std::back_inserter(only_b));
    ADD_FAILURE() << what << ": different vertex sets, " << only_a.size() << " only in the first (e.g. "
                  << (only_a.empty() ? "-" : tritri_test::to_string(only_a[0])) << "), " << only_b.size()
                  << " only in the second (e.g. " << (only_b.empty() ? "-" : tritri_test::to_string(only_b[0]))
                  << ")";
  }
  EXPECT_EQ(a.triangles, b.triangles) << what << ": output triangles";
  EXPECT_EQ(a.labels_of.size(), b.labels_of.size()) << what << ": soup triangles with output";
  std::size_t differ = 0;
  for (const auto& [s, l] : a.labels_of) {
    const auto it = b.labels_of.find(s);
    if (it != b.labels_of.end() && it->second == l) continue;
    if (differ++ < 4)
      ADD_FAILURE() << what << ": soup triangle (source " << s << "): " << l.size() << " triangles vs "
                    << (it == b.labels_of.end() ? 0 : it->second.size()) << ", or other label sets";
  }
  EXPECT_EQ(differ, 0u) << what << ": soup triangles whose triangles or label sets differ";
}

// Segments inside coplanar-clustered triangles (constraints from other planes).
template <class G>
std::size_t cluster_segments(const G& g) {
  std::size_t n = 0;
  for (std::size_t t = 0; t < g.coplanar_partners.size(); ++t)
    if (!g.coplanar_partners[t].empty()) n += g.triangle_segments[t].size();
  return n;
}

// graph_problems walks every listed segment, and stage 4 lists a segment in every triangle
// of a cluster that holds it (12 times on average in the wedges): each one once.
ta::Problems graph_problems_once(ta::Pipeline p) {
  std::set<std::array<int, 2>> seen;
  for (auto& segments : p.graph.triangle_segments)
    std::erase_if(segments, [&](const std::array<int, 2>& s) { return !seen.insert(s).second; });
  return ta::graph_problems(p);
}

// graph_problems follows a segment along edges of any output triangle, and a segment of a
// cluster triangle lies on the line where a crossing triangle meets the plane, so the
// crossing triangle's own edges satisfy it even when the cluster's triangles skip a point
// of it (a T-junction: sabotage showed it). So per cluster, the chains of its triangles'
// segments among the edges of its own output triangles alone (other points are not used
// there: only the chains are kept of what graph_problems reports).
ta::Problems cluster_chain_problems(const ta::Pipeline& p) {
  const auto& g = p.graph;
  const std::size_t n = g.coplanar_partners.size();
  std::vector<int> cluster(n, -1);
  int clusters = 0;
  for (std::size_t t = 0; t < n; ++t) {
    if (g.coplanar_partners[t].empty() || cluster[t] >= 0) continue;
    std::vector<int> stack = {static_cast<int>(t)};
    cluster[t] = clusters;
    while (!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      for (int w : g.coplanar_partners[u])
        if (cluster[w] < 0) cluster[w] = clusters, stack.push_back(w);
    }
    ++clusters;
  }
  ta::Problems out;
  for (int c = 0; c < clusters; ++c) {
    ta::Pipeline q;
    q.graph = g;
    for (std::size_t t = 0; t < n; ++t)
      if (cluster[t] != c) q.graph.triangle_segments[t].clear();
    q.tr.points = p.tr.points;
    q.tr.num_tpi = p.tr.num_tpi;
    for (std::size_t t = 0; t < p.tr.triangles.size(); ++t)
      if (cluster[p.tr.owner[t]] == c) q.tr.triangles.push_back(p.tr.triangles[t]);
    for (std::string& problem : graph_problems_once(std::move(q)))
      if (problem.rfind("constraint", 0) == 0) out.push_back("cluster " + std::to_string(c) + ": " + problem);
  }
  return out;
}

constexpr std::size_t kAllPairsUpTo = 500;  // all_pairs_problems is quadratic

// ---------------------------------------------------------------------------------------

TEST(TriangulateCluster, WholeClustersMatchPerTriangle) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Scene> all = scenes();
  for (std::size_t s = 0; s < all.size(); ++s) {
    const Scene& scene = all[s];
    const auto scene_start = std::chrono::steady_clock::now();
    const std::vector<Placement>& where = scene.where;
    std::size_t out_triangles = 0, tpis = 0, segments = 0;
    for (std::size_t p = 0; p < where.size(); ++p) {
      const std::string what = scene.name + ", " + where[p].name();
      const TriangleSoup input = place(scene.soup, where[p]);
      const Classifier classifier = (s + p) % 2 == 0 ? Classifier::Native : Classifier::Tritri;
      TriangulationInfo whole_info, per_info;
      per_info.per_triangle_only = true;
      const ta::Pipeline whole = ta::run_stages(input, classifier, &whole_info);
      const ta::Pipeline per = ta::run_stages(input, classifier, &per_info);
      // Not vacuous: the scene's clusters took the new path (and none with per_triangle_only).
      ASSERT_EQ(whole_info.whole_clusters, scene.clusters) << what;
      EXPECT_EQ(per_info.whole_clusters, 0u) << what;
      out_triangles = whole.tr.triangles.size(), tpis = whole_info.new_tpi, segments = cluster_segments(whole.graph);
      if (scene.crossed) {
        EXPECT_GT(tpis, 0u) << what << ": no new TPI";
        EXPECT_GT(segments, 0u) << what << ": no segment inside the clusters";
      }
      ta::expect_no_problems(ta::tiling_problems(whole), what + ": tiling (whole)");
      ta::expect_no_problems(graph_problems_once(whole), what + ": graph (whole)");
      ta::expect_no_problems(cluster_chain_problems(whole), what + ": chains in clusters (whole)");
      // The quadratic check, and the reference's own tiling, on small outputs (once).
      if (p == 0 && scene.clusters > 0 && out_triangles <= kAllPairsUpTo) {
        ta::expect_no_problems(ta::all_pairs_problems(whole.tr.points, whole.tr.triangles), what + ": all pairs");
        ta::expect_no_problems(ta::tiling_problems(per), what + ": tiling (per triangle)");
      }
      EXPECT_EQ(tpis, per_info.new_tpi) << what;
      expect_same(arrangement_of(whole), arrangement_of(per), what + ": whole vs per triangle");
      if (scene.clusters == 0) {  // the control: byte for byte
        EXPECT_EQ(whole.tr.triangles, per.tr.triangles) << what;
        EXPECT_EQ(whole.tr.label_set, per.tr.label_set) << what;
        EXPECT_EQ(whole.tr.label_sets, per.tr.label_sets) << what;
      }
      // arrange(): the same output with one and two threads (two clusters: in parallel).
      if (p + 1 == where.size()) {
        const ArrangeResult one = ta::run_arrange(input, classifier, 1);
        const ArrangeResult two = ta::run_arrange(input, classifier, 2);
        EXPECT_TRUE(ta::same_output(one.mesh, two.mesh)) << what << ": 1 and 2 threads";
        EXPECT_EQ(one.mesh.triangles.size(), out_triangles) << what;
      }
    }
    std::printf("%-26s %3zu triangles -> %4zu, %2zu TPIs, %5zu segments in clusters; %zu placements, %.2f s\n",
                scene.name.c_str(), scene.soup.triangles.size(), out_triangles, tpis, segments, where.size(),
                seconds_since(scene_start));
  }
  std::printf("all: %.2f s\n", seconds_since(start));
}

// The exact model on the smaller scenes (z = 0, and z = x + y moved by 2^20 and scaled by
// 2^-60, as for_each_exact_run): both paths the same, and the same as the double model's
// whole path (the same input, exactly).
TEST(TriangulateCluster, ExactModelMatchesPerTriangleAndDoubleModel) {
  const auto start = std::chrono::steady_clock::now();
  for (const Scene& scene : scenes()) {
    if (!scene.exact) continue;
    for (const Placement& where : {Placement{0, 0, false}, Placement{4, -60, true}}) {
      if (tritri_test::scaled_down() && where.plane != 0) continue;
      const std::string what = scene.name + ", " + where.name() + " (exact)";
      const TriangleSoup input = place(scene.soup, where);
      PreprocessStats stats;
      const auto soup = preprocess<ExactModel>(to_exact(input), PreprocessOptions{}, stats);
      const auto& V = soup.vertices;
      const auto& F = soup.triangles;
      const auto g = build_intersection_graph<ExactModel>(
          V, F, classify_pairs<ExactModel>(V, F, detect_pairs<ExactModel>(V, F, 0).pairs, Classifier::Native));
      TriangulationInfo whole_info, per_info;
      per_info.per_triangle_only = true;
      const auto whole = triangulate<ExactModel>(soup, g, 0, whole_info);
      const auto per = triangulate<ExactModel>(soup, g, 0, per_info);
      ASSERT_EQ(whole_info.whole_clusters, scene.clusters) << what;
      EXPECT_EQ(per_info.whole_clusters, 0u) << what;
      if (scene.crossed) {
        EXPECT_GT(whole_info.new_tpi, 0u) << what;
      }
      EXPECT_EQ(whole_info.new_tpi, per_info.new_tpi) << what;
      const Arrangement exact_whole = arrangement_of(soup, whole);
      expect_same(exact_whole, arrangement_of(soup, per), what + ": whole vs per triangle");
      TriangulationInfo double_info;
      const ta::Pipeline d = ta::run_stages(input, Classifier::Native, &double_info);
      EXPECT_EQ(double_info.whole_clusters, scene.clusters) << what;
      expect_same(exact_whole, arrangement_of(d), what + ": exact vs double");
    }
  }
  std::printf("exact: %.2f s\n", seconds_since(start));
}

}  // namespace
