// The exact Eigen overload arrangements::arrange(V of CGAL::Gmpq, F, options, labels)
// (arrangements/arrange_eigen.h):
//   - on rational input with thirds (two crossing triangles), the counts and the two new
//     points derived by hand, exactly;
//   - on the generated scenes (as rationals, with labels), every output field equals
//     arrange(ExactTriangleSoup) on the same soup built by hand here (source = row of F,
//     one label set {l} per distinct label in first-appearance order), and the vertex set
//     equals tritri::to_exact of the double overload's vertices (also through the
//     `exact` output of detail::arrange_eigen, which the Python module uses);
//   - bad input throws std::invalid_argument (|x| > DBL_MAX, shapes, indices, labels);
//     DBL_MAX itself is accepted;
//   - double matrix expressions still pick the double overload.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cfloat>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "arrangements/arrange.h"
#include "arrangements/as_input.h"
#include "arrangements/arrange_eigen.h"
#include "support/arrangement_scenes.h"
#include "support/exact_soups.h"

namespace {

using namespace arrangements;
using Q = CGAL::Gmpq;
using ExactV = Eigen::Matrix<Q, Eigen::Dynamic, 3>;

ExactV exact_matrix(const std::vector<ExactVec3>& rows) {
  ExactV V(static_cast<Eigen::Index>(rows.size()), 3);
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (int c = 0; c < 3; ++c) V(static_cast<Eigen::Index>(r), c) = rows[r][c];
  return V;
}

Eigen::MatrixXi index_matrix(const std::vector<Tri>& tris) {
  Eigen::MatrixXi F(static_cast<Eigen::Index>(tris.size()), 3);
  for (std::size_t r = 0; r < tris.size(); ++r)
    for (int c = 0; c < 3; ++c) F(static_cast<Eigen::Index>(r), c) = tris[r][c];
  return F;
}

// The soup the Eigen entry point is documented to build: source = row, label set {l} per
// distinct label, numbered in order of first appearance.
ExactTriangleSoup expected_soup(const std::vector<ExactVec3>& V, const std::vector<Tri>& F,
                                const std::vector<int>& labels) {
  ExactTriangleSoup s;
  s.vertices = V;
  s.triangles = F;
  std::map<int, int> set_of;
  for (std::size_t t = 0; t < F.size(); ++t) {
    const int l = labels.empty() ? 0 : labels[t];
    auto [it, added] = set_of.try_emplace(l, static_cast<int>(s.label_sets.size()));
    if (added) s.label_sets.push_back({static_cast<std::uint32_t>(l)});
    s.label_set.push_back(it->second);
    s.source.push_back(static_cast<std::int64_t>(t));
  }
  return s;
}

void expect_equal(const ExactEigenArrangement& e, const ExactArrangeResult& r, const std::string& what) {
  ASSERT_EQ(e.V.rows(), static_cast<Eigen::Index>(r.mesh.vertices.size())) << what;
  for (Eigen::Index v = 0; v < e.V.rows(); ++v)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(e.V(v, c), r.mesh.vertices[v][c]) << what << ": V(" << v << ", " << c << ")";
  ASSERT_EQ(e.F.rows(), static_cast<Eigen::Index>(r.mesh.triangles.size())) << what;
  for (Eigen::Index f = 0; f < e.F.rows(); ++f) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(e.F(f, c), r.mesh.triangles[f][c]) << what;
    EXPECT_EQ(e.source(f), r.mesh.source[f]) << what;
    EXPECT_EQ(e.label_set(f), r.mesh.label_set[f]) << what;
  }
  EXPECT_EQ(e.label_sets, r.mesh.label_sets) << what;
  EXPECT_EQ(e.stats.out_vertices, r.stats.out_vertices) << what;
  EXPECT_EQ(e.stats.out_triangles, r.stats.out_triangles) << what;
  EXPECT_EQ(e.stats.intersection_points, r.stats.intersection_points) << what;
  EXPECT_EQ(e.stats.euler, r.stats.euler) << what;
}

