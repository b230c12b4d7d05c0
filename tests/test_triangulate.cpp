// Specification of the triangulation stage (arrangements/triangulate.h) and of the
// arrangement it produces (arrange.h, output_mesh.h), checked exactly (rationals from
// tritri::to_exact, exact predicates; no tolerance anywhere):
//  1. output triangles meet only in shared vertices and shared edges (check_arrangement,
//     and an independent all-pairs classification for small scenes);
//  2. every output triangle lies in its source triangle, and per input triangle the
//     output triangles covering it tile it exactly (areas as rationals); owner and label
//     set follow from which input triangles cover it;
//  3. every intersection point is an output vertex and every constraint segment is a
//     chain of output edges;
//  4. simplex counts and Euler characteristics derived by hand;
//  5. the output does not depend on the thread count;
//  6. known upstream failure modes (unreferenced vertices, unknown extensions, tiny
//     coordinates, coplanar edge-edge crossings);
//  7. labels and provenance of coplanar overlaps.
// Sizes scale with TRITRI_TEST_SCALE (default 1; sanitizer runs use 0.1).
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <tritri/classify.h>
#include <tritri/implicit_kernel.h>
#include <tritri/implicit_point.h>
#include <tritri/implicit_predicates.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <unistd.h>
#include <utility>
#include <vector>

#include "pipeline.h"
#include "stages/2_candidate_pairs.h"
#include "arrangements/check_arrangement.h"
#include "stages/3_classify_pairs.h"
#include "arrangements/input_error.h"
#include "stages/4_intersection_graph.h"
#include "arrangements/load_triangle_soup.h"
#include "support/mesh_counts.h"
#include "support/mesh_generators.h"
#include "arrangements/output_mesh.h"
#include "stages/1_preprocess.h"
#include "arrangements/triangle_soup.h"
#include "stages/5_triangulate.h"
#include "arrangements/write_mesh.h"
#include "support/shared_meshes.h"

namespace {

namespace fs = std::filesystem;
using namespace arrangements;
using tritri::ImplicitPoint;
using Q = mpq_class;
using Q3 = std::array<Q, 3>;

constexpr Classifier kClassifiers[] = {Classifier::Native, Classifier::Tritri};

const char* name_of(Classifier c) { return c == Classifier::Native ? "native" : "tritri"; }

double test_scale() {
  const char* s = std::getenv("TRITRI_TEST_SCALE");
  const double v = s ? std::atof(s) : 1.0;
  return v > 0 ? v : 1.0;
}

// ---------------------------------------------------------------------------------------
// Exact arithmetic on rational coordinates (independent of the library's predicates).

Q3 exact(const ImplicitPoint& p) {
  const auto q = tritri::to_exact(p);
  return {Q(q[0].mpq()), Q(q[1].mpq()), Q(q[2].mpq())};
}
Q3 exact(const Vec3& v) { return {Q(v[0]), Q(v[1]), Q(v[2])}; }

Q3 sub(const Q3& a, const Q3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Q3 cross(const Q3& a, const Q3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Q dot(const Q3& a, const Q3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
bool is_zero(const Q3& a) { return sgn(a[0]) == 0 && sgn(a[1]) == 0 && sgn(a[2]) == 0; }

int orient3d(const Q3& a, const Q3& b, const Q3& c, const Q3& d) {
  return sgn(dot(cross(sub(b, a), sub(c, a)), sub(d, a)));
}
// Twice the signed area of (a, b, c) projected along `axis` (coordinates axis+1, axis+2).
Q area2(const Q3& a, const Q3& b, const Q3& c, int axis) {
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  return (b[i] - a[i]) * (c[j] - a[j]) - (b[j] - a[j]) * (c[i] - a[i]);
}
// An axis along which the (non-degenerate) triangle's projection is not degenerate.
int projection_axis(const Q3& a, const Q3& b, const Q3& c) {
  const Q3 n = cross(sub(b, a), sub(c, a));
  int best = -1;
  for (int k = 0; k < 3; ++k)
    if (sgn(n[k]) != 0 && (best < 0 || abs(n[k]) > abs(n[best]))) best = k;
  return best;
}
// p in the closed triangle (a, b, c), all four coplanar, in the projection along `axis`.
bool in_closed_triangle(const Q3& a, const Q3& b, const Q3& c, const Q3& p, int axis) {
  const int s = sgn(area2(a, b, c, axis));
  return sgn(area2(a, b, p, axis)) * s >= 0 && sgn(area2(b, c, p, axis)) * s >= 0 &&
         sgn(area2(c, a, p, axis)) * s >= 0;
}
// p strictly inside segment (a, b).
bool strictly_inside_segment(const Q3& a, const Q3& b, const Q3& p) {
  const Q3 d = sub(b, a);
  return is_zero(cross(d, sub(p, a))) && sgn(dot(sub(p, a), d)) > 0 && sgn(dot(sub(b, p), d)) > 0;
}

std::string str(const Q3& p) { return "(" + p[0].get_str() + ", " + p[1].get_str() + ", " + p[2].get_str() + ")"; }

// ---------------------------------------------------------------------------------------
// Scenes.

// A soup written by hand: one label set per triangle index in `labels` (default all 0 with
// label_sets {{0}}), `source` defaults to the triangle index.
TriangleSoup hand_soup(std::vector<Vec3> vertices, std::vector<Tri> triangles, std::vector<int> labels = {},
                       std::vector<LabelSet> label_sets = {{0}}, std::vector<std::int64_t> source = {}) {
  TriangleSoup s;
  s.vertices = std::move(vertices);
  s.triangles = std::move(triangles);
  s.label_set = labels.empty() ? std::vector<int>(s.triangles.size(), 0) : std::move(labels);
  s.label_sets = std::move(label_sets);
  if (source.empty())
    for (std::size_t i = 0; i < s.triangles.size(); ++i) source.push_back(static_cast<std::int64_t>(i));
  s.source = std::move(source);
  return s;
}

TriangleSoup scaled(TriangleSoup s, double factor) {
  for (Vec3& v : s.vertices)
    for (double& x : v) x *= factor;
  return s;
}
TriangleSoup scaled_pow2(TriangleSoup s, int k) {
  for (Vec3& v : s.vertices)
    for (double& x : v) x = std::ldexp(x, k);
  return s;
}

// A in z = 0; B in the plane y = 1 crosses A along (1,1,0)-(2,1,0): each end is a crossing
// of an edge of B with the interior of A.
TriangleSoup two_triangles_crossing() {
  return hand_soup({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, -1}, {3, 1, -1}, {1, 1, 1}}, {{0, 1, 2}, {3, 4, 5}},
                   {0, 1}, {{0}, {1}});
}

// B pierces A: the intersection runs from p = (1,1,0) (B's edge (1,1,-1)-(1,1,1) through
// A's interior) to q = (3,1,0) (A's edge x + y = 4 through B's interior).
TriangleSoup triangle_pierced() {
  return hand_soup({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, -1}, {1, 1, 1}, {6, 1, 0.5}}, {{0, 1, 2}, {3, 4, 5}},
                   {0, 1}, {{0}, {1}});
}

// Three triangles in the planes z = 0 (A), y = 0 (B), x = 0 (C), each crossing the other
// two, all three through the origin O (inside each). On the axes:
//   x: A covers [-1, 3], B [-2, 2]: A n B = [-1, 2] x {0} x {0}, -1 on A's edge, 2 on B's;
//   y: A covers [-1, 3], C [-2, 1]: A n C = [-1, 1], -1 on A's edge, 1 on C's;
//   z: B covers [-1, 2], C [-2, 1]: B n C = [-1, 1], -1 on B's edge, 1 on C's.
// In each triangle the two segments cross at O: one TPI.
TriangleSoup three_triangles_triple_point() {
  return hand_soup({{-1, -1, 0}, {4, -1, 0}, {-1, 4, 0},    // A: x >= -1, y >= -1, x + y <= 3
                    {-2, 0, -1}, {3, 0, -1}, {-2, 0, 4},    // B: x >= -2, z >= -1, x + z <= 2
                    {0, -2, -2}, {0, 3, -2}, {0, -2, 3}},  // C: y >= -2, z >= -2, y + z <= 1
                   {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}}, {0, 1, 2}, {{0}, {1}, {2}});
}

// Three spheres, centres near an equilateral triangle of side 1, radii near 1: every two
// cross in one closed curve, and all three meet in two triple points (near
// (0.5, 0.29, +-0.82)).
TriangleSoup three_spheres(int rings = 10) {
  return concatenate(concatenate(uv_sphere({0, 0, 0}, 1.0, rings, rings + 4),
                                 uv_sphere({1, 0.05, 0.02}, 0.95, rings - 1, rings + 3)),
                     uv_sphere({0.45, 0.85, -0.03}, 1.05, rings + 1, rings + 2));
}

TriangleSoup two_spheres() {
  return concatenate(uv_sphere({0, 0, 0}, 1.0, 10, 16), uv_sphere({0.7, 0.3, 0.2}, 0.8, 9, 14));
}
TriangleSoup cube_through_cube() { return concatenate(box({0, 0, 0}, {2, 2, 2}), box({1, -1, 0.5}, {3, 3, 1.5})); }
TriangleSoup coplanar_grids() { return concatenate(grid(6, 1.0, 0.0), grid(5, 1.0, 0.0, 0.5, 0.25)); }
TriangleSoup grids_sharing_cells() { return concatenate(grid(4, 1.0, 0.0), grid(4, 1.0, 0.0, 1.0, 0.0)); }
TriangleSoup grid_through_sphere() {
  return concatenate(grid(8, 0.25, 0.0, -1, -1), uv_sphere({0, 0, 0}, 0.9, 8, 12));
}

// Two squares [0,2]^2 and [1,3]^2 in z = 0, two triangles each, with their diagonals on
// the same line y = x; labels 0 and 1, sources 100, 101 and 200, 201.
TriangleSoup overlapping_squares() {
  return hand_soup({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}},
                   {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}}, {0, 0, 1, 1}, {{0}, {1}}, {100, 101, 200, 201});
}

