// Specification of the Eigen API arrangements::arrange(V, F, options, labels)
// (arrangements/arrange_eigen.h) as a user relies on it, checked exactly (rationals from
// tritri::to_exact, no tolerance): hand-made scenes with answers derived by hand (in the
// comments); every output field and input form; the same output as arrangements::arrange
// on the equivalent TriangleSoup (seeded random soups, grids, spheres); bad input throws
// std::invalid_argument; the same output for 1, 2 and all threads; provenance: each
// output triangle lies in the closed input triangle its source names, oriented like it.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <arrangements/arrange.h>
#include <arrangements/arrange_eigen.h>
#include "support/mesh_generators.h"
#include <tritri/implicit_point.h>

#include "support/exact_oracle.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

using arrangements::ArrangeOptions;
using arrangements::Classifier;
using arrangements::EigenArrangement;
using arrangements::TriangleSoup;
using tritri_test::Q;
using tritri_test::Q3;
using Rows = std::vector<std::array<double, 3>>;
using Tris = std::vector<std::array<int, 3>>;

constexpr Classifier kClassifiers[] = {Classifier::Tritri, Classifier::Native};
const char* name_of(Classifier c) { return c == Classifier::Tritri ? "tritri" : "native"; }

struct Scene {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  Eigen::VectorXi labels;  // size 0: no labels (nullptr)
};

Scene scene(const Rows& v, const Tris& f, const std::vector<int>& labels = {}) {
  Scene s{Eigen::MatrixXd(v.size(), 3), Eigen::MatrixXi(f.size(), 3), Eigen::VectorXi(labels.size())};
  for (std::size_t r = 0; r < v.size(); ++r) s.V.row(r) << v[r][0], v[r][1], v[r][2];
  for (std::size_t r = 0; r < f.size(); ++r) s.F.row(r) << f[r][0], f[r][1], f[r][2];
  for (std::size_t r = 0; r < labels.size(); ++r) s.labels(r) = labels[r];
  return s;
}

Scene from_soup(const TriangleSoup& t) {  // generators: one label per triangle
  std::vector<int> labels;
  for (int l : t.label_set) labels.push_back(static_cast<int>(t.label_sets.at(l).at(0)));
  return scene(Rows(t.vertices.begin(), t.vertices.end()), Tris(t.triangles.begin(), t.triangles.end()), labels);
}

ArrangeOptions opts(Classifier c = Classifier::Tritri, int threads = 1) {
  ArrangeOptions o;
  o.classifier = c, o.threads = threads;
  return o;
}

EigenArrangement run(const Scene& s, const ArrangeOptions& o = opts()) {
  return arrangements::arrange(s.V, s.F, o, s.labels.size() ? &s.labels : nullptr);
}

// --- exact geometry on rationals (the rest from support/exact_oracle.h) ------------------
Q3 add(const Q3& a, const Q3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Q3 q3(double x, double y, double z) { return {Q(x), Q(y), Q(z)}; }
Q3 in_point(const Scene& s, int r) { return q3(s.V(r, 0), s.V(r, 1), s.V(r, 2)); }
// Face f's label set as ints (label_sets[label_set(f)]).
std::vector<int> labels_of(const EigenArrangement& a, int f) {
  const arrangements::LabelSet& set = a.label_sets.at(static_cast<std::size_t>(a.label_set(f)));
  return std::vector<int>(set.begin(), set.end());
}

Q3 out_point(const EigenArrangement& a, int v) { return tritri_test::exact(a.vertices.at(v)); }
// Twice the vector area of a triangle: its normal, length 2 * area.
Q3 out_normal(const EigenArrangement& a, int f) {
  return tritri_test::normal(out_point(a, a.F(f, 0)), out_point(a, a.F(f, 1)), out_point(a, a.F(f, 2)));
}

std::size_t edge_count(const Eigen::MatrixXi& F) {
  std::set<std::pair<int, int>> e;
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) e.emplace(std::min(F(f, k), F(f, (k + 1) % 3)), std::max(F(f, k), F(f, (k + 1) % 3)));
  return e.size();
}