std::vector<ExactVec3> rows_of(const ExactV& V) {
  std::vector<ExactVec3> rows(static_cast<std::size_t>(V.rows()));
  for (Eigen::Index r = 0; r < V.rows(); ++r) rows[r] = {V(r, 0), V(r, 1), V(r, 2)};
  return rows;
}

ArrangeOptions one_thread() {
  ArrangeOptions o;
  o.threads = 1;
  return o;
}

// A = (0,0,0), (1,0,0), (0,1,0) in z = 0; B in the plane x = 1/3 with corners
// (1/3,1/3,-1), (1/3,1/3,1), (1/3,-1,1/3). B's edge 0 (the vertical one) crosses A's
// interior at (1/3,1/3,0); B's edge 2 meets z = 0 at (1/3,-2/3,0), outside A; edge 1 stays
// above. So B meets A along x = 1/3, z = 0, y from 1/3 down to A's edge y = 0, where A's
// edge 0 crosses B's interior at (1/3,0,0) (in B's plane: (y,z) = (0,0) is inside the
// triangle (1/3,-1), (1/3,1), (-1,1/3)). Each triangle: 4 boundary points and 1 interior
// point -> 4 triangles and 8 edges; they share the segment: V = 8, E = 15, F = 8.
TEST(ArrangeEigenExact, ThirdsCrossingByHand) {
  const Q third(1, 3);
  const std::vector<ExactVec3> V = {{Q(0), Q(0), Q(0)},    {Q(1), Q(0), Q(0)},   {Q(0), Q(1), Q(0)},
                                    {third, third, Q(-1)}, {third, third, Q(1)}, {third, Q(-1), third}};
  const std::vector<Tri> F = {{0, 1, 2}, {3, 4, 5}};
  Eigen::VectorXi labels(2);
  labels << 0, 7;
  const ExactEigenArrangement e = arrangements::arrange(exact_matrix(V), index_matrix(F), one_thread(), &labels);
  EXPECT_EQ(e.V.rows(), 8);
  EXPECT_EQ(e.F.rows(), 8);
  EXPECT_EQ(e.stats.out_edges, 15u);
  EXPECT_EQ(e.stats.intersection_points, 2u);
  std::vector<ExactVec3> fresh;
  for (const ExactVec3& p : rows_of(e.V))
    if (std::find(V.begin(), V.end(), p) == V.end()) fresh.push_back(p);
  std::sort(fresh.begin(), fresh.end());
  EXPECT_EQ(fresh, (std::vector<ExactVec3>{{third, Q(0), Q(0)}, {third, third, Q(0)}}));
  EXPECT_EQ(std::count(e.source.begin(), e.source.end(), 0), 4);
  EXPECT_EQ(e.label_sets, (std::vector<LabelSet>{{0}, {7}}));
  expect_equal(e, arrange(expected_soup(V, F, {0, 7}), one_thread()), "thirds");
}

