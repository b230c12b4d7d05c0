// Specification of tritri::self_intersections (tritri/self_intersections.h) and
// tritri::intersections (tritri/intersections.h):
// - the output equals a brute-force classification of all pairs with the documented rule
//   (self: beyond the shared vertices, by index; two meshes: any common point), results
//   included, on generated meshes: overlapping spheres, rotated copies, grids with
//   coplanar overlaps and coincident vertices;
// - the rule on hand-made cases: neighbours, a fold, a duplicated face, a duplicated
//   vertex, a degenerate triangle;
// - sorted by (i, j), the same with one thread, any Eigen matrix type accepted;
// - bad input (columns, NaN / Inf, indices out of range) throws std::invalid_argument
//   naming the matrix.
#include <gtest/gtest.h>

#include "support/brute_force_mesh_pairs.h"
#include "support/mesh_generators.h"
#include <tbb/task_arena.h>
#include <tritri/classify.h>
#include <tritri/double_kernel.h>
#include <tritri/intersections.h>
#include <tritri/self_intersections.h>

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using arrangements::TriangleSoup;
using tritri::IntersectingPair;

struct Mesh {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
};

Mesh to_eigen(const TriangleSoup& s) {
  Mesh m{Eigen::MatrixXd(s.vertices.size(), 3), Eigen::MatrixXi(s.triangles.size(), 3)};
  for (std::size_t v = 0; v < s.vertices.size(); ++v)
    for (int c = 0; c < 3; ++c) m.V(v, c) = s.vertices[v][c];
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) m.F(t, c) = s.triangles[t][c];
  return m;
}

tritri::Result classify_rows(const Mesh& a, int i, const Mesh& b, int j) {
  auto p = [](const Mesh& m, int t, int c) {
    return tritri::DoubleKernel::Point{m.V(m.F(t, c), 0), m.V(m.F(t, c), 1), m.V(m.F(t, c), 2)};
  };
  return tritri::classify<tritri::DoubleKernel>(p(a, i, 0), p(a, i, 1), p(a, i, 2), p(b, j, 0), p(b, j, 1), p(b, j, 2));
}

std::vector<IntersectingPair> brute_force_self(const Mesh& m) {
  return tritri_test::brute_force_self(m, classify_rows);
}
std::vector<IntersectingPair> brute_force_two(const Mesh& a, const Mesh& b) {
  return tritri_test::brute_force_two(a, b, classify_rows);
}

Mesh concatenated(const TriangleSoup& a, const TriangleSoup& b) { return to_eigen(arrangements::concatenate(a, b)); }

TriangleSoup sphere_a() { return arrangements::uv_sphere({0, 0, 0}, 1.0, 10, 14); }
TriangleSoup sphere_b() { return arrangements::uv_sphere({0.7, 0.3, 0.2}, 0.8, 9, 12); }

TEST(SelfIntersections, EqualsBruteForceOnTwoOverlappingSpheresAsOneMesh) {
  const Mesh m = concatenated(sphere_a(), sphere_b());
  const auto expected = brute_force_self(m);
  EXPECT_GT(expected.size(), 20u);
  EXPECT_EQ(tritri::self_intersections(m.V, m.F), expected);
}

TEST(SelfIntersections, EqualsBruteForceOnRotatedCopiesOfASphere) {
  const Mesh m = to_eigen(arrangements::rotated_copies(arrangements::uv_sphere({0.2, 0, 0}, 1.0, 8, 10), 3));
  const auto expected = brute_force_self(m);
  EXPECT_GT(expected.size(), 20u);
  EXPECT_EQ(tritri::self_intersections(m.V, m.F), expected);
}

TEST(SelfIntersections, EqualsBruteForceOnGridsWithCoplanarOverlapsAndCoincidentVertices) {
  // Half-cell shift: coplanar overlaps everywhere. Whole-cell shift: corners at equal
  // coordinates with different indices, edges along edges.
  const Mesh half = concatenated(arrangements::grid(5, 1.0, 0.0), arrangements::grid(4, 1.0, 0.0, 0.5, 0.5));
  const Mesh whole = concatenated(arrangements::grid(4, 1.0, 0.0), arrangements::grid(4, 1.0, 0.0, 1.0, 0.0));
  for (const Mesh* m : {&half, &whole}) {
    const auto expected = brute_force_self(*m);
    EXPECT_GT(expected.size(), 20u);
    std::size_t coplanar = 0;
    for (const auto& p : expected) coplanar += p.result.coplanar;
    EXPECT_EQ(coplanar, expected.size());
    EXPECT_EQ(tritri::self_intersections(m->V, m->F), expected);
  }
}