// Two coplanar triangles T0 = (0,0),(4,0),(0,4) (label 0, source 100) and T1 = (1,1),(5,1),
// (1,5) (label 1, source 200) in z = 0; `t1_first` lists T1 first.
TriangleSoup overlapping_triangles(bool t1_first) {
  std::vector<Vec3> V = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0}, {5, 1, 0}, {1, 5, 0}};
  if (t1_first) return hand_soup(V, {{3, 4, 5}, {0, 1, 2}}, {0, 1}, {{1}, {0}}, {200, 100});
  return hand_soup(V, {{0, 1, 2}, {3, 4, 5}}, {0, 1}, {{0}, {1}}, {100, 200});
}

// A star of David (two coplanar triangles whose edges cross in six points) in the plane
// z = cz + ax x + ay y, from 2D corners.
struct Star {
  std::array<std::array<double, 2>, 6> corners;  // A = 0, 1, 2; B = 3, 4, 5
  double cz, ax, ay;
  Vec3 lift(const std::array<double, 2>& p) const { return {p[0], p[1], cz + ax * p[0] + ay * p[1]}; }
  TriangleSoup soup() const {
    std::vector<Vec3> V;
    for (const auto& c : corners) V.push_back(lift(c));
    return hand_soup(V, {{0, 1, 2}, {3, 4, 5}}, {0, 1}, {{0}, {1}}, {100, 200});
  }
};
// Integer corners; crossings (4,0), (8,0), (4,8), (8,8), (2,4), (10,4).
const Star kIntegerStar{{{{0, 0}, {12, 0}, {6, 12}, {0, 8}, {6, -4}, {12, 8}}}, 0, 1, 2};
// Dyadic corners, non-dyadic crossings (21/20, 7/4), ...: the LPIs are not doubles.
const Star kRationalStar{{{{0, 0}, {3, 0}, {1.5, 2.5}, {0, 1.75}, {1.5, -0.75}, {3, 1.75}}}, 1, 0.25, -0.5};

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

