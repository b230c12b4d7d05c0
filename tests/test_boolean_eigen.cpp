// The Eigen Boolean API arrangements::boolean(V list, F list, op or tree, options)
// (arrangements/boolean_eigen.h): two cubes [0,2]^3 and [1,3]^3 (every output point is
// dyadic, so the double vertices are exact): union volume 15, intersection 1, difference
// 7, xor 14; the output is closed and consistently oriented; the exact overload agrees;
// bad input throws.
#include <CGAL/Gmpq.h>
#include <Eigen/Core>
#include <gtest/gtest.h>

#include <arrangements/boolean_eigen.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using arrangements::BooleanOp;

std::pair<Eigen::MatrixXd, Eigen::MatrixXi> cube(double lo, double hi) {
  Eigen::MatrixXd V(8, 3);
  for (int i = 0; i < 8; ++i) {
    V(i, 0) = (i & 1) ? hi : lo;
    V(i, 1) = (i & 2) ? hi : lo;
    V(i, 2) = (i & 4) ? hi : lo;
  }
  Eigen::MatrixXi F(12, 3);
  // Outward-oriented faces of the cube with corner i = x + 2y + 4z.
  F << 0, 2, 1, 1, 2, 3,  // z = lo
      4, 5, 6, 5, 7, 6,   // z = hi
      0, 1, 4, 1, 5, 4,   // y = lo
      2, 6, 3, 3, 6, 7,   // y = hi
      0, 4, 2, 2, 4, 6,   // x = lo
      1, 3, 5, 3, 7, 5;   // x = hi
  return {V, F};
}

// Six times the signed volume, exactly (the coordinates are dyadic).
CGAL::Gmpq volume(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  CGAL::Gmpq sum = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    auto p = [&](int c, int k) { return CGAL::Gmpq(V(F(f, c), k)); };
    sum += p(0, 0) * (p(1, 1) * p(2, 2) - p(1, 2) * p(2, 1)) - p(0, 1) * (p(1, 0) * p(2, 2) - p(1, 2) * p(2, 0)) +
           p(0, 2) * (p(1, 0) * p(2, 1) - p(1, 1) * p(2, 0));
  }
  return sum / 6;
}

// Every directed edge is matched by its reverse (closed and consistently oriented).
void expect_closed(const Eigen::MatrixXi& F, const std::string& what) {
  std::map<std::pair<int, int>, int> directed;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int c = 0; c < 3; ++c) ++directed[{F(f, c), F(f, (c + 1) % 3)}];
  for (const auto& [e, n] : directed) {
    const auto it = directed.find({e.second, e.first});
    EXPECT_TRUE(it != directed.end() && it->second == n) << what << ": edge " << e.first << " " << e.second;
  }
}

TEST(BooleanEigen, TwoCubesVolumes) {
  const auto [VA, FA] = cube(0, 2);
  const auto [VB, FB] = cube(1, 3);
  const std::vector<Eigen::MatrixXd> V{VA, VB};
  const std::vector<Eigen::MatrixXi> F{FA, FB};
  const std::vector<std::pair<BooleanOp, int>> cases{
      {BooleanOp::Union, 15}, {BooleanOp::Intersection, 1}, {BooleanOp::Difference, 7}, {BooleanOp::Xor, 14}};
  for (const auto& [op, expected] : cases) {
    const std::string what = "op " + std::to_string(static_cast<int>(op));
    const arrangements::EigenArrangement out = arrangements::boolean(V, F, op, {});
    ASSERT_GT(out.F.rows(), 0) << what;
    EXPECT_TRUE(out.V_is_exact.all()) << what;
    EXPECT_EQ(volume(out.V, out.F), CGAL::Gmpq(expected)) << what;
    expect_closed(out.F, what);
    EXPECT_EQ(out.source.size(), out.F.rows());
    EXPECT_EQ(out.label_set.size(), out.F.rows());
    for (Eigen::Index f = 0; f < out.F.rows(); ++f) {
      EXPECT_TRUE(out.source(f) >= 0 && out.source(f) < 24) << what;
      const arrangements::LabelSet& labels = out.label_sets.at(static_cast<std::size_t>(out.label_set(f)));
      // Rows 0..11 are operand 0's, 12..23 operand 1's: the source row's operand covers f.
      EXPECT_TRUE(std::find(labels.begin(), labels.end(), out.source(f) < 12 ? 0u : 1u) != labels.end()) << what;
    }
    EXPECT_EQ(static_cast<Eigen::Index>(out.vertices.size()), out.V.rows());

    // The same through a CsgNode, and the exact overload.
    const arrangements::EigenArrangement tree = arrangements::boolean(V, F, arrangements::operation_tree(op, 2), {});
    EXPECT_EQ(tree.F, out.F) << what;
    std::vector<arrangements::ExactOperandMatrix> VQ(2);
    for (int i = 0; i < 2; ++i) VQ[i] = V[i].cast<CGAL::Gmpq>();
    const arrangements::ExactEigenArrangement exact = arrangements::boolean(VQ, F, op, {});
    Eigen::MatrixXd rounded(exact.V.rows(), 3);
    for (Eigen::Index r = 0; r < exact.V.rows(); ++r)
      for (int c = 0; c < 3; ++c) {
        rounded(r, c) = CGAL::to_double(exact.V(r, c));
        EXPECT_EQ(CGAL::Gmpq(rounded(r, c)), exact.V(r, c));
      }
    EXPECT_EQ(volume(rounded, exact.F), CGAL::Gmpq(expected)) << what;
    expect_closed(exact.F, what + " exact");
  }
}

TEST(BooleanEigen, BadInput) {
  const auto [VA, FA] = cube(0, 2);
  Eigen::MatrixXi open = FA.topRows(11);
  EXPECT_THROW(arrangements::boolean(std::vector<Eigen::MatrixXd>{}, std::vector<Eigen::MatrixXi>{},
                                     BooleanOp::Union, {}),
               std::invalid_argument);
  EXPECT_THROW(arrangements::boolean(std::vector<Eigen::MatrixXd>{VA}, std::vector<Eigen::MatrixXi>{},
                                     BooleanOp::Union, {}),
               std::invalid_argument);
  Eigen::MatrixXi out_of_range = FA;
  out_of_range(0, 0) = 8;  // a row of the second operand's V once concatenated: refused
  EXPECT_THROW(arrangements::boolean(std::vector<Eigen::MatrixXd>{VA, VA}, std::vector<Eigen::MatrixXi>{out_of_range, FA},
                                     BooleanOp::Union, {}),
               std::invalid_argument);
  try {
    arrangements::boolean(std::vector<Eigen::MatrixXd>{VA, VA}, std::vector<Eigen::MatrixXi>{FA, open},
                          BooleanOp::Union, {});
    FAIL() << "an open operand was accepted";
  } catch (const arrangements::OpenOperandError& e) {
    EXPECT_EQ(e.operand, 1);
    EXPECT_NE(std::string(e.what()).find("operand 1 is not closed"), std::string::npos) << e.what();
  }
}

}  // namespace