// Every field consistent with the documentation, independently of how it was computed.
void expect_well_formed(const EigenArrangement& a, const Scene& s, const std::string& what) {
  const auto nv = a.V.rows(), nf = a.F.rows();
  ASSERT_TRUE(a.V.cols() == 3 && a.F.cols() == 3 && a.V_is_exact.size() == nv && a.source.size() == nf) << what;
  ASSERT_EQ(a.vertices.size(), std::size_t(nv)) << what;
  ASSERT_EQ(a.label_set.size(), nf) << what;
  for (int f = 0; f < nf; ++f)
    ASSERT_TRUE(a.label_set(f) >= 0 && static_cast<std::size_t>(a.label_set(f)) < a.label_sets.size()) << what;
  // F indexes the referenced vertices only, numbered in first-use order.
  int next = 0;
  for (int f = 0; f < nf; ++f)
    for (int c = 0; c < 3; ++c) {
      ASSERT_GE(a.F(f, c), 0) << what;
      ASSERT_LE(a.F(f, c), next) << what << ": face " << f;
      next = std::max(next, a.F(f, c) + 1);
    }
  EXPECT_EQ(next, nv) << what;
  // V: each coordinate the double nearest to the exact one; V_is_exact iff equal; input
  // points (explicit) are input rows, exactly.
  std::set<Q3> inputs, distinct;
  for (int r = 0; r < s.V.rows(); ++r) inputs.insert(in_point(s, r));
  for (int v = 0; v < nv; ++v) {
    const Q3 p = out_point(a, v);
    EXPECT_TRUE(distinct.insert(p).second) << what << ": two output vertices at one position";
    bool equal = true;
    for (int c = 0; c < 3; ++c) {
      const double d = a.V(v, c);
      ASSERT_TRUE(std::isfinite(d)) << what;
      equal = equal && Q(d) == p[c];
      auto err = [&](double x) -> Q { return p[c] > Q(x) ? p[c] - Q(x) : Q(x) - p[c]; };
      EXPECT_TRUE(err(d) <= err(std::nextafter(d, -INFINITY)) && err(d) <= err(std::nextafter(d, INFINITY)))
          << what << ": V(" << v << ", " << c << ") is not the nearest double";
    }
    EXPECT_EQ(bool(a.V_is_exact(v)), equal) << what << ": V_is_exact(" << v << ")";
    if (a.vertices[v].is_explicit()) {
      EXPECT_EQ(inputs.count(p), 1u) << what << ": explicit vertex " << v;
    }
  }
  // labels: sorted sets that contain the label of the source row.
  for (int f = 0; f < nf; ++f) {
    const auto& l = labels_of(a, f);
    ASSERT_FALSE(l.empty()) << what;
    EXPECT_TRUE(std::adjacent_find(l.begin(), l.end(), std::greater_equal<int>()) == l.end()) << what;
    ASSERT_TRUE(a.source(f) >= 0 && a.source(f) < s.F.rows()) << what;
    const int own = s.labels.size() ? s.labels(a.source(f)) : 0;
    EXPECT_TRUE(std::binary_search(l.begin(), l.end(), own)) << what << ": face " << f;
  }
  const std::size_t ne = edge_count(a.F);
  EXPECT_EQ((std::vector<long long>{(long long)a.stats.in_vertices, (long long)a.stats.in_triangles,
                                    (long long)a.stats.out_vertices, (long long)a.stats.out_edges,
                                    (long long)a.stats.out_triangles, a.stats.euler}),
            (std::vector<long long>{s.V.rows(), s.F.rows(), nv, (long long)ne, nf, nv - (long long)ne + nf}))
      << what << ": stats (in V, in F, out V, E, F, euler)";
}

// Provenance: every output triangle lies in the closed input triangle its source names,
// is non-degenerate and is oriented like it. tiling (no coplanar overlaps, no removed
// triangles): the output triangles of each source add up to it (sum of vector areas).
void expect_provenance(const EigenArrangement& a, const Scene& s, const std::string& what, bool tiling = false) {
  using namespace tritri_test;  // sub, cross, dot, is_zero, normal
  std::vector<Q3> sum(s.F.rows(), q3(0, 0, 0));
  for (int f = 0; f < a.F.rows(); ++f) {
    const int src = a.source(f);
    ASSERT_TRUE(src >= 0 && src < s.F.rows()) << what;
    const Q3 A = in_point(s, s.F(src, 0)), B = in_point(s, s.F(src, 1)), C = in_point(s, s.F(src, 2));
    const Q3 n = normal(A, B, C), m = out_normal(a, f);
    EXPECT_TRUE(is_zero(cross(n, m)) && dot(n, m) > 0) << what << ": face " << f << " not oriented like row " << src;
    sum[src] = add(sum[src], m);
    for (int k = 0; k < 3; ++k) {
      const Q3 p = out_point(a, a.F(f, k));
      EXPECT_EQ(dot(n, sub(p, A)), 0) << what << ": face " << f << " corner " << k << " off the plane of row " << src;
      const bool inside = dot(n, cross(sub(B, A), sub(p, A))) >= 0 && dot(n, cross(sub(C, B), sub(p, B))) >= 0 &&
                          dot(n, cross(sub(A, C), sub(p, C))) >= 0;
      EXPECT_TRUE(inside) << what << ": face " << f << " corner " << k << " outside row " << src;
    }
  }
  for (int r = 0; tiling && r < s.F.rows(); ++r)
    EXPECT_EQ(sum[r], normal(in_point(s, s.F(r, 0)), in_point(s, s.F(r, 1)), in_point(s, s.F(r, 2))))
        << what << ": row " << r << " not tiled";
}