TEST(ArrangeEigenExact, EqualsTheExactPipelineAndTheDoubleOverloadOnGeneratedScenes) {
  for (const auto& [name, soup] : tritri_test::arrangement::generated_scenes()) {
    const ExactTriangleSoup exact = arrangements::to_exact(soup);
    std::vector<int> labels;
    Eigen::VectorXi L(static_cast<Eigen::Index>(soup.triangles.size()));
    for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
      labels.push_back(static_cast<int>(soup.label_sets.at(soup.label_set[t]).at(0)));
      L(static_cast<Eigen::Index>(t)) = labels.back();
    }
    const ExactV V = exact_matrix(exact.vertices);
    const Eigen::MatrixXi F = index_matrix(soup.triangles);
    const ExactEigenArrangement e = arrangements::arrange(V, F, ArrangeOptions{}, &L);
    expect_equal(e, arrange(expected_soup(exact.vertices, soup.triangles, labels), ArrangeOptions{}), name);

    Eigen::MatrixXd Vd(V.rows(), 3);
    for (std::size_t r = 0; r < soup.vertices.size(); ++r)
      for (int c = 0; c < 3; ++c) Vd(static_cast<Eigen::Index>(r), c) = soup.vertices[r][c];
    std::vector<ExactVec3> from_double;
    const EigenArrangement d = detail::arrange_eigen(Vd, F, ArrangeOptions{}, &L, "test", &from_double);
    ASSERT_EQ(from_double.size(), d.vertices.size()) << name;
    for (std::size_t v = 0; v < from_double.size(); ++v) {
      EXPECT_EQ(from_double[v], tritri::to_exact(d.vertices[v])) << name;
      bool rounded_is_exact = true;
      for (int c = 0; c < 3; ++c) rounded_is_exact = rounded_is_exact && Q(d.V(v, c)) == from_double[v][c];
      EXPECT_EQ(d.V_is_exact(v), rounded_is_exact) << name;
    }
    std::vector<ExactVec3> exact_rows = rows_of(e.V);
    std::sort(from_double.begin(), from_double.end());
    std::sort(exact_rows.begin(), exact_rows.end());
    EXPECT_EQ(exact_rows, from_double) << name;
    EXPECT_EQ(e.F.rows(), d.F.rows()) << name;
  }
}

TEST(ArrangeEigenExact, RefusesBadInput) {
  const Q big(DBL_MAX);
  const std::vector<ExactVec3> V = {{Q(0), Q(0), Q(0)}, {Q(1), Q(0), Q(0)}, {Q(0), Q(1), Q(0)}};
  const Eigen::MatrixXi F = index_matrix({{0, 1, 2}});
  const auto arrange_rows = [&](std::vector<ExactVec3> rows) {
    return arrangements::arrange(exact_matrix(rows), F, one_thread());
  };
  for (const Q& huge : {big + Q(1, 1000), -big - Q(1), big * Q(3, 2)})
    for (int c = 0; c < 3; ++c) {
      std::vector<ExactVec3> rows = V;
      rows[1][c] = huge;
      EXPECT_THROW(arrange_rows(rows), std::invalid_argument) << c;
    }
  std::vector<ExactVec3> extreme = V;
  extreme[1][0] = big;
  extreme[2][1] = -big;
  EXPECT_EQ(arrange_rows(extreme).F.rows(), 1);  // the largest double itself is fine
  const Eigen::Matrix<Q, Eigen::Dynamic, Eigen::Dynamic> two_columns(3, 2);
  EXPECT_THROW(arrangements::arrange(two_columns, F, one_thread()), std::invalid_argument);
  EXPECT_THROW(arrangements::arrange(exact_matrix(V), index_matrix({{0, 1, 3}}), one_thread()), std::invalid_argument);
  EXPECT_THROW(arrangements::arrange(exact_matrix(V), index_matrix({{0, -1, 2}}), one_thread()), std::invalid_argument);
  Eigen::VectorXi labels(2);
  labels << 0, 1;
  EXPECT_THROW(arrangements::arrange(exact_matrix(V), F, one_thread(), &labels), std::invalid_argument);
  labels.resize(1);
  labels << -1;
  EXPECT_THROW(arrangements::arrange(exact_matrix(V), F, one_thread(), &labels), std::invalid_argument);
  // Nothing to arrange: an empty result, not an error.
  EXPECT_EQ(arrangements::arrange(ExactV(0, 3), Eigen::MatrixXi(0, 3), one_thread()).V.rows(), 0);
}

TEST(ArrangeEigenExact, DoubleExpressionsStillTakeTheDoubleOverload) {
  Eigen::MatrixXd V(4, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 9, 9, 9;
  const Eigen::MatrixXi F = index_matrix({{0, 1, 2}});
  const EigenArrangement a = arrangements::arrange(V.topRows(3), F, one_thread());  // a block of doubles
  EXPECT_EQ(a.F.rows(), 1);
  EXPECT_TRUE(a.V_is_exact.all());
}

}  // namespace