TEST(SelfIntersections, OneGridHasNoSelfIntersections) {
  const Mesh m = to_eigen(arrangements::grid(6, 0.5, 1.0));
  EXPECT_TRUE(tritri::self_intersections(m.V, m.F).empty());
  const Mesh s = to_eigen(sphere_a());
  EXPECT_TRUE(tritri::self_intersections(s.V, s.F).empty());
}

TEST(SelfIntersections, RuleOnHandMadeCases) {
  Eigen::MatrixXd V(8, 3);
  V << 0, 0, 0,     //
      1, 0, 0,      //
      0, 1, 0,      //
      1, 1, 1,      // 3: with 1, 2 a neighbour of (0, 1, 2) across edge 1-2, bent up
      0.2, 0.2, 0,  // 4: folds (1, 2, 4) back over (0, 1, 2)
      0, 0, 0,      // 5: the coordinates of vertex 0 under another index
      -1, 0, 0,     // 6
      2, 0, 0;      // 7: (0, 1, 7) is degenerate (collinear)
  auto pairs_of = [&](const Eigen::MatrixXi& F) {
    std::vector<std::pair<int, int>> ij;
    for (const auto& p : tritri::self_intersections(V, F)) ij.emplace_back(p.i, p.j);
    return ij;
  };
  using Pairs = std::vector<std::pair<int, int>>;
  Eigen::MatrixXi neighbours(2, 3), fold(2, 3), duplicate(2, 3), touch(2, 3), degenerate(2, 3), corner(2, 3);
  neighbours << 0, 1, 2, 2, 1, 3;
  fold << 0, 1, 2, 2, 1, 4;
  duplicate << 0, 1, 2, 2, 1, 0;
  touch << 0, 1, 2, 5, 6, 3;   // meets (0, 1, 2) only at vertex 0's point, as vertex 5
  corner << 0, 1, 2, 0, 6, 3;  // the same contact through the shared index 0
  degenerate << 0, 1, 2, 0, 1, 7;
  EXPECT_EQ(pairs_of(neighbours), Pairs{});
  EXPECT_EQ(pairs_of(fold), (Pairs{{0, 1}}));
  EXPECT_EQ(pairs_of(duplicate), (Pairs{{0, 1}}));
  EXPECT_EQ(pairs_of(touch), (Pairs{{0, 1}}));
  EXPECT_EQ(pairs_of(corner), Pairs{});
  EXPECT_EQ(pairs_of(degenerate), Pairs{});

  const auto folded = tritri::self_intersections(V, fold);
  ASSERT_EQ(folded.size(), 1u);
  EXPECT_TRUE(folded[0].result.coplanar);
  EXPECT_EQ(folded[0].result, classify_rows({V, fold}, 0, {V, fold}, 1));
}

TEST(Intersections, EqualsBruteForceOnTwoSpheresAndOnShiftedGrids) {
  const Mesh a = to_eigen(sphere_a()), b = to_eigen(sphere_b());
  const auto expected = brute_force_two(a, b);
  EXPECT_GT(expected.size(), 20u);
  EXPECT_EQ(tritri::intersections(a.V, a.F, b.V, b.F), expected);

  const Mesh g = to_eigen(arrangements::grid(4, 1.0, 0.0)), h = to_eigen(arrangements::grid(4, 1.0, 0.0, 1.0, 0.5));
  const auto expected_grids = brute_force_two(g, h);
  EXPECT_GT(expected_grids.size(), 20u);
  EXPECT_EQ(tritri::intersections(g.V, g.F, h.V, h.F), expected_grids);
}

TEST(Intersections, ASingleCommonCornerCounts) {
  Eigen::MatrixXd V1(3, 3), V2(3, 3);
  V1 << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  V2 << 0, 0, 0, -1, 0, 0, 0, 0, 1;
  const Eigen::MatrixXi F = (Eigen::MatrixXi(1, 3) << 0, 1, 2).finished();
  const auto found = tritri::intersections(V1, F, V2, F);
  ASSERT_EQ(found.size(), 1u);
  ASSERT_EQ(found[0].result.points.size(), 1u);
  EXPECT_EQ(found[0].result.points[0], (tritri::IntersectionPoint{tritri::Type::VA_ON_VB, 0, 0}));
}