void expect_same(const EigenArrangement& a, const EigenArrangement& b, const std::string& what) {
  ASSERT_TRUE(a.V.rows() == b.V.rows() && a.F.rows() == b.F.rows()) << what;
  EXPECT_TRUE(a.V == b.V && a.F == b.F && a.source == b.source && a.V_is_exact == b.V_is_exact) << what;
  for (int f = 0; f < a.F.rows(); ++f) EXPECT_EQ(labels_of(a, f), labels_of(b, f)) << what << ": face " << f;
  for (int v = 0; v < a.V.rows(); ++v) EXPECT_EQ(out_point(a, v), out_point(b, v)) << what << ": vertex " << v;
}

// --- hand-made scenes -------------------------------------------------------------------
// A in z = 0; B in y = 1 with corners (x, z) = (1,-1), (1,2), (3,2). B's edge x = 1 meets
// z = 0 at p = (1,1,0), its edge (1,-1)-(3,2) at t = 1/3: q = (5/3,1,0); both inside A.
// A: 3 boundary points, 2 interior (p, q): 2*2 + 3 - 2 = 5 triangles. B: corners plus p, q
// on its edges: 5 - 2 = 3. V = 6 + 2, F = 8, E = (5+5-1) + (5+3-1) - 1 (pq) = 15.
Scene crossing() {
  return scene({{0, 0, 0}, {6, 0, 0}, {0, 6, 0}, {1, 1, -1}, {1, 1, 2}, {3, 1, 2}}, {{0, 1, 2}, {3, 4, 5}});
}
// A in z = 0; B in y = 1 with corners (x, z) = (1,-2), (1,2), (9,1): B meets z = 0 for x in
// [1, 19/3], A meets y = 1 for x in [0, 3]: p = (1,1,0) (B's edge in A's interior), q =
// (3,1,0) (A's edge in B's interior). A: 4 boundary, 1 interior: 4; B likewise: 4.
Scene pierced() {
  return scene({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, -2}, {1, 1, 2}, {9, 1, 1}}, {{0, 1, 2}, {3, 4, 5}});
}
// B's corner (1,1,0) touches A's interior: A becomes 3 triangles, B stays one; the corner
// is one output vertex. V = 6, E = 6 + 3, F = 4.
Scene touching() {
  return scene({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0}, {2, 1, 3}, {1, 2, 3}}, {{0, 1, 2}, {3, 4, 5}});
}
// Coplanar in z = 0: A = (0,0) (4,0) (0,4), B = (1,1) (5,1) (1,5); edges cross at (3,1) and
// (1,3). Overlap: triangle (1,1) (3,1) (1,3) (twice area 4); A only: hexagon (0,0) (4,0)
// (3,1) (1,1) (1,3) (0,4), 4 triangles (twice area 16 - 4); B only: quad (3,1) (5,1) (1,5)
// (1,3), 2 triangles (twice area 12). V = 8, F = 7, E = 14.
Scene coplanar(bool b_first) {
  Rows a = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}, b = {{1, 1, 0}, {5, 1, 0}, {1, 5, 0}};
  Rows v = b_first ? b : a;
  v.insert(v.end(), (b_first ? a : b).begin(), (b_first ? a : b).end());
  return scene(v, {{0, 1, 2}, {3, 4, 5}}, b_first ? std::vector<int>{3, 7} : std::vector<int>{7, 3});
}
// An axis-aligned box, faces -x +x -y +y -z +z (outward), each quad (a,b,c,d) split into
// (a,b,c), (a,c,d); corner i = (i&1 ? hi : lo, i&2 ..., i&4 ...).
void add_box(Rows& v, Tris& f, std::array<double, 3> lo, std::array<double, 3> hi) {
  const int o = static_cast<int>(v.size());
  for (int i = 0; i < 8; ++i) v.push_back({i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]});
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    f.push_back({o + q[0], o + q[1], o + q[2]});
    f.push_back({o + q[0], o + q[2], o + q[3]});
  }
}
// A = [0,2]^3 (rows 0-11), B = [1,3] x [.5,1.5]^2 (rows 12-23) pokes out of A's face x = 2
// (rows 2, 3, diagonal y = z). The loop on x = 2: (y,z) in {.5,1,1.5}^2 minus (1,1): 4
// where B's long edges cross, 4 where B's face diagonals cross (at the middle). A's rows
// 2, 3: 2 loop corners on the diagonal, 3 loop points inside each: 2*3 + 5 - 2 = 9 each.
// B's long faces (rows 16-23): 2 loop points on the boundary of each triangle: 3 each.
// Others: 1. F = 10 + 18 + 4 + 24 = 56; V = 8 + 8 + 8 = 24; two spheres glued along a
// loop: chi = 2 + 2 - 0 = 4, so E = 24 + 56 - 4 = 76.
Scene cube_through_cube() {
  Rows v;
  Tris f;
  add_box(v, f, {0, 0, 0}, {2, 2, 2});
  add_box(v, f, {1, 0.5, 0.5}, {3, 1.5, 1.5});
  std::vector<int> labels(24, 0);
  std::fill(labels.begin() + 12, labels.end(), 1);
  return scene(v, f, labels);
}

