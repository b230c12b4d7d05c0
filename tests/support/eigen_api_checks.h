// tests/support/eigen_api_checks.h
//
// Helpers of the Eigen API tests (test_arrange_api*.cpp): scenes as Eigen matrices, the
// options and the call, and exact checks of every output field (rationals from
// tritri::to_exact and support/exact_oracle.h, no tolerance), and the hand-made scenes.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <arrangements/arrange.h>
#include <arrangements/arrange_eigen.h>
#include "support/mesh_generators.h"
#include <tritri/implicit_point.h>

#include "exact_oracle.h"

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

namespace eigen_api {

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

}  // namespace eigen_api