TEST(SelfIntersections, SortedAndTheSameWithOneThread) {
  const Mesh m = concatenated(arrangements::rotated_copies(sphere_a(), 2), sphere_b());
  const auto all = tritri::self_intersections(m.V, m.F);
  for (std::size_t k = 1; k < all.size(); ++k)
    EXPECT_TRUE(std::pair(all[k - 1].i, all[k - 1].j) < std::pair(all[k].i, all[k].j));
  tbb::task_arena one(1);
  std::vector<IntersectingPair> single;
  one.execute([&] { single = tritri::self_intersections(m.V, m.F); });
  EXPECT_EQ(single, all);
}

TEST(SelfIntersections, AcceptsOtherEigenTypesAndEmptyInput) {
  const Mesh m = concatenated(sphere_a(), sphere_b());
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
  const RowMajor V = m.V;
  const Eigen::Matrix<std::int64_t, Eigen::Dynamic, Eigen::Dynamic> F = m.F.cast<std::int64_t>();
  EXPECT_EQ(tritri::self_intersections(V, F), tritri::self_intersections(m.V, m.F));
  EXPECT_TRUE(tritri::self_intersections(Eigen::MatrixXd(), Eigen::MatrixXi()).empty());
  EXPECT_TRUE(tritri::self_intersections(m.V, Eigen::MatrixXi(0, 3)).empty());
  EXPECT_TRUE(tritri::intersections(m.V, m.F, Eigen::MatrixXd(), Eigen::MatrixXi()).empty());
}

// The message of the std::invalid_argument that f throws (empty if it throws nothing).
template <class Fn>
std::string invalid_argument_message(Fn f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(SelfIntersections, BadInputThrowsInvalidArgumentNamingTheMatrix) {
  Eigen::MatrixXd V(3, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  const Eigen::MatrixXi F = (Eigen::MatrixXi(1, 3) << 0, 1, 2).finished();
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();

  auto self = [](const Eigen::MatrixXd& v, const Eigen::MatrixXi& f) {
    return invalid_argument_message([&] { tritri::self_intersections(v, f); });
  };
  EXPECT_NE(self(Eigen::MatrixXd::Zero(3, 2), F).find("V must have 3 columns"), std::string::npos);
  EXPECT_NE(self(V, Eigen::MatrixXi::Zero(1, 4)).find("F must have 3 columns"), std::string::npos);
  Eigen::MatrixXd bad = V;
  bad(1, 2) = nan;
  EXPECT_NE(self(bad, F).find("V(1, 2)"), std::string::npos);
  bad(1, 2) = -inf;
  EXPECT_NE(self(bad, F).find("not a finite coordinate"), std::string::npos);
  Eigen::MatrixXi out = F;
  out(0, 1) = 3;
  EXPECT_NE(self(V, out).find("F(0, 1) = 3 is out of range"), std::string::npos);
  out(0, 1) = -1;
  EXPECT_NE(self(V, out).find("F(0, 1) = -1 is out of range"), std::string::npos);

  auto two = [](const Eigen::MatrixXd& v1, const Eigen::MatrixXi& f1, const Eigen::MatrixXd& v2,
                const Eigen::MatrixXi& f2) {
    return invalid_argument_message([&] { tritri::intersections(v1, f1, v2, f2); });
  };
  bad = V;
  bad(2, 0) = inf;
  EXPECT_NE(two(V, F, bad, F).find("V2(2, 0)"), std::string::npos);
  EXPECT_NE(two(bad, F, V, F).find("V1(2, 0)"), std::string::npos);
  out = F;
  out(0, 2) = 7;
  EXPECT_NE(two(V, F, V, out).find("F2(0, 2) = 7"), std::string::npos);
  EXPECT_NE(two(V, out, V, F).find("F1(0, 2) = 7"), std::string::npos);
  EXPECT_NE(two(V, F, Eigen::MatrixXd::Zero(2, 4), F).find("V2 must have 3 columns"), std::string::npos);
}

}  // namespace