// A closed tetrahedron, a triangle touching its apex through a duplicated row (merged:
// one output vertex), an unreferenced row (dropped). V = 4 + 2, E = 6 + 3, F = 5.
Scene shared_vertices() {
  return scene({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 1}, {1, 1, 2}, {-1, 1, 2}, {9, 9, 9}},
               {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {4, 5, 6}});
}

struct HandCase {
  std::string name;
  Scene scene;
  int V, E, F;
  std::vector<int> per_source;
  std::set<Q3> fresh;  // the new (implicit) vertices, exactly
};

std::vector<HandCase> hand_cases() {
  std::vector<int> cube(24, 1);
  cube[2] = cube[3] = 9;
  std::fill(cube.begin() + 16, cube.end(), 3);
  std::set<Q3> loop;
  for (double y : {0.5, 1.0, 1.5})
    for (double z : {0.5, 1.0, 1.5})
      if (y != 1.0 || z != 1.0) loop.insert(q3(2, y, z));
  return {{"crossing", crossing(), 8, 15, 8, {5, 3}, {q3(1, 1, 0), {Q(5, 3), Q(1), Q(0)}}},
          {"pierced", pierced(), 8, 15, 8, {4, 4}, {q3(1, 1, 0), q3(3, 1, 0)}},
          {"touching", touching(), 6, 9, 4, {3, 1}, {}},
          {"cube through cube", cube_through_cube(), 24, 76, 56, cube, loop},
          {"shared vertices", shared_vertices(), 6, 9, 5, {1, 1, 1, 1, 1}, {}}};
}

TEST(ArrangeApi, HandScenesCountsPointsAndTiling) {
  for (const HandCase& h : hand_cases())
    for (Classifier c : kClassifiers) {
      const std::string what = h.name + " (" + name_of(c) + ")";
      const EigenArrangement a = run(h.scene, opts(c));
      expect_well_formed(a, h.scene, what);
      expect_provenance(a, h.scene, what, true);
      EXPECT_EQ((std::array<long long, 3>{a.V.rows(), (long long)a.stats.out_edges, a.F.rows()}),
                (std::array<long long, 3>{h.V, h.E, h.F}))
          << what << ": V, E, F";
      std::vector<int> per_source(h.scene.F.rows(), 0);
      for (int f = 0; f < a.F.rows(); ++f) ++per_source.at(a.source(f));
      EXPECT_EQ(per_source, h.per_source) << what;
      std::set<Q3> fresh;
      for (int v = 0; v < a.V.rows(); ++v)
        if (!a.vertices[v].is_explicit()) {
          EXPECT_EQ(a.vertices[v].kind(), tritri::ImplicitPoint::Kind::LPI) << what;
          fresh.insert(out_point(a, v));
        }
      EXPECT_EQ(fresh, h.fresh) << what;
      EXPECT_TRUE(a.stats.intersection_points == h.fresh.size() && a.stats.tpi == 0) << what;
      EXPECT_EQ(a.stats.classifier, name_of(c));
      if (h.scene.labels.size() == 0) {
        for (int f = 0; f < a.F.rows(); ++f)
          EXPECT_EQ(labels_of(a, f), std::vector<int>{0}) << what;  // no labels: all 0
      }
    }
}