Triangulated in_graph_numbering(const TriangleSoup& soup, const IntersectionGraph& g, const OutputMesh& mesh,
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

struct Pipeline {
  TriangleSoup soup;  // preprocessed
  IntersectionGraph graph;
  Triangulated tr;
};

Pipeline run_pipeline(const TriangleSoup& input, Classifier classifier) {
  Pipeline p;
  PreprocessStats stats;
  p.soup = preprocess(input, PreprocessOptions{}, stats);
  const auto& V = p.soup.vertices;
  const auto& F = p.soup.triangles;
  const auto records = classify_pairs(V, F, candidate_pairs(V, F), classifier);
  p.graph = build_intersection_graph(V, F, records);
  TriangulationInfo info;
  const OutputMesh mesh = triangulate(p.soup, p.graph, 0, info);
  p.tr = in_graph_numbering(p.soup, p.graph, mesh, info);
  return p;
}

ArrangeResult run_arrange(const TriangleSoup& input, Classifier classifier, int threads = 0, bool scale = false) {
  ArrangeOptions o;
  o.classifier = classifier;
  o.threads = threads;
  o.scale = scale;
  return arrange(input, o);
}

// ---------------------------------------------------------------------------------------
// Independent validity check (item 1): every pair of output triangles classified with
// tritri on the implicit points; the only contact allowed is vertex-on-vertex at a vertex
// both triangles name by the same id (so a shared vertex or a shared edge). Also: no two
// vertices at one position, no degenerate triangle. Quadratic: small meshes only.
using Problems = std::vector<std::string>;

void expect_no_problems(const Problems& problems, const std::string& what) {
  EXPECT_TRUE(problems.empty()) << what << ": " << problems.size() << " problems";
  for (std::size_t i = 0; i < problems.size() && i < 8; ++i) ADD_FAILURE() << what << ": " << problems[i];
}
bool mentions(const Problems& problems, const std::string& word) {
  for (const std::string& p : problems)
    if (p.find(word) != std::string::npos) return true;
  return false;
}

Problems all_pairs_problems(const std::vector<ImplicitPoint>& P, const std::vector<Tri>& F) {
  Problems out;
  std::vector<int> used;
  for (const Tri& t : F) used.insert(used.end(), t.begin(), t.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::set<Q3> positions;
  for (int v : used)
    if (!positions.insert(exact(P[v])).second) out.push_back("two vertices at " + str(exact(P[v])));
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
// Item 2: containment, tiling by exact areas, owner and labels, for the direct pipeline.
//
// An output triangle t is covered by a soup triangle u when t's three vertices lie in u's
// plane and in the closed u (then t, their convex hull, lies in u). In an arrangement
// every input triangle is exactly the union of the output triangles it covers (the output
// triangles covering u tile u, overlapping only on edges), so per u the projected areas
// of those output triangles sum exactly to u's projected area. The owner of t is the
// smallest covering triangle, and t's label set is the union of the covering triangles'.
Problems tiling_problems(const Pipeline& p) {
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
        fail("output triangle " + std::to_string(t) + " vertex " + str(X[T[k]]) + " is not in the plane of its owner " +
             std::to_string(o));
      else if (!in_closed_triangle(U[o][0], U[o][1], U[o][2], X[T[k]], axis[o]))
        fail("output triangle " + std::to_string(t) + " vertex " + str(X[T[k]]) + " is outside its owner " +
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
// Item 3: the intersection graph survives in the output. Every point of the graph and
// every TPI is a vertex of an output triangle; every constraint segment (a, b) is a chain
// of output edges a = v0, v1, ..., vk = b, each v(i+1) the only neighbour of v(i) that lies
// on the segment strictly between v(i) and b... (at least one such neighbour is required,
// the nearest is taken; a valid arrangement has exactly one).
Problems graph_problems(const Pipeline& p) {
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

void expect_stats_match_mesh(const ArrangeResult& r, const std::string& what) {
  const MeshCounts c = mesh_counts(r.mesh.triangles);
  EXPECT_EQ(r.stats.out_vertices, c.vertices) << what;
  EXPECT_EQ(r.stats.out_edges, c.edges) << what;
  EXPECT_EQ(r.stats.out_triangles, c.triangles) << what;
  EXPECT_EQ(r.stats.euler, c.euler) << what;
  EXPECT_EQ(r.mesh.vertices.size(), c.vertices) << what << ": unreferenced output vertices";
  EXPECT_EQ(r.mesh.source.size(), r.mesh.triangles.size()) << what;
  EXPECT_EQ(r.mesh.label_set.size(), r.mesh.triangles.size()) << what;
}

bool same_output(const OutputMesh& a, const OutputMesh& b) {
  if (a.triangles != b.triangles || a.source != b.source || a.label_set != b.label_set ||
      a.label_sets != b.label_sets || a.vertices.size() != b.vertices.size())
    return false;
  for (std::size_t i = 0; i < a.vertices.size(); ++i)
    if (compare_xyz(a.vertices[i], b.vertices[i]) != 0) return false;
  return true;
}

// The scenes of the whole-arrangement checks; the two largest shrink below scale 0.5.
std::vector<std::pair<std::string, TriangleSoup>> generated_scenes() {
  const bool full = test_scale() >= 0.5;
  return {
      {"two triangles crossing", two_triangles_crossing()},
      {"triangle pierced", triangle_pierced()},
      {"two spheres", two_spheres()},
      {"cube through cube", cube_through_cube()},
      {"coplanar grids", coplanar_grids()},
      {"grids sharing cells", grids_sharing_cells()},
      {"grid through sphere", grid_through_sphere()},
      {"overlapping squares", overlapping_squares()},
      {"star of David", kIntegerStar.soup()},
      {"rational star", kRationalStar.soup()},
      {"rotated spheres", full ? rotated_copies(uv_sphere({0, 0, 0}, 1.0, 6, 10), 4)
                                : rotated_copies(uv_sphere({0, 0, 0}, 1.0, 4, 6), 3)},
      {"three triangles, triple point", three_triangles_triple_point()},
      {"three spheres", three_spheres(full ? 10 : 6)},
      {"rotated boxes", rotated_copies(box({0, 0, 0}, {2, 1, 1}), 4)},
      {"rotated grids", rotated_copies(grid(4, 1.0, 0.0), 3)},
  };
}

// =======================================================================================
// 1. Triangles meet only in shared vertices and edges.

TEST(Arrangement, GeneratedScenesPassCheckArrangement) {
  for (const auto& [name, soup] : generated_scenes()) {
    const ArrangeResult native = run_arrange(soup, Classifier::Native);
    const ArrangeResult tritri = run_arrange(soup, Classifier::Tritri);
    for (const ArrangeResult* r : {&native, &tritri}) {
      expect_stats_match_mesh(*r, name);
      if (r == &tritri && same_output(tritri.mesh, native.mesh)) continue;  // checked already
      const ArrangementCheck check = check_arrangement(r->mesh);
      EXPECT_TRUE(check.ok()) << name << " (" << r->stats.classifier << "): " << check.violations << " violations, "
                              << check.degenerate_triangles << " degenerate; "
                              << (check.examples.empty() ? "" : check.examples.front());
      EXPECT_GT(check.pairs_checked, 0u) << name;
    }
  }
}

TEST(Arrangement, SmallScenesPassIndependentAllPairsCheck) {
  for (const auto& [name, soup] :
       std::vector<std::pair<std::string, TriangleSoup>>{{"two triangles crossing", two_triangles_crossing()},
                                                         {"triangle pierced", triangle_pierced()},
                                                         {"cube through cube", cube_through_cube()},
                                                         {"overlapping squares", overlapping_squares()},
                                                         {"overlapping triangles", overlapping_triangles(false)},
                                                         {"star of David", kIntegerStar.soup()},
                                                         {"rational star", kRationalStar.soup()},
                                                         {"grids sharing cells", grids_sharing_cells()},
                                                         {"rotated grids", rotated_copies(grid(2, 1.0, 0.0), 3)},
                                                         {"small spheres", concatenate(uv_sphere({0, 0, 0}, 1, 4, 6),
                                                                                       uv_sphere({0.5, 0.2, 0.1}, 0.9, 5, 5))}})
    for (Classifier c : kClassifiers) {
      const ArrangeResult r = run_arrange(soup, c);
      expect_no_problems(all_pairs_problems(r.mesh.vertices, r.mesh.triangles), name + " (" + name_of(c) + ")");
    }
}

// The checker itself must be able to fail: an overlapping pair, a crossing pair and two
// vertices at one position are refused.
TEST(Arrangement, IndependentCheckRefusesBadMeshes) {
  auto P = [](double x, double y, double z) { return ImplicitPoint::explicit_point(x, y, z); };
  // Two coplanar triangles overlapping (sharing an edge, folded onto the same side).
  const std::vector<ImplicitPoint> pts = {P(0, 0, 0), P(4, 0, 0), P(0, 4, 0), P(1, 1, 0), P(0, 0, 0)};
  EXPECT_TRUE(mentions(all_pairs_problems(pts, {{0, 1, 2}, {0, 1, 3}}), "improperly"));
  // Same position under two ids.
  EXPECT_TRUE(mentions(all_pairs_problems(pts, {{0, 1, 2}, {4, 2, 1}}), "two vertices"));
  // A proper pair sharing an edge passes.
  std::vector<ImplicitPoint> fine = pts;
  fine.push_back(P(2, -2, 0));
  EXPECT_TRUE(all_pairs_problems(fine, {{0, 1, 2}, {1, 0, 5}}).empty());
  OutputMesh m;
  m.vertices = pts;
  m.triangles = {{0, 1, 2}, {0, 1, 3}};
  EXPECT_FALSE(check_arrangement(m).ok());
}

// Every shared mesh up to a size limit, both classifiers.
TEST(Arrangement, SharedMeshesPassCheckArrangement) {
  const fs::path dir = tritri_test::shared_meshes_dir();
  TRITRI_REQUIRE_DATA(dir);
  const std::size_t max_triangles = static_cast<std::size_t>(20000 * test_scale());
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::string ext = entry.path().extension().string();
    for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (ext == ".obj" || ext == ".off" || ext == ".stl" || ext == ".ply") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  // Below scale 1, every n-th file only (n about 1 / scale), so sanitizer runs stay short.
  const std::size_t every = test_scale() < 1 ? static_cast<std::size_t>(std::lround(1 / test_scale())) : 1;
  std::size_t eligible = 0;
  int arranged = 0, refused = 0, skipped = 0, skipped_check = 0;
  for (const fs::path& f : files) {
    TriangleSoup input;
    try {
      input = load_triangle_soup(f.string());
    } catch (const InputError&) {
      ++refused;  // bad files of the collection: test_load_triangle_soup's business
      continue;
    }
    if (input.triangles.size() > max_triangles || eligible++ % every != 0) {
      ++skipped;
      continue;
    }
    // Both classifiers; the (costly) check runs once when they give the same output.
    std::vector<ArrangeResult> results;
    for (Classifier c : kClassifiers) {
      results.push_back(run_arrange(input, c));  // valid input is never refused
    }
    for (std::size_t i = 0; i < results.size(); ++i) {
      const ArrangeResult& r = results[i];
      expect_stats_match_mesh(r, f.string());
      if (i > 0 && same_output(r.mesh, results[0].mesh)) continue;
      if (r.mesh.triangles.size() > max_triangles) {  // the check costs by output size
        ++skipped_check;
        continue;
      }
      const ArrangementCheck check = check_arrangement(r.mesh);
      EXPECT_TRUE(check.ok()) << f << " (" << r.stats.classifier << "): " << check.violations << " violations, "
                              << check.degenerate_triangles << " degenerate; "
                              << (check.examples.empty() ? "" : check.examples.front());
    }
    ++arranged;
  }
  EXPECT_GT(arranged, 0);
  std::printf("arranged %d shared meshes (%d outputs too large to check), refused %d, skipped (size or sampling) %d\n",
              arranged, skipped_check, refused, skipped);
}

// =======================================================================================
// 2. Output triangles lie in their sources and tile them.

TEST(Triangulate, OutputTrianglesTileTheirSourcesExactly) {
  for (const auto& [name, soup] : generated_scenes()) {
    if (name.rfind("rotated", 0) == 0) continue;  // covered below at a smaller size
    for (Classifier c : kClassifiers)
      expect_no_problems(tiling_problems(run_pipeline(soup, c)), name + " (" + name_of(c) + ")");
  }
  expect_no_problems(tiling_problems(run_pipeline(rotated_copies(uv_sphere({0, 0, 0}, 1.0, 5, 6), 3), Classifier::Tritri)),
                       "rotated spheres");
  expect_no_problems(tiling_problems(run_pipeline(rotated_copies(box({0, 0, 0}, {2, 1, 1}), 4), Classifier::Tritri)), "rotated boxes");
  expect_no_problems(tiling_problems(run_pipeline(rotated_copies(grid(3, 1.0, 0.0), 3), Classifier::Tritri)), "rotated grids");
  expect_no_problems(tiling_problems(run_pipeline(overlapping_triangles(true), Classifier::Native)), "overlapping triangles");
}

// Coplanar overlaps are emitted once: the total area is the area of the union, by hand.
TEST(Triangulate, CoplanarOverlapIsEmittedOnce) {
  struct Case {
    std::string name;
    TriangleSoup soup;
    Q union_area2;  // twice the area of the union in the XY projection
  };
  const std::vector<Case> cases = {
      {"overlapping squares", overlapping_squares(), Q(2 * 7)},           // 4 + 4 - 1
      {"overlapping triangles", overlapping_triangles(false), Q(2 * 14)},  // 8 + 8 - 2
      {"coplanar grids", coplanar_grids(), Q(2 * 36)},                    // the second grid is inside the first
      {"grids sharing cells", grids_sharing_cells(), Q(2 * 20)},          // [0,5] x [0,4]
      {"star of David", kIntegerStar.soup(), Q(2 * 96)},                  // 72 + 72 - 48 (hexagon)
  };
  for (const auto& cs : cases)
    for (Classifier c : kClassifiers) {
      const ArrangeResult r = run_arrange(cs.soup, c);
      Q total = 0;
      for (const Tri& t : r.mesh.triangles)
        total += abs(area2(exact(r.mesh.vertices[t[0]]), exact(r.mesh.vertices[t[1]]), exact(r.mesh.vertices[t[2]]), 2));
      EXPECT_EQ(total, cs.union_area2) << cs.name << " (" << name_of(c) << ")";
    }
}

// The tiling check must be able to fail: a triangulation with a triangle moved out of its
// source, or with a triangle missing, is refused.
TEST(Triangulate, TilingCheckRefusesWrongOutput) {
  Pipeline p = run_pipeline(two_triangles_crossing(), Classifier::Tritri);
  Pipeline missing = p;
  missing.tr.triangles.pop_back();
  missing.tr.owner.pop_back();
  missing.tr.label_set.pop_back();
  EXPECT_TRUE(mentions(tiling_problems(missing), "covered area"));
  Pipeline wrong_owner = p;
  wrong_owner.tr.owner[0] = 1 - wrong_owner.tr.owner[0];
  EXPECT_TRUE(mentions(tiling_problems(wrong_owner), "owner"));
  EXPECT_TRUE(tiling_problems(p).empty());
}

// The small hand-made configurations of the shared collection (2 and 3 triangles touching
// in every degenerate way) and its two_spheres / three_cubes: tiling, graph and an
// independent all-pairs check of the output.
TEST(Triangulate, SmallSharedConfigurationsPassAllExactChecks) {
  const fs::path dir = tritri_test::shared_meshes_dir() / "cherchi_arrangements";
  TRITRI_REQUIRE_DATA(dir);
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  int checked = 0;
  for (const fs::path& f : files) {
    const std::string ext = f.extension().string();
    if (ext != ".off" && ext != ".stl") continue;
    const TriangleSoup input = load_triangle_soup(f.string());
    if (input.triangles.size() > static_cast<std::size_t>(4000 * test_scale())) continue;
    for (Classifier c : kClassifiers) {
      const std::string what = f.filename().string() + " (" + name_of(c) + ")";
      const Pipeline p = run_pipeline(input, c);
      expect_no_problems(tiling_problems(p), what);
      expect_no_problems(graph_problems(p), what);
      if (p.tr.triangles.size() <= 400) expect_no_problems(all_pairs_problems(p.tr.points, p.tr.triangles), what);
    }
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

// =======================================================================================
// 3. Intersection points are output vertices; constraints are chains of output edges.

TEST(Triangulate, GraphPointsAndConstraintsAreInTheOutput) {
  for (const auto& [name, soup] : generated_scenes())
    for (Classifier c : kClassifiers)
      expect_no_problems(graph_problems(run_pipeline(soup, c)), name + " (" + name_of(c) + ")");
}

// The check must be able to fail: drop the output triangles at one intersection point.
TEST(Triangulate, GraphCheckRefusesMissingPieces) {
  Pipeline p = run_pipeline(two_triangles_crossing(), Classifier::Tritri);
  ASSERT_TRUE(graph_problems(p).empty());
  const int lpi = p.graph.num_input_vertices;  // the first intersection point
  Pipeline cut = p;
  cut.tr.triangles.clear();
  for (const Tri& t : p.tr.triangles)
    if (t[0] != lpi && t[1] != lpi && t[2] != lpi) cut.tr.triangles.push_back(t);
  const Problems problems = graph_problems(cut);
  EXPECT_TRUE(mentions(problems, "not an output vertex"));
  EXPECT_TRUE(mentions(problems, "chain of output edges"));
}

// And through arrange(): every graph point's exact position is an output vertex.
TEST(Arrange, KeptGraphPointsAreOutputVertices) {
  for (const auto& [name, soup] : generated_scenes()) {
    PipelineInternals kept;
    const ArrangeResult r = run_pipeline(soup, ArrangeOptions{}, &kept);
    std::set<Q3> out;
    for (const ImplicitPoint& v : r.mesh.vertices) out.insert(exact(v));
    for (std::size_t i = kept.graph.num_input_vertices; i < kept.graph.points.size(); ++i)
      EXPECT_EQ(out.count(exact(kept.graph.points[i])), 1u) << name << ": intersection point " << i;
    for (const Vec3& v : kept.soup.vertices) EXPECT_EQ(out.count(exact(v)), 1u) << name << ": input vertex";
    // Provenance maps back to the input numbering: the output triangle lies in the input
    // triangle whose source is source[t] (coplanar and inside, exactly).
    std::map<std::int64_t, std::size_t> by_source;
    for (std::size_t i = 0; i < soup.source.size(); ++i) by_source[soup.source[i]] = i;
    for (std::size_t t = 0; t < r.mesh.triangles.size(); ++t) {
      ASSERT_TRUE(by_source.count(r.mesh.source[t])) << name << ": unknown source " << r.mesh.source[t];
      const Tri& in = soup.triangles[by_source.at(r.mesh.source[t])];
      const Q3 a = exact(soup.vertices[in[0]]), b = exact(soup.vertices[in[1]]), c = exact(soup.vertices[in[2]]);
      const int axis = projection_axis(a, b, c);
      for (int v : r.mesh.triangles[t]) {
        const Q3 x = exact(r.mesh.vertices[v]);
        EXPECT_TRUE(orient3d(a, b, c, x) == 0 && in_closed_triangle(a, b, c, x, axis))
            << name << ": output triangle " << t << " is not in input triangle " << r.mesh.source[t];
      }
    }
  }
}

// =======================================================================================
// 4. Counts and Euler characteristics by hand.
//
// A triangulated polygon (a disc) with B boundary and I interior vertices and no other
// vertices has F = 2I + B - 2 triangles and E = 3I + 2B - 3 edges, whatever the
// triangulation (V - E + F = 1 and 3F + B = 2E). Gluing complexes: chi(X u Y) = chi(X) +
// chi(Y) - chi(X n Y).

MeshCounts counts(std::size_t v, std::size_t e, std::size_t f) {
  return {v, e, f, static_cast<long long>(v) - static_cast<long long>(e) + static_cast<long long>(f)};
}

TEST(Arrange, CountsOfSmallConfigurationsByHand) {
  struct Case {
    std::string name;
    TriangleSoup soup;
    MeshCounts expected;
    std::size_t tpi = 0;  // constraints crossing inside a triangle
  };
  const std::vector<Case> cases = {
      // A gets 2 interior points joined by a constraint: B = 3, I = 2: 5 triangles, 9 edges.
      // B gets 2 edge points joined by a constraint: B = 5, I = 0: 3 triangles, 7 edges.
      // Shared: the 2 points and the edge between them. V = 3 + 3 + 2, E = 9 + 7 - 1.
      {"two triangles crossing", two_triangles_crossing(), counts(8, 15, 8)},
      // A: q on an edge, p inside: B = 4, I = 1: 4 triangles, 8 edges; B: p on an edge, q
      // inside: also 4 and 8. V = 8, E = 8 + 8 - 1, F = 8.
      {"triangle pierced", triangle_pierced(), counts(8, 15, 8)},
      // The union is one disc: boundary (0,0) (2,0) (2,1) (3,1) (3,3) (1,3) (1,2) (0,2),
      // B = 8; inside (1,1) and (2,2), I = 2: F = 10, E = 19.
      {"overlapping squares", overlapping_squares(), counts(10, 19, 10)},
      // Union boundary (0,0) (4,0) (3,1) (5,1) (1,5) (1,3) (0,4), B = 7; (1,1) inside:
      // F = 7, E = 14.
      {"overlapping triangles", overlapping_triangles(false), counts(8, 14, 7)},
      // Hexagram: 6 corners + 6 crossings on the boundary, no interior vertex: F = 10,
      // E = 21 (6 tips + the hexagon in 4 triangles; 12 outer edges, 6 hexagon sides, 3
      // diagonals).
      {"star of David", kIntegerStar.soup(), counts(12, 21, 10)},
      {"rational star", kRationalStar.soup(), counts(12, 21, 10)},
      // One closed uv sphere with r rings and s segments, nothing to split: V = 2 + (r-1)s,
      // F = 2s(r-1), E = 3s(r-1). r = 6, s = 8.
      {"one sphere", uv_sphere({0, 0, 0}, 1, 6, 8), counts(42, 120, 80)},
      // Each triangle: 3 corners and 2 segment ends on its boundary (B = 5), one segment end
      // inside, the other segment's far end inside, and O inside (I = 3): 9 triangles, 16
      // edges. V = 9 corners + 6 segment ends + O = 16; the 3 segments, each cut by O into 2
      // edges, are shared by two triangles: E = 3 * 16 - 6 = 42; F = 27. chi = 1 =
      // 3 discs - 3 segments + 1 point. O is one TPI, whatever triangle builds it.
      {"three triangles, triple point", three_triangles_triple_point(), counts(16, 42, 27), 1},
  };
  for (const auto& cs : cases)
    for (Classifier c : kClassifiers) {
      const ArrangeResult r = run_arrange(cs.soup, c);
      expect_stats_match_mesh(r, cs.name);
      EXPECT_EQ(mesh_counts(r.mesh.triangles), cs.expected)
          << cs.name << " (" << name_of(c) << "): got V " << r.stats.out_vertices << " E " << r.stats.out_edges << " F "
          << r.stats.out_triangles;
      EXPECT_EQ(r.stats.tpi, cs.tpi) << cs.name << " (" << name_of(c) << ")";
    }
}

TEST(Arrange, EulerCharacteristicsByHand) {
  struct Case {
    std::string name;
    TriangleSoup soup;
    long long euler;
  };
  const std::vector<Case> cases = {
      // Two closed surfaces (spheres, chi = 2 each) crossing transversally along one closed
      // polygon C (chi(C) = 0, as many vertices as edges): the output is the two subdivided
      // spheres glued along C, chi = 2 + 2 - 0.
      {"two spheres", two_spheres(), 4},
      // The second box enters the first through its faces y = 0 and y = 2 and leaves through
      // x = 2; the surfaces meet in one closed loop (1,0,.5) (1,0,1.5) (2,0,1.5) (2,2,1.5)
      // (1,2,1.5) (1,2,.5) (2,2,.5) (2,0,.5): again 2 + 2 - 0.
      {"cube through cube", cube_through_cube(), 4},
      // The plane of the grid (a disc, chi = 1) cuts the sphere (chi = 2) in one closed
      // polygon around the equator inside the grid's square: 1 + 2 - 0.
      {"grid through sphere", grid_through_sphere(), 3},
      // Coplanar grids: the output is the triangulated union, a square (disc): 1.
      {"coplanar grids", coplanar_grids(), 1},
      {"grids sharing cells", grids_sharing_cells(), 1},
      // Three spheres: chi = 3 * 2 - 3 circles (0 each) + 2 triple points.
      {"three spheres", three_spheres(), 8},
      // Two disjoint spheres: 2 + 2.
      {"disjoint spheres", concatenate(uv_sphere({0, 0, 0}, 1, 5, 7), uv_sphere({3, 0, 0}, 1, 5, 7)), 4},
  };
  for (const auto& cs : cases)
    for (Classifier c : kClassifiers) {
      const ArrangeResult r = run_arrange(cs.soup, c);
      expect_stats_match_mesh(r, cs.name);
      EXPECT_EQ(r.stats.euler, cs.euler) << cs.name << " (" << name_of(c) << ")";
    }
}

// The triple point: one TPI at exactly (0, 0, 0), the segment ends exact LPIs on the axes.
// Three spheres: each of the two triple points lies inside one triangle of each sphere
// (generic position), where two constraints cross: two TPIs.
TEST(Arrange, TriplePointsAreSingleExactTPIs) {
  const std::set<Q3> ends = {{Q(-1), Q(0), Q(0)}, {Q(2), Q(0), Q(0)}, {Q(0), Q(-1), Q(0)},
                             {Q(0), Q(1), Q(0)},  {Q(0), Q(0), Q(-1)}, {Q(0), Q(0), Q(1)}};
  for (Classifier c : kClassifiers) {
    const Pipeline p = run_pipeline(three_triangles_triple_point(), c);
    std::set<Q3> lpis;
    for (std::size_t i = p.graph.num_input_vertices; i < p.graph.points.size(); ++i) lpis.insert(exact(p.graph.points[i]));
    EXPECT_EQ(lpis, ends) << name_of(c);
    ASSERT_EQ(p.tr.num_tpi, 1u) << name_of(c);
    const ImplicitPoint& o = p.tr.points.back();
    EXPECT_EQ(o.kind(), ImplicitPoint::Kind::TPI) << name_of(c);
    EXPECT_EQ(exact(o), (Q3{Q(0), Q(0), Q(0)})) << name_of(c);
    // O is a vertex of output triangles of all three sources.
    std::set<int> owners;
    for (std::size_t t = 0; t < p.tr.triangles.size(); ++t)
      for (int v : p.tr.triangles[t])
        if (v == static_cast<int>(p.tr.points.size()) - 1) owners.insert(p.tr.owner[t]);
    EXPECT_EQ(owners, (std::set<int>{0, 1, 2})) << name_of(c);
    EXPECT_EQ(run_arrange(three_spheres(), c).stats.tpi, 2u) << name_of(c);
  }
}

// =======================================================================================
// 5. The output does not depend on the number of threads.

void expect_same_output(const OutputMesh& a, const OutputMesh& b, const std::string& what) {
  EXPECT_EQ(a.triangles, b.triangles) << what;
  EXPECT_EQ(a.source, b.source) << what;
  EXPECT_EQ(a.label_set, b.label_set) << what;
  EXPECT_EQ(a.label_sets, b.label_sets) << what;
  ASSERT_EQ(a.vertices.size(), b.vertices.size()) << what;
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.vertices.size(); ++i) differ += compare_xyz(a.vertices[i], b.vertices[i]) != 0;
  EXPECT_EQ(differ, 0u) << what << ": vertices differ";
}

TEST(Arrange, SameOutputForOneAndTwoThreads) {
  const int k = std::max(3, static_cast<int>(6 * test_scale()));
  std::vector<std::pair<std::string, TriangleSoup>> scenes = {
      {"rotated spheres", rotated_copies(uv_sphere({0, 0, 0}, 1.0, 12, 16), k)},
      {"rotated grids", rotated_copies(grid(6, 1.0, 0.0), 4)},
      {"coplanar grids", coplanar_grids()},
  };
  const fs::path dir = tritri_test::shared_meshes_dir();
  for (const char* name : {"cherchi_arrangements/two_spheres.stl", "cherchi_arrangements/three_cubes.stl"})
    if (fs::exists(dir / name)) scenes.emplace_back(name, load_triangle_soup((dir / name).string()));
  for (const auto& [name, soup] : scenes)
    for (Classifier c : kClassifiers) {
      const ArrangeResult one = run_arrange(soup, c, 1);
      const ArrangeResult two = run_arrange(soup, c, 2);
      EXPECT_EQ(one.stats.threads, 1) << name;
      EXPECT_EQ(two.stats.threads, 2) << name;
      EXPECT_GT(one.stats.intersecting_pairs, 0u) << name;
      expect_same_output(one.mesh, two.mesh, name + " (" + name_of(c) + ")");
    }
}

// =======================================================================================
// 6. Known upstream failure modes.

// Upstream crashes when unreferenced vertices outnumber 3x the triangles.
TEST(Arrange, ManyUnreferencedVerticesAreIgnored) {
  // The two crossing triangles (V 8, F 8 by hand, above) plus 8 disjoint triangles far
  // away (copied as they are: 24 vertices), with 1000 unused vertices interleaved.
  TriangleSoup s = two_triangles_crossing();
  for (int i = 0; i < 8; ++i) {
    const int base = static_cast<int>(s.vertices.size());
    s.vertices.push_back({100.0 + 10 * i, 0, 0});
    s.vertices.push_back({101.0 + 10 * i, 0, 0});
    s.vertices.push_back({100.0 + 10 * i, 1, 0});
    s.triangles.push_back({base, base + 1, base + 2});
    s.label_set.push_back(0);
    s.source.push_back(static_cast<std::int64_t>(s.source.size()));
    for (int j = 0; j < 125; ++j) s.vertices.push_back({-50.0 - i, 0.5 * j, 7.25});
  }
  ASSERT_EQ(s.triangles.size(), 10u);
  ASSERT_EQ(s.vertices.size(), 6u + 8 * 128);
  for (Classifier c : kClassifiers) {
    const ArrangeResult r = run_arrange(s, c);
    EXPECT_EQ(r.stats.in_vertices, s.vertices.size());
    EXPECT_EQ(mesh_counts(r.mesh.triangles), counts(8 + 24, 15 + 24, 8 + 8)) << name_of(c);
    EXPECT_EQ(r.mesh.vertices.size(), 32u);
    for (const ImplicitPoint& v : r.mesh.vertices) EXPECT_GE(tritri::to_double(v)[0], -1.0) << "an unused vertex";
    EXPECT_TRUE(check_arrangement(r.mesh).ok());
  }
}

class TempDir {
 public:
  TempDir() : dir_(fs::temp_directory_path() / ("test_triangulate_" + std::to_string(::getpid()))) {
    fs::create_directories(dir_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  fs::path operator/(const std::string& name) const { return dir_ / name; }

 private:
  fs::path dir_;
};

// Upstream crashes on an unknown extension; here it is a clear InputError.
TEST(Arrange, UnknownExtensionsAreInputErrors) {
  TempDir tmp;
  const ArrangeResult r = run_arrange(two_triangles_crossing(), Classifier::Tritri);
  for (const char* name : {"out.stlx", "out", "out.obj.bak", "out.xyz"}) {
    const fs::path path = tmp / name;
    try {
      write_mesh(path.string(), r.mesh);
      ADD_FAILURE() << name << ": no exception";
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind, InputErrorKind::unknown_format) << name << ": " << e.what();
    }
    EXPECT_FALSE(fs::exists(path)) << name;
  }
  // A valid OBJ under unknown names is refused by the loader; under .OBJ it loads.
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  for (const char* name : {"in.xyz", "in.obj2", "in"}) {
    std::ofstream(tmp / name) << obj;
    try {
      load_triangle_soup((tmp / name).string());
      ADD_FAILURE() << name << ": no exception";
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind, InputErrorKind::unknown_format) << name << ": " << e.what();
    }
  }
  std::ofstream(tmp / "in.OBJ") << obj;
  EXPECT_EQ(load_triangle_soup((tmp / "in.OBJ").string()).triangles.size(), 1u);
  // Round trip: what write_mesh writes, load_triangle_soup reads.
  write_mesh((tmp / "out.off").string(), r.mesh);
  EXPECT_EQ(load_triangle_soup((tmp / "out.off").string()).triangles.size(), r.mesh.triangles.size());
}

// Upstream computes its scale with an int shift and gets coordinates below 1 wrong. Scaling
// by 2^k changes no predicate, so the output is the unscaled output times 2^k exactly,
// also with options.scale (arrange.h: the output is in the input's frame).
TEST(Arrange, TinyCoordinatesPowerOfTwo) {
  for (const auto& [name, soup] : std::vector<std::pair<std::string, TriangleSoup>>{
           {"cube through cube", cube_through_cube()},
           {"star of David", kRationalStar.soup()},
           {"two triangles crossing", two_triangles_crossing()}})
    for (Classifier c : kClassifiers) {
      const ArrangeResult ref = run_arrange(soup, c);
      for (int k : {-60, -1000})
        for (bool scale : {false, true}) {
          const std::string what = name + " (" + name_of(c) + ") 2^" + std::to_string(k) + (scale ? " scaled" : "");
          const ArrangeResult r = run_arrange(scaled_pow2(soup, k), c, 0, scale);
          EXPECT_EQ(mesh_counts(r.mesh.triangles), mesh_counts(ref.mesh.triangles)) << what;
          EXPECT_EQ(r.mesh.triangles, ref.mesh.triangles) << what;
          EXPECT_EQ(r.mesh.source, ref.mesh.source) << what;
          ASSERT_EQ(r.mesh.vertices.size(), ref.mesh.vertices.size()) << what;
          // The factor: from the first vertex with a non-zero coordinate, then checked for
          // every coordinate of every vertex.
          Q factor = 0;
          std::size_t mismatches = 0;
          for (std::size_t i = 0; i < ref.mesh.vertices.size(); ++i) {
            const Q3 a = exact(ref.mesh.vertices[i]), b = exact(r.mesh.vertices[i]);
            for (int d = 0; d < 3; ++d) {
              if (sgn(factor) == 0 && sgn(a[d]) != 0) factor = b[d] / a[d];
              mismatches += b[d] != a[d] * factor;
            }
          }
          EXPECT_EQ(mismatches, 0u) << what;
          EXPECT_EQ(factor, Q(std::ldexp(1.0, k))) << what;
        }
    }
}

// Coordinates around 1e-7 (not a power of two: the geometry changes by rounding, but not
// its combinatorics here, which are far from degenerate): still a valid arrangement with
// the same topology.
TEST(Arrange, TinyCoordinatesNotAPowerOfTwo) {
  for (const auto& [name, soup, euler] : std::vector<std::tuple<std::string, TriangleSoup, long long>>{
           {"cube through cube", cube_through_cube(), 4},
           {"two spheres", two_spheres(), 4},
           {"rational star", kRationalStar.soup(), 1}})
    for (Classifier c : kClassifiers)
      for (bool scale : {false, true}) {
        const std::string what = name + " (" + name_of(c) + ")" + (scale ? " scaled" : "");
        const ArrangeResult r = run_arrange(scaled(soup, 1e-7), c, 0, scale);
        const ArrangementCheck check = check_arrangement(r.mesh);
        EXPECT_TRUE(check.ok()) << what << ": " << (check.examples.empty() ? "" : check.examples.front());
        EXPECT_EQ(r.stats.euler, euler) << what;
        EXPECT_EQ(mesh_counts(r.mesh.triangles), mesh_counts(run_arrange(soup, c).mesh.triangles)) << what;
      }
}

// A bug of the authors' tri-tri tool: coplanar edge-edge crossings built as undefined LPIs.
// Here each crossing of the star is an LPI at the exact rational crossing of the two edges
// (computed here in 2D by Cramer's rule, then lifted to the plane), strictly inside both.
TEST(Arrange, CoplanarEdgeCrossingsAreProperLPIs) {
  for (const Star* star : {&kIntegerStar, &kRationalStar}) {
    // The expected crossings: every pair (edge of A, edge of B) whose segments cross
    // properly in 2D (exact signs), at the exact intersection point.
    std::set<Q3> expected;
    std::vector<std::array<Q3, 4>> expected_edges;  // per crossing: its two edges
    auto q2 = [&](int i) { return std::array<Q, 2>{Q(star->corners[i][0]), Q(star->corners[i][1])}; };
    auto o2 = [](const std::array<Q, 2>& a, const std::array<Q, 2>& b, const std::array<Q, 2>& c) {
      return sgn((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    };
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const auto p = q2(i), q = q2((i + 1) % 3), r = q2(3 + j), s = q2(3 + (j + 1) % 3);
        if (o2(p, q, r) * o2(p, q, s) >= 0 || o2(r, s, p) * o2(r, s, q) >= 0) continue;
        // p + t (q - p) on line rs: t = cross(r - p, s - r) / cross(q - p, s - r).
        const Q den = (q[0] - p[0]) * (s[1] - r[1]) - (q[1] - p[1]) * (s[0] - r[0]);
        const Q t = ((r[0] - p[0]) * (s[1] - r[1]) - (r[1] - p[1]) * (s[0] - r[0])) / den;
        const Q x = p[0] + t * (q[0] - p[0]), y = p[1] + t * (q[1] - p[1]);
        const Q3 X{x, y, Q(star->cz) + Q(star->ax) * x + Q(star->ay) * y};
        expected.insert(X);
        auto lift = [&](int k) { return exact(star->lift(star->corners[k])); };
        expected_edges.push_back({lift(i), lift((i + 1) % 3), lift(3 + j), lift(3 + (j + 1) % 3)});
      }
    ASSERT_EQ(expected.size(), 6u) << "the scene is not a star";
    if (star == &kIntegerStar) {  // the derivation agrees with the crossings read off by hand
      EXPECT_TRUE(expected.count({Q(4), Q(0), Q(4)}) && expected.count({Q(8), Q(8), Q(24)}) &&
                  expected.count({Q(2), Q(4), Q(10)}) && expected.count({Q(10), Q(4), Q(18)}));
    }
    for (Classifier c : kClassifiers) {
      ArrangeOptions o;
      o.classifier = c;
      PipelineInternals kept;
      const ArrangeResult r = run_pipeline(star->soup(), o, &kept);
      const IntersectionGraph& g = kept.graph;
      ASSERT_EQ(g.points.size() - g.num_input_vertices, 6u) << name_of(c);
      std::set<Q3> got;
      for (std::size_t i = g.num_input_vertices; i < g.points.size(); ++i) {
        EXPECT_EQ(g.points[i].kind(), ImplicitPoint::Kind::LPI) << name_of(c);
        got.insert(exact(g.points[i]));
      }
      EXPECT_EQ(got, expected) << name_of(c);
      for (const auto& e : expected_edges) {
        // The crossing of these two edges is strictly inside both.
        int found = 0;
        for (const Q3& x : got) found += strictly_inside_segment(e[0], e[1], x) && strictly_inside_segment(e[2], e[3], x);
        EXPECT_EQ(found, 1) << name_of(c);
      }
      // Every output vertex is an input corner or one of the crossings.
      std::set<Q3> allowed = expected;
      for (const auto& corner : star->corners) allowed.insert(exact(star->lift(corner)));
      for (const ImplicitPoint& v : r.mesh.vertices) EXPECT_EQ(allowed.count(exact(v)), 1u) << name_of(c);
      EXPECT_EQ(r.mesh.vertices.size(), 12u) << name_of(c);
    }
  }
}

// =======================================================================================
// 7. Labels and provenance.

struct Region {
  std::size_t triangles = 0;
  Q area2 = 0;  // XY projection, absolute
  std::set<std::int64_t> sources;
};

// Output triangles grouped by label set.
std::map<LabelSet, Region> regions_by_labels(const OutputMesh& m) {
  std::map<LabelSet, Region> out;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    Region& r = out[m.label_sets.at(m.label_set[t])];
    ++r.triangles;
    const Tri& T = m.triangles[t];
    r.area2 += abs(area2(exact(m.vertices[T[0]]), exact(m.vertices[T[1]]), exact(m.vertices[T[2]]), 2));
    r.sources.insert(m.source[t]);
  }
  return out;
}

TEST(Arrange, CoplanarOverlapOfTwoLabelledTrianglesIsEmittedOnceWithBothLabels) {
  for (bool t1_first : {false, true})
    for (Classifier c : kClassifiers) {
      const std::string what = std::string(name_of(c)) + (t1_first ? ", T1 first" : "");
      const ArrangeResult r = run_arrange(overlapping_triangles(t1_first), c);
      EXPECT_EQ(r.mesh.label_sets.size(), 3u) << what;
      const auto regions = regions_by_labels(r.mesh);
      ASSERT_EQ(regions.size(), 3u) << what;
      // Overlap: the triangle (1,1) (3,1) (1,3), area 2, owned by the triangle listed first.
      const Region& both = regions.at({0, 1});
      EXPECT_EQ(both.triangles, 1u) << what;
      EXPECT_EQ(both.area2, Q(4)) << what;
      EXPECT_EQ(both.sources, std::set<std::int64_t>{t1_first ? 200 : 100}) << what;
      // T0 alone: the hexagon (0,0) (4,0) (3,1) (1,1) (1,3) (0,4), 4 triangles, area 8 - 2.
      const Region& zero = regions.at({0});
      EXPECT_EQ(zero.triangles, 4u) << what;
      EXPECT_EQ(zero.area2, Q(12)) << what;
      EXPECT_EQ(zero.sources, std::set<std::int64_t>{100}) << what;
      // T1 alone: the quadrilateral (3,1) (5,1) (1,5) (1,3), 2 triangles, area 8 - 2.
      const Region& one = regions.at({1});
      EXPECT_EQ(one.triangles, 2u) << what;
      EXPECT_EQ(one.area2, Q(12)) << what;
      EXPECT_EQ(one.sources, std::set<std::int64_t>{200}) << what;
    }
}

TEST(Arrange, OverlappingSquaresLabelsAndSources) {
  for (Classifier c : kClassifiers) {
    const ArrangeResult r = run_arrange(overlapping_squares(), c);
    const auto regions = regions_by_labels(r.mesh);
    ASSERT_EQ(regions.size(), 3u) << name_of(c);
    // The overlap [1,2]^2 is cut by the common diagonal: one half in each triangle of the
    // first square (sources 100 and 101), both covered by the second square too.
    EXPECT_EQ(regions.at({0, 1}).triangles, 2u);
    EXPECT_EQ(regions.at({0, 1}).area2, Q(2));
    EXPECT_EQ(regions.at({0, 1}).sources, (std::set<std::int64_t>{100, 101}));
    // The rest of each square: two quadrilaterals of area 3/2, two triangles each.
    EXPECT_EQ(regions.at({0}).triangles, 4u);
    EXPECT_EQ(regions.at({0}).area2, Q(6));
    EXPECT_EQ(regions.at({0}).sources, (std::set<std::int64_t>{100, 101}));
    EXPECT_EQ(regions.at({1}).triangles, 4u);
    EXPECT_EQ(regions.at({1}).area2, Q(6));
    EXPECT_EQ(regions.at({1}).sources, (std::set<std::int64_t>{200, 201}));
  }
}

// Duplicate triangles (the shared cells of the grids) merge their labels: those cells get
// {0, 1}; the cells of one grid only keep its label.
TEST(Arrange, DuplicateCellsMergeLabels) {
  for (Classifier c : kClassifiers) {
    const ArrangeResult r = run_arrange(grids_sharing_cells(), c);
    const auto regions = regions_by_labels(r.mesh);
    ASSERT_EQ(regions.size(), 3u) << name_of(c);
    EXPECT_EQ(regions.at({0, 1}).area2, Q(2 * 12));  // [1,4] x [0,4]
    EXPECT_EQ(regions.at({0}).area2, Q(2 * 4));      // [0,1] x [0,4]
    EXPECT_EQ(regions.at({1}).area2, Q(2 * 4));      // [4,5] x [0,4]
    // The shared cells come from the first grid (its triangles are numbered first).
    for (std::int64_t s : regions.at({0, 1}).sources) EXPECT_LT(s, 32) << name_of(c);
    for (std::int64_t s : regions.at({1}).sources) EXPECT_GE(s, 32) << name_of(c);
  }
}

}  // namespace
