// tests/support/triangulation_checks.h
//
// Running the pipeline and checking exactly what it produced, for the arrangement tests
// (rationals from support/exact_oracle.h; no tolerance anywhere):
//   run_stages(input, classifier[, info])  the stages one by one (preprocess, candidate pairs,
//                  classification, intersection graph, triangulate), keeping the soup, the
//                  graph and the triangulation in the graph's numbering; the one place
//                  that calls triangulate()
//   run_arrange    arrange() with a classifier, thread count and scaling
//   all_pairs_problems  every two output triangles meet only in a shared vertex or edge
//                  (tritri on the implicit points; quadratic, small meshes only)
//   tiling_problems     every output triangle lies in its owner, the triangles covering a
//                  soup triangle tile it (exact areas), owner and label sets are right
//   graph_problems      every graph point is an output vertex, every constraint segment a
//                  chain of output edges
//   expect_stats_match_mesh, same_output, counts   the stats against the mesh; equal
//                  outputs; MeshCounts from V, E, F
// A check returns its Problems (empty: none); expect_no_problems reports them.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <tritri/classify.h>
#include <tritri/implicit_kernel.h>
#include <tritri/implicit_point.h>
#include <tritri/implicit_predicates.h>

#include "arrangements/arrange.h"
#include "arrangements/output_mesh.h"
#include "arrangements/triangle_soup.h"
#include "stages/1_preprocess.h"
#include "stages/2_candidate_pairs.h"
#include "stages/3_classify_pairs.h"
#include "stages/4_intersection_graph.h"
#include "stages/5_triangulate.h"
#include "support/mesh_counts.h"

#include "exact_oracle.h"

namespace tritri_test::arrangement {

using namespace ::arrangements;
using tritri::ImplicitPoint;

inline constexpr Classifier kClassifiers[] = {Classifier::Native, Classifier::Tritri};

inline const char* name_of(Classifier c) { return c == Classifier::Native ? "native" : "tritri"; }

// ---------------------------------------------------------------------------------------
// The pipeline stage by stage, keeping what the checks need.

// The triangulation in the graph's numbering (graph point ids, then the new TPIs; owner =
// soup triangle), so that the checks below can follow graph ids: triangulate() returns
// the output mesh, renumbered, with TriangulationInfo::output_vertex as the map.
struct Triangulated {
  std::vector<ImplicitPoint> points;
  std::size_t num_tpi = 0;
  std::vector<Tri> triangles;
  std::vector<int> owner;
  std::vector<int> label_set;
  std::vector<LabelSet> label_sets;
};

inline Triangulated in_graph_numbering(const TriangleSoup& soup, const IntersectionGraph& g, const OutputMesh& mesh,
                                       const TriangulationInfo& info) {
  Triangulated tr;
  tr.num_tpi = info.new_tpi;
  tr.points = g.points;
  std::vector<int> graph_id(mesh.vertices.size(), -1);
  for (std::size_t i = 0; i < info.output_vertex.size(); ++i) {
    const int v = info.output_vertex[i];
    if (i >= g.points.size()) tr.points.push_back(v >= 0 ? mesh.vertices[v] : ImplicitPoint{});
    if (v >= 0) graph_id[v] = static_cast<int>(i);
  }
  std::map<std::int64_t, int> soup_triangle;
  for (std::size_t t = 0; t < soup.source.size(); ++t) soup_triangle[soup.source[t]] = static_cast<int>(t);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    Tri T = mesh.triangles[t];
    for (int& v : T) v = graph_id[v];
    tr.triangles.push_back(T);
    tr.owner.push_back(soup_triangle.at(mesh.source[t]));
  }
  tr.label_set = mesh.label_set;
  tr.label_sets = mesh.label_sets;
  return tr;
}

// What run_stages keeps: the input of the triangulation and its output.
struct Pipeline {
  TriangleSoup soup;  // preprocessed
  IntersectionGraph graph;
  Triangulated tr;
};

// info: when given, passed to triangulate() (its options, e.g. per_triangle_only, are
// read; its results, e.g. new_tpi and whole_clusters, are left in it).
inline Pipeline run_stages(const TriangleSoup& input, Classifier classifier, TriangulationInfo* info = nullptr) {
  Pipeline p;
  PreprocessStats stats;
  p.soup = preprocess(input, PreprocessOptions{}, stats);
  const auto& V = p.soup.vertices;
  const auto& F = p.soup.triangles;
  const auto records = classify_pairs(V, F, candidate_pairs(V, F), classifier);
  p.graph = build_intersection_graph(V, F, records);
  TriangulationInfo own;
  TriangulationInfo& used = info != nullptr ? *info : own;
  const OutputMesh mesh = triangulate(p.soup, p.graph, 0, used);
  p.tr = in_graph_numbering(p.soup, p.graph, mesh, used);
  return p;
}