// Crossing: p = (1,1,0) is a double, q = (5/3,1,0) is rounded in V; pq is an edge of both.
TEST(ArrangeApi, CrossingSegmentEndpoints) {
  const EigenArrangement a = run(crossing());
  int ip = -1, iq = -1;
  for (int v = 0; v < a.V.rows(); ++v) {
    if (out_point(a, v) == q3(1, 1, 0)) ip = v;
    if (out_point(a, v) == Q3{Q(5, 3), Q(1), Q(0)}) iq = v;
  }
  ASSERT_TRUE(ip >= 0 && iq >= 0);
  EXPECT_TRUE(a.V_is_exact(ip) && !a.V_is_exact(iq));
  EXPECT_TRUE((a.V.row(ip) == Eigen::RowVector3d(1, 1, 0)));
  EXPECT_TRUE((a.V.row(iq) == Eigen::RowVector3d(5.0 / 3.0, 1, 0)));
  EXPECT_EQ(a.V_is_exact.count(), 7);
  std::set<int> sides;
  for (int f = 0; f < a.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (std::minmax(a.F(f, k), a.F(f, (k + 1) % 3)) == std::minmax(ip, iq)) sides.insert(a.source(f));
  EXPECT_EQ(sides, (std::set<int>{0, 1}));
  EXPECT_EQ(a.stats.intersecting_pairs, 1u);
}

// Cube: labels by box; shared vertices: the apex is one vertex of rows 1-4, duplicates
// merged.
TEST(ArrangeApi, CubeLabelsAndSharedApex) {
  const EigenArrangement a = run(cube_through_cube());
  for (int f = 0; f < a.F.rows(); ++f) EXPECT_EQ(labels_of(a, f), std::vector<int>{a.source(f) < 12 ? 0 : 1});
  const EigenArrangement b = run(shared_vertices());
  EXPECT_TRUE(b.stats.merged_vertices == 1 && b.stats.intersection_points == 0);
  std::set<int> users;
  for (int f = 0; f < b.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (out_point(b, b.F(f, k)) == q3(0, 0, 1)) users.insert(b.source(f));
  EXPECT_EQ(users, (std::set<int>{1, 2, 3, 4}));
}

TEST(ArrangeApi, CoplanarOverlapUnitesLabels) {
  for (bool b_first : {false, true})
    for (Classifier c : kClassifiers) {
      const std::string what = std::string(name_of(c)) + (b_first ? ", B first" : "");
      const Scene s = coplanar(b_first);  // labels: A 7, B 3
      const EigenArrangement a = run(s, opts(c));
      expect_well_formed(a, s, what);
      expect_provenance(a, s, what);
      EXPECT_TRUE(a.V.rows() == 8 && a.stats.out_edges == 14 && a.F.rows() == 7) << what;
      EXPECT_EQ(a.stats.coplanar_pairs, 1u) << what;
      struct Region {
        int triangles = 0;
        Q area2 = 0;  // z component of the normals: twice the area in z = 0
        std::set<int> sources;
      };
      std::map<std::vector<int>, Region> regions;
      for (int f = 0; f < a.F.rows(); ++f) {
        Region& r = regions[labels_of(a, f)];
        const Q z = out_normal(a, f)[2];
        EXPECT_GT(z, 0) << what;  // oriented like the input, counter-clockwise
        ++r.triangles, r.area2 += z, r.sources.insert(a.source(f));
      }
      const int rowA = b_first ? 1 : 0, rowB = b_first ? 0 : 1;
      ASSERT_EQ(regions.size(), 3u) << what;
      // {3, 7}: the overlap, owned by the first row covering it (row 0).
      const std::tuple<std::vector<int>, int, int, int> want[] = {
          {{3, 7}, 1, 4, 0}, {{7}, 4, 12, rowA}, {{3}, 2, 12, rowB}};  // labels, triangles, twice area, source
      for (const auto& [labels, triangles, area2, row] : want) {
        const Region& r = regions[labels];
        EXPECT_TRUE(r.triangles == triangles && r.area2 == area2 && r.sources == std::set<int>{row})
            << what << ", labels " << labels.back() << " (" << labels.size() << "): " << r.triangles << " " << r.area2;
      }
    }
}

// A duplicate of a triangle (any corner order) is removed and gives its labels to the
// first one; labels are any non-negative ints.
TEST(ArrangeApi, DuplicateTrianglesUniteLabels) {
  Scene s = coplanar(false);
  s.F.conservativeResize(3, 3);
  s.F.row(2) << 1, 2, 0;  // A again
  s.labels.conservativeResize(3);
  s.labels(2) = INT_MAX;
  const EigenArrangement a = run(s);
  expect_well_formed(a, s, "duplicate");
  EXPECT_EQ(a.stats.removed_duplicate, 1u);
  std::set<std::vector<int>> sets;
  for (int f = 0; f < a.F.rows(); ++f) sets.insert(labels_of(a, f));
  EXPECT_EQ(sets, (std::set<std::vector<int>>{{7, INT_MAX}, {3, 7, INT_MAX}, {3}}));
  for (int f = 0; f < a.F.rows(); ++f) EXPECT_NE(a.source(f), 2);
}

// Nothing intersects: the output is the input (vertices in first-use order, each
// triangle the same up to a rotation of its corners, source = row).
TEST(ArrangeApi, DisjointTrianglesAreOutputUnchanged) {
  const Scene s = scene({{0, 0, 0},
                         {1, 0, 0},
                         {0, 1, 0},
                         {5, 5, 5},
                         {6, 5, 5.5},
                         {5, 7, 6},
                         {0.1, 0.2, 9},
                         {0.3, 0.1, 9.5},
                         {0.2, 0.7, 9}},
                        {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}}, {4, 1, 4});
  const EigenArrangement a = run(s);
  expect_well_formed(a, s, "disjoint");
  EXPECT_TRUE(a.V == s.V && a.V_is_exact.all());
  ASSERT_EQ(a.F.rows(), 3);
  for (int f = 0; f < 3; ++f) {
    EXPECT_TRUE(a.source(f) == f && labels_of(a, f) == std::vector<int>{s.labels(f)}) << f;
    bool rotated = false;
    for (int k = 0; k < 3; ++k)
      rotated = rotated || a.F.row(f) == Eigen::RowVector3i(s.F(f, k), s.F(f, (k + 1) % 3), s.F(f, (k + 2) % 3));
    EXPECT_TRUE(rotated) << "face " << f;
  }
  EXPECT_TRUE(a.stats.intersecting_pairs == 0 && a.stats.euler == 3);
}

// Nothing left to arrange (all triangles degenerate, or none) is an empty arrangement, not
// an error.
TEST(ArrangeApi, DegenerateOrEmptyInputGivesAnEmptyArrangement) {
  const Scene degenerate = scene({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {5, 0, 0}, {0, 0, 0}},
                                 {{0, 1, 2}, {3, 3, 0}, {0, 4, 3}}, {1, 2, 3});  // collinear, repeated, coincident
  const Scene no_rows{Eigen::MatrixXd(0, 3), Eigen::MatrixXi(0, 3), Eigen::VectorXi()};
  const Scene no_faces{Eigen::MatrixXd::Ones(2, 3), Eigen::MatrixXi(0, 3), Eigen::VectorXi(0)};
  const Scene sizeless{Eigen::MatrixXd(), Eigen::MatrixXi(), Eigen::VectorXi()};
  for (const Scene* s : {&degenerate, &no_rows, &no_faces, &sizeless}) {
    EigenArrangement a;
    EXPECT_NO_THROW(a = arrangements::arrange(s->V, s->F, opts(), s == &no_faces ? &s->labels : nullptr));
    EXPECT_TRUE(a.V.rows() == 0 && a.V.cols() == 3 && a.F.rows() == 0 && a.F.cols() == 3 && a.source.size() == 0 &&
                a.label_set.size() == 0 && a.vertices.empty() && a.V_is_exact.size() == 0);
    EXPECT_TRUE(a.stats.out_triangles == 0 && a.stats.out_vertices == 0 && a.stats.euler == 0);
  }
  EXPECT_EQ(run(degenerate).stats.removed_degenerate, 3u);
}

// --- input forms and options ------------------------------------------------------------
TEST(ArrangeApi, OtherEigenMatrixTypesGiveTheSameOutput) {
  const Scene s = crossing();
  const EigenArrangement ref = run(s);
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> Vr = s.V;
  const Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor> Fr = s.F;
  const Eigen::Matrix<double, 6, 3> Vf = s.V;
  const Eigen::Matrix<int, 2, 3> Ff = s.F;
  std::vector<double> vbuf(Vr.data(), Vr.data() + Vr.size());
  std::vector<int> fbuf(Fr.data(), Fr.data() + Fr.size());
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> Vm(vbuf.data(), 6, 3);
  const Eigen::Map<const Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> Fm(fbuf.data(), 2, 3);
  expect_same(arrangements::arrange(Vr, Fr, opts()), ref, "row-major");
  expect_same(arrangements::arrange(Vf, Ff, opts()), ref, "fixed size");
  expect_same(arrangements::arrange(Vm, Fm, opts()), ref, "maps");
  expect_same(arrangements::arrange(s.V, s.F, {}), ref, "default options");
  const Eigen::VectorXi zeros = Eigen::VectorXi::Zero(2);
  expect_same(arrangements::arrange(s.V, s.F, opts(), &zeros), ref, "labels all 0 = no labels");
}

TEST(ArrangeApi, OptionsAreHonoured) {
  const Scene s = crossing();
  const EigenArrangement ref = run(s);
  for (int t : {1, 2}) EXPECT_EQ(run(s, opts(Classifier::Tritri, t)).stats.threads, t);
  EXPECT_GE(run(s, opts(Classifier::Tritri, 0)).stats.threads, 1);
  EXPECT_EQ(run(s, opts(Classifier::Native)).stats.classifier, "native");
  ArrangeOptions o = opts();
  EXPECT_EQ(ref.stats.orient3d_calls, 0u);
  o.count_predicates = true;
  const EigenArrangement counted = run(s, o);
  expect_same(counted, ref, "count_predicates");
  EXPECT_GT(counted.stats.orient3d_calls, 0u);
}

// scale: the same exact output in the input's coordinates, whatever the magnitude (also
// when scaling would round a coordinate: the model is then kept unscaled, no error).
TEST(ArrangeApi, ScaleGivesTheSameOutput) {
  const Scene base = crossing();
  for (double k : {0.1, std::ldexp(1.0, -700), 1e300}) {
    Scene s = base;
    s.V *= k;
    if (k == 1e300) s.V(0, 0) = 1e-300;  // a dynamic range no power of two can scale exactly
    ArrangeOptions o = opts();
    o.scale = true;  // exact power-of-two scaling inside, undone on output
    EigenArrangement scaled;
    ASSERT_NO_THROW(scaled = run(s, o)) << k;
    expect_same(scaled, run(s), "scale " + std::to_string(k));
    expect_provenance(scaled, s, "scale");
  }
}

// --- bad input --------------------------------------------------------------------------
TEST(ArrangeApi, BadInputThrowsInvalidArgument) {
  const Scene s = crossing();
  std::vector<std::pair<std::string, std::function<void()>>> cases;
  auto with = [&](const std::string& name, Scene t) { cases.emplace_back(name, [t] { run(t); }); };
  for (int cols : {1, 2, 4}) {
    with("V with " + std::to_string(cols) + " columns", Scene{Eigen::MatrixXd::Zero(6, cols), s.F, {}});
    with("F with " + std::to_string(cols) + " columns", Scene{s.V, Eigen::MatrixXi::Zero(2, cols), {}});
  }
  auto change = [&](auto edit) {
    Scene t = s;
    edit(t);
    return t;
  };
  for (double bad : {NAN, INFINITY, -INFINITY})
    for (int r : {0, 5})
      with(std::to_string(bad) + " in row " + std::to_string(r), change([&](Scene& t) { t.V(r, r % 3) = bad; }));
  with("NaN in an unreferenced row", change([](Scene& t) { t.V.conservativeResize(7, 3), t.V.row(6) << 0, NAN, 0; }));
  for (int i : {6, 1000, -1, INT_MIN}) with("index " + std::to_string(i), change([&](Scene& t) { t.F(1, 2) = i; }));
  with("indices into an empty V", Scene{Eigen::MatrixXd(0, 3), s.F, Eigen::VectorXi()});
  for (int n : {1, 3}) with(std::to_string(n) + " labels for 2 rows", Scene{s.V, s.F, Eigen::VectorXi::Zero(n)});
  with("negative label", Scene{s.V, s.F, Eigen::Vector2i(0, -1)});
  const Eigen::VectorXi none(0);
  cases.emplace_back("empty labels vector", [&] { arrangements::arrange(s.V, s.F, opts(), &none); });
  for (const auto& [name, call] : cases) EXPECT_THROW(call(), std::invalid_argument) << name;
  expect_same(run(s), run(s), "after the errors");  // still usable
}

// --- generated inputs: soup API equivalence, threads, provenance ------------------------
// Random soups: integer coordinates in [0, 3] (many coplanar, touching, degenerate and
// duplicate triangles) or uniform doubles; random rows, labels in [0, 4].
Scene random_scene(unsigned seed) {
  std::mt19937 rng(seed);
  const int nv = 5 + static_cast<int>(rng() % 10), nf = 3 + static_cast<int>(rng() % 12);
  Scene s{Eigen::MatrixXd(nv, 3), Eigen::MatrixXi(nf, 3), Eigen::VectorXi(nf)};
  std::uniform_real_distribution<double> real(-1.0, 1.0);
  for (int r = 0; r < nv; ++r)
    for (int c = 0; c < 3; ++c) s.V(r, c) = seed % 2 ? real(rng) : static_cast<double>(rng() % 4);
  for (int r = 0; r < nf; ++r) {
    for (int c = 0; c < 3; ++c) s.F(r, c) = static_cast<int>(rng() % nv);
    s.labels(r) = static_cast<int>(rng() % 5);
  }
  return s;
}

std::vector<std::pair<std::string, Scene>> generated_scenes() {
  using namespace arrangements;
  std::vector<std::pair<std::string, Scene>> out;
  for (unsigned seed = 1; seed <= 40; ++seed) out.emplace_back("random " + std::to_string(seed), random_scene(seed));
  out.emplace_back("two spheres",
                   from_soup(concatenate(uv_sphere({0, 0, 0}, 1, 6, 8), uv_sphere({0.5, 0.3, 0.2}, 0.8, 5, 7))));
  out.emplace_back("grid through sphere",
                   from_soup(concatenate(grid(4, 0.5, 0.1, -1, -1), uv_sphere({0, 0, 0}, 0.9, 5, 6))));
  out.emplace_back("rotated grids", from_soup(rotated_copies(grid(3, 1.0, 0.0), 3)));
  out.emplace_back("rotated boxes", from_soup(rotated_copies(box({0, 0, 0}, {2, 1, 1}), 3)));
  out.emplace_back("cube through cube", cube_through_cube());
  out.emplace_back("coplanar", coplanar(true));
  return out;
}

// The TriangleSoup a user would build for (V, F, labels): source = row, label sets
// numbered in decreasing label order (the Eigen layer numbers them by first use).
TriangleSoup soup_of(const Scene& s) {
  TriangleSoup t;
  for (int r = 0; r < s.V.rows(); ++r) t.vertices.push_back({s.V(r, 0), s.V(r, 1), s.V(r, 2)});
  std::map<int, int, std::greater<int>> index;
  for (int r = 0; r < s.F.rows(); ++r) index[s.labels.size() ? s.labels(r) : 0] = 0;
  for (auto& [label, i] : index) {
    i = static_cast<int>(t.label_sets.size());
    t.label_sets.push_back({static_cast<std::uint32_t>(label)});
  }
  for (int r = 0; r < s.F.rows(); ++r) {
    t.triangles.push_back({s.F(r, 0), s.F(r, 1), s.F(r, 2)});
    t.label_set.push_back(index[s.labels.size() ? s.labels(r) : 0]);
    t.source.push_back(r);
  }
  return t;
}

TEST(ArrangeApi, SameOutputAsTheSoupApi) {
  for (const auto& [name, s] : generated_scenes())
    for (Classifier c : kClassifiers) {
      const std::string what = name + " (" + name_of(c) + ")";
      const EigenArrangement a = run(s, opts(c, 2));
      const arrangements::ArrangeResult r = arrangements::arrange(soup_of(s), opts(c, 2));
      const auto& m = r.mesh;
      ASSERT_TRUE(std::size_t(a.V.rows()) == m.vertices.size() && std::size_t(a.F.rows()) == m.triangles.size())
          << what;
      for (int v = 0; v < a.V.rows(); ++v) {
        EXPECT_EQ(out_point(a, v), tritri_test::exact(m.vertices[v])) << what << ": vertex " << v;
        EXPECT_EQ(a.vertices[v].kind(), m.vertices[v].kind()) << what;
      }
      for (int f = 0; f < a.F.rows(); ++f) {
        for (int k = 0; k < 3; ++k) EXPECT_EQ(a.F(f, k), m.triangles[f][k]) << what << ": face " << f;
        EXPECT_EQ(a.source(f), m.source[f]) << what << ": face " << f;
        const auto& set = m.label_sets.at(m.label_set[f]);
        EXPECT_EQ(labels_of(a, f), std::vector<int>(set.begin(), set.end())) << what << ": face " << f;
      }
      const auto counts = [](const arrangements::ArrangeStats& t) {
        return std::vector<std::size_t>{t.in_vertices,        t.in_triangles,        t.merged_vertices,
                                        t.removed_degenerate, t.removed_duplicate,   t.candidate_pairs,
                                        t.intersecting_pairs, t.coplanar_pairs,      t.intersection_points,
                                        t.segments,           t.tri_segments,        t.tpi,
                                        t.out_vertices,       t.out_edges,           t.out_triangles,
                                        std::size_t(t.euler), std::size_t(t.threads)};
      };
      EXPECT_EQ(counts(a.stats), counts(r.stats)) << what;
      EXPECT_EQ(a.stats.classifier, r.stats.classifier) << what;
    }
}

TEST(ArrangeApi, SameOutputForOneTwoAndAllThreads) {
  for (const auto& [name, s] : generated_scenes())
    for (Classifier c : kClassifiers) {
      const EigenArrangement one = run(s, opts(c, 1));
      expect_same(run(s, opts(c, 2)), one, name + ", 2 threads, " + name_of(c));
      expect_same(run(s, opts(c, 0)), one, name + ", all threads, " + name_of(c));
    }
}

TEST(ArrangeApi, ProvenanceAndFieldsOfGeneratedInputs) {
  for (const auto& [name, s] : generated_scenes()) {
    const EigenArrangement a = run(s, opts(Classifier::Tritri, 2));
    expect_well_formed(a, s, name);
    expect_provenance(a, s, name);
  }
}

}  // namespace