inline ArrangeResult run_arrange(const TriangleSoup& input, Classifier classifier, int threads = 0,
                                 bool scale = false) {
  ArrangeOptions o;
  o.classifier = classifier;
  o.threads = threads;
  o.scale = scale;
  return arrange(input, o);
}

// ---------------------------------------------------------------------------------------
// Independent validity check: every pair of output triangles classified with
// tritri on the implicit points; the only contact allowed is vertex-on-vertex at a vertex
// both triangles name by the same id (so a shared vertex or a shared edge). Also: no two
// vertices at one position, no degenerate triangle. Quadratic: small meshes only.
using Problems = std::vector<std::string>;

inline void expect_no_problems(const Problems& problems, const std::string& what) {
  EXPECT_TRUE(problems.empty()) << what << ": " << problems.size() << " problems";
  for (std::size_t i = 0; i < problems.size() && i < 8; ++i) ADD_FAILURE() << what << ": " << problems[i];
}
inline bool mentions(const Problems& problems, const std::string& word) {
  for (const std::string& p : problems)
    if (p.find(word) != std::string::npos) return true;
  return false;
}

inline Problems all_pairs_problems(const std::vector<ImplicitPoint>& P, const std::vector<Tri>& F) {
  Problems out;
  std::vector<int> used;
  for (const Tri& t : F) used.insert(used.end(), t.begin(), t.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::set<Q3> positions;
  for (int v : used)
    if (!positions.insert(exact(P[v])).second) out.push_back("two vertices at " + to_string(exact(P[v])));
  for (std::size_t i = 0; i < F.size(); ++i) {
    const Tri& a = F[i];
    for (std::size_t j = i + 1; j < F.size(); ++j) {
      const Tri& b = F[j];
      const tritri::Result r =
          tritri::classify<tritri::ImplicitKernel>(P[a[0]], P[a[1]], P[a[2]], P[b[0]], P[b[1]], P[b[2]]);
      bool ok = !r.degenerate;
      for (const auto& x : r.points) ok &= x.type == tritri::Type::VA_ON_VB && a[x.id0] == b[x.id1];
      if (!ok) {
        std::ostringstream os;
        os << "output triangles " << i << " and " << j << " intersect improperly: " << r;
        out.push_back(os.str());
      }
    }
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// Containment, tiling by exact areas, owner and labels, for the pipeline run stage by stage.
//
// An output triangle t is covered by a soup triangle u when t's three vertices lie in u's
// plane and in the closed u (then t, their convex hull, lies in u). In an arrangement
// every input triangle is exactly the union of the output triangles it covers (the output
// triangles covering u tile u, overlapping only on edges), so per u the projected areas
// of those output triangles sum exactly to u's projected area. The owner of t is the
// smallest covering triangle, and t's label set is the union of the covering triangles'.
inline Problems tiling_problems(const Pipeline& p) {
  Problems out;
  const auto& soup = p.soup;
  const auto& tr = p.tr;
  if (tr.owner.size() != tr.triangles.size() || tr.label_set.size() != tr.triangles.size())
    return {"per-triangle arrays of the wrong size"};
  std::vector<Q3> X(tr.points.size());
  std::vector<std::array<double, 3>> D(tr.points.size());
  for (std::size_t i = 0; i < tr.points.size(); ++i) {
    X[i] = exact(tr.points[i]);
    D[i] = tritri::to_double(tr.points[i]);
  }
  const std::size_t nf = soup.triangles.size();
  std::vector<std::array<Q3, 3>> U(nf);
  std::vector<int> axis(nf);
  std::vector<std::array<double, 6>> box(nf);
  for (std::size_t u = 0; u < nf; ++u) {
    for (int k = 0; k < 3; ++k) U[u][k] = exact(soup.vertices[soup.triangles[u][k]]);
    axis[u] = projection_axis(U[u][0], U[u][1], U[u][2]);
    if (axis[u] < 0) return {"degenerate soup triangle " + std::to_string(u)};
    for (int c = 0; c < 3; ++c) {
      box[u][c] = std::min({soup.vertices[soup.triangles[u][0]][c], soup.vertices[soup.triangles[u][1]][c],
                            soup.vertices[soup.triangles[u][2]][c]});
      box[u][3 + c] = std::max({soup.vertices[soup.triangles[u][0]][c], soup.vertices[soup.triangles[u][1]][c],
                                soup.vertices[soup.triangles[u][2]][c]});
    }
  }
  std::vector<Q> covered_area(nf, 0), owned_area(nf, 0);
  auto fail = [&](const std::string& msg) { out.push_back(msg); };
  for (std::size_t t = 0; t < tr.triangles.size(); ++t) {
    const Tri& T = tr.triangles[t];
    const int o = tr.owner[t];
    if (o < 0 || static_cast<std::size_t>(o) >= nf) {
      fail("output triangle " + std::to_string(t) + " has owner out of range");
      continue;
    }
    // Conservative filter: correctly rounded coordinates stay inside any double box that
    // contains the exact point.
    std::vector<int> covering;
    for (std::size_t u = 0; u < nf; ++u) {
      bool maybe = true;
      for (int k = 0; k < 3 && maybe; ++k)
        for (int c = 0; c < 3; ++c) maybe &= D[T[k]][c] >= box[u][c] && D[T[k]][c] <= box[u][3 + c];
      if (!maybe) continue;
      bool in = true;
      for (int k = 0; k < 3 && in; ++k)
        in = orient3d(U[u][0], U[u][1], U[u][2], X[T[k]]) == 0 &&
             in_closed_triangle(U[u][0], U[u][1], U[u][2], X[T[k]], axis[u]);
      if (in) covering.push_back(static_cast<int>(u));
    }
    // Inside its own source: coplanar (orient3d == 0) and in the closed triangle.
    for (int k = 0; k < 3; ++k) {
      if (orient3d(U[o][0], U[o][1], U[o][2], X[T[k]]) != 0)
        fail("output triangle " + std::to_string(t) + " vertex " + to_string(X[T[k]]) +
             " is not in the plane of its owner " + std::to_string(o));
      else if (!in_closed_triangle(U[o][0], U[o][1], U[o][2], X[T[k]], axis[o]))
        fail("output triangle " + std::to_string(t) + " vertex " + to_string(X[T[k]]) + " is outside its owner " +
             std::to_string(o));
    }
    if (covering.empty()) continue;  // reported above
    if (covering.front() != o)
      fail("output triangle " + std::to_string(t) + ": owner " + std::to_string(o) + ", smallest covering triangle " +
           std::to_string(covering.front()));
    // Orientation like the owner, non-degenerate.
    const Q a_t = area2(X[T[0]], X[T[1]], X[T[2]], axis[o]);
    const Q a_o = area2(U[o][0], U[o][1], U[o][2], axis[o]);
    if (sgn(a_t) != sgn(a_o))
      fail("output triangle " + std::to_string(t) + " is degenerate or oriented against its owner");
    LabelSet labels;
    for (int u : covering) {
      const LabelSet& l = soup.label_sets[soup.label_set[u]];
      labels.insert(labels.end(), l.begin(), l.end());
      covered_area[u] += abs(area2(X[T[0]], X[T[1]], X[T[2]], axis[u]));
    }
    owned_area[o] += abs(a_t);
    std::sort(labels.begin(), labels.end());
    labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
    if (tr.label_sets.at(tr.label_set[t]) != labels) fail("output triangle " + std::to_string(t) + ": wrong label set");
  }
  for (std::size_t u = 0; u < nf; ++u) {
    const Q full = abs(area2(U[u][0], U[u][1], U[u][2], axis[u]));
    if (covered_area[u] != full)
      fail("soup triangle " + std::to_string(u) + ": covered area " + covered_area[u].get_str() + " != its area " +
           full.get_str());
    // Without coplanar overlaps, each triangle owns exactly its own area.
    if (p.graph.coplanar_partners[u].empty() && owned_area[u] != full)
      fail("soup triangle " + std::to_string(u) + ": owned area " + owned_area[u].get_str() + " != its area " +
           full.get_str());
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// The intersection graph survives in the output. Every point of the graph and
// every TPI is a vertex of an output triangle; every constraint segment (a, b) is a chain
// of output edges a = v0, v1, ..., vk = b, each v(i+1) the only neighbour of v(i) that lies
// on the segment strictly between v(i) and b... (at least one such neighbour is required,
// the nearest is taken; a valid arrangement has exactly one).
inline Problems graph_problems(const Pipeline& p) {
  Problems out;
  const auto& g = p.graph;
  const auto& tr = p.tr;
  if (tr.points.size() < g.points.size()) return {"fewer points than the graph"};
  if (tr.num_tpi != tr.points.size() - g.points.size()) out.push_back("num_tpi does not count the new points");
  for (std::size_t i = 0; i < g.points.size(); ++i)
    if (compare_xyz(g.points[i], tr.points[i]) != 0) out.push_back("point " + std::to_string(i) + " renumbered");
  std::vector<std::set<int>> nbr(tr.points.size());
  for (const Tri& t : tr.triangles)
    for (int k = 0; k < 3; ++k) {
      nbr[t[k]].insert(t[(k + 1) % 3]);
      nbr[t[(k + 1) % 3]].insert(t[k]);
    }
  for (std::size_t i = 0; i < tr.points.size(); ++i)
    if (nbr[i].empty())
      out.push_back("point " + std::to_string(i) +
                    (i < static_cast<std::size_t>(g.num_input_vertices) ? " (input)" : "") +
                    (i >= g.points.size() ? " (TPI)" : "") + " is not an output vertex");

  std::vector<Q3> X(tr.points.size());
  for (std::size_t i = 0; i < tr.points.size(); ++i) X[i] = exact(tr.points[i]);
  for (std::size_t t = 0; t < g.triangle_segments.size(); ++t)
    for (const auto& seg : g.triangle_segments[t]) {
      const int a = seg[0], b = seg[1];
      const Q3 dir = sub(X[b], X[a]);
      int cur = a;
      while (cur != b) {
        int next = -1;
        Q best;
        for (int w : nbr[cur]) {
          if (!is_zero(cross(dir, sub(X[w], X[a])))) continue;  // not on the segment's line
          const Q ahead = dot(sub(X[w], X[cur]), dir);
          if (sgn(ahead) <= 0 || sgn(dot(sub(X[b], X[w]), dir)) < 0) continue;  // behind cur or beyond b
          if (next < 0 || ahead < best) next = w, best = ahead;
        }
        if (next < 0) break;  // strictly advancing, so the walk ends
        cur = next;
      }
      if (cur != b)
        out.push_back("constraint " + std::to_string(a) + "-" + std::to_string(b) + " of triangle " +
                      std::to_string(t) + " is not a chain of output edges (stuck at " + std::to_string(cur) + ")");
    }
  return out;
}

// ---------------------------------------------------------------------------------------
// Whole outputs.

// The stats describe the mesh; every vertex is used; one source and label set per triangle.
inline void expect_stats_match_mesh(const ArrangeResult& r, const std::string& what) {
  const MeshCounts c = mesh_counts(r.mesh.triangles);
  EXPECT_EQ(r.stats.out_vertices, c.vertices) << what;
  EXPECT_EQ(r.stats.out_edges, c.edges) << what;
  EXPECT_EQ(r.stats.out_triangles, c.triangles) << what;
  EXPECT_EQ(r.stats.euler, c.euler) << what;
  EXPECT_EQ(r.mesh.vertices.size(), c.vertices) << what << ": unreferenced output vertices";
  EXPECT_EQ(r.mesh.source.size(), r.mesh.triangles.size()) << what;
  EXPECT_EQ(r.mesh.label_set.size(), r.mesh.triangles.size()) << what;
}

// Equal triangles, provenance, labels and exact vertices.
inline bool same_output(const OutputMesh& a, const OutputMesh& b) {
  if (a.triangles != b.triangles || a.source != b.source || a.label_set != b.label_set ||
      a.label_sets != b.label_sets || a.vertices.size() != b.vertices.size())
    return false;
  for (std::size_t i = 0; i < a.vertices.size(); ++i)
    if (compare_xyz(a.vertices[i], b.vertices[i]) != 0) return false;
  return true;
}

// The counts of a mesh with v vertices, e edges and f triangles (Euler characteristic v - e + f).
inline MeshCounts counts(std::size_t v, std::size_t e, std::size_t f) {
  return {v, e, f, static_cast<long long>(v) - static_cast<long long>(e) + static_cast<long long>(f)};
}

}  // namespace tritri_test::arrangement
