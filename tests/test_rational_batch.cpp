// tritri::self_intersections and tritri::intersections on exact rational coordinates
// (Eigen matrices of CGAL::Gmpq, tritri::RationalKernel):
// - on meshes of doubles given as rationals, exactly the double path's output (pairs and
//   results): overlapping spheres, rotated copies, coplanar grids; also with one mesh of
//   doubles and one of rationals;
// - on non-dyadic meshes (thirds and sevenths: grids and near-degenerate configurations),
//   the brute-force classification of all pairs with an unfiltered rational CGAL kernel
//   (Simple_cartesian<Gmpq>) and the documented rule written out directly;
// - contacts that only exist exactly (a vertex at 1/3 on a plane): found, where the rounded
//   doubles miss them;
// - bad input (coordinates beyond the double range, wrong shapes) throws
//   std::invalid_argument naming the matrix.
#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>  // before Eigen is used with it
#include <CGAL/Simple_cartesian.h>

#include "support/brute_force_mesh_pairs.h"
#include "support/mesh_generators.h"
#include <tritri/cgal_kernel.h>
#include <tritri/classify.h>
#include <tritri/intersections.h>
#include <tritri/rational_kernel.h>
#include <tritri/self_intersections.h>

#include <Eigen/Core>

#include <cfloat>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using arrangements::TriangleSoup;
using CGAL::Gmpq;
using tritri::IntersectingPair;
using RationalMatrix = Eigen::Matrix<Gmpq, Eigen::Dynamic, 3>;
using Unfiltered = tritri::CgalKernel<CGAL::Simple_cartesian<Gmpq>>;

struct RationalMesh {
  RationalMatrix V;
  Eigen::MatrixXi F;
};

RationalMesh rational(const TriangleSoup& s) {
  RationalMesh m{RationalMatrix(s.vertices.size(), 3), Eigen::MatrixXi(s.triangles.size(), 3)};
  for (std::size_t v = 0; v < s.vertices.size(); ++v)
    for (int c = 0; c < 3; ++c) m.V(v, c) = Gmpq(s.vertices[v][c]);
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) m.F(t, c) = s.triangles[t][c];
  return m;
}

Eigen::MatrixXd doubles(const TriangleSoup& s) {
  Eigen::MatrixXd V(s.vertices.size(), 3);
  for (std::size_t v = 0; v < s.vertices.size(); ++v)
    for (int c = 0; c < 3; ++c) V(v, c) = s.vertices[v][c];
  return V;
}

Eigen::MatrixXi faces(const TriangleSoup& s) { return rational(s).F; }

tritri::Result classify_rows(const RationalMesh& a, int i, const RationalMesh& b, int j) {
  using P = Unfiltered::Point;
  auto p = [](const RationalMesh& m, int t, int c) {
    return P(m.V(m.F(t, c), 0), m.V(m.F(t, c), 1), m.V(m.F(t, c), 2));
  };
  return tritri::classify<Unfiltered>(p(a, i, 0), p(a, i, 1), p(a, i, 2), p(b, j, 0), p(b, j, 1), p(b, j, 2));
}

std::vector<IntersectingPair> brute_force_self(const RationalMesh& m) {
  return tritri_test::brute_force_self(m, classify_rows);
}
std::vector<IntersectingPair> brute_force_two(const RationalMesh& a, const RationalMesh& b) {
  return tritri_test::brute_force_two(a, b, classify_rows);
}

// The soup (integer coordinates) scaled to thirds, sevenths and 21sts: vertex (x, y, z)
// becomes (x / 3, y / 7, z / 21 + z_offset), not dyadic.
RationalMesh non_dyadic(const TriangleSoup& s, const Gmpq& z_offset) {
  RationalMesh m = rational(s);
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) {
    m.V(v, 0) = m.V(v, 0) / Gmpq(3);
    m.V(v, 1) = m.V(v, 1) / Gmpq(7);
    m.V(v, 2) = m.V(v, 2) / Gmpq(21) + z_offset;
  }
  return m;
}

RationalMesh joined(const RationalMesh& a, const RationalMesh& b) {
  RationalMesh m{RationalMatrix(a.V.rows() + b.V.rows(), 3), Eigen::MatrixXi(a.F.rows() + b.F.rows(), 3)};
  m.V << a.V, b.V;
  m.F << a.F, (b.F.array() + static_cast<int>(a.V.rows())).matrix();
  return m;
}

TEST(RationalBatch, DoublesAsRationalsGiveTheDoublePathsOutput) {
  const TriangleSoup spheres = arrangements::concatenate(arrangements::uv_sphere({0, 0, 0}, 1.0, 10, 14),
                                                         arrangements::uv_sphere({0.7, 0.3, 0.2}, 0.8, 9, 12));
  const TriangleSoup copies = arrangements::rotated_copies(arrangements::uv_sphere({0.2, 0, 0}, 1.0, 8, 10), 3);
  const TriangleSoup grids =
      arrangements::concatenate(arrangements::grid(5, 1.0, 0.0), arrangements::grid(4, 1.0, 0.0, 0.5, 0.5));
  for (const TriangleSoup* s : {&spheres, &copies, &grids}) {
    const auto expected = tritri::self_intersections(doubles(*s), faces(*s));
    EXPECT_GT(expected.size(), 20u);
    const RationalMesh m = rational(*s);
    EXPECT_EQ(tritri::self_intersections(m.V, m.F), expected);
  }
  const TriangleSoup a = arrangements::uv_sphere({0, 0, 0}, 1.0, 10, 14), b = arrangements::grid(6, 0.4, 0.1, -1, -1);
  const auto expected = tritri::intersections(doubles(a), faces(a), doubles(b), faces(b));
  EXPECT_GT(expected.size(), 10u);
  const RationalMesh ra = rational(a), rb = rational(b);
  EXPECT_EQ(tritri::intersections(ra.V, ra.F, rb.V, rb.F), expected);
  // One mesh of doubles, one of rationals: the doubles are taken exactly.
  EXPECT_EQ(tritri::intersections(doubles(a), faces(a), rb.V, rb.F), expected);
  EXPECT_EQ(tritri::intersections(ra.V, ra.F, doubles(b), faces(b)), expected);
}

TEST(RationalBatch, NonDyadicMeshesEqualTheBruteForceRule) {
  // Grids of thirds and sevenths: one shifted by half a cell in the same plane (coplanar
  // overlaps), one through it at a slant, one 1/21 above (no contact), one whose corners
  // lie exactly on the first's edges and vertices.
  const RationalMesh base = non_dyadic(arrangements::grid(4, 1.0, 0.0), Gmpq(0));
  const RationalMesh shifted = non_dyadic(arrangements::grid(4, 1.0, 0.0, 0.5, 0.5), Gmpq(0));
  RationalMesh slanted = non_dyadic(arrangements::grid(4, 1.0, 0.0, 0.25, -0.5), Gmpq(0));
  for (Eigen::Index v = 0; v < slanted.V.rows(); ++v) slanted.V(v, 2) = slanted.V(v, 0) / Gmpq(5) - Gmpq(1, 10);
  const RationalMesh above = non_dyadic(arrangements::grid(4, 1.0, 0.0), Gmpq(1, 21));
  const RationalMesh on_edges = non_dyadic(arrangements::grid(3, 1.0, 0.0, 1.0, 0.5), Gmpq(0));
  for (const RationalMesh* other : std::vector<const RationalMesh*>{&shifted, &slanted, &above, &on_edges}) {
    SCOPED_TRACE(other == &shifted   ? "shifted"
                 : other == &slanted ? "slanted"
                 : other == &above   ? "above"
                                     : "on edges");
    const RationalMesh m = joined(base, *other);
    const auto expected = brute_force_self(m);
    EXPECT_EQ(tritri::self_intersections(m.V, m.F), expected);
    EXPECT_EQ(tritri::intersections(base.V, base.F, other->V, other->F), brute_force_two(base, *other));
    if (other == &above)
      EXPECT_TRUE(expected.empty());
    else
      EXPECT_GT(expected.size(), 10u);
  }
}

TEST(RationalBatch, FindsContactsThatOnlyExistExactly) {
  // A lies in x + y + z = 1; B's first corner is A's centroid (1/3, 1/3, 1/3), on A
  // exactly; its other corners are above the plane. Rounded to doubles the centroid is off
  // the plane, so the contact is gone (or moved): exactly it is one point, VB_ON_TA.
  RationalMatrix VA(3, 3), VB(3, 3);
  VA << Gmpq(1), Gmpq(0), Gmpq(0), Gmpq(0), Gmpq(1), Gmpq(0), Gmpq(0), Gmpq(0), Gmpq(1);
  VB << Gmpq(1, 3), Gmpq(1, 3), Gmpq(1, 3), Gmpq(1), Gmpq(1), Gmpq(1), Gmpq(2), Gmpq(1), Gmpq(1);
  const Eigen::MatrixXi F = (Eigen::MatrixXi(1, 3) << 0, 1, 2).finished();
  const auto found = tritri::intersections(VA, F, VB, F);
  ASSERT_EQ(found.size(), 1u);
  ASSERT_EQ(found[0].result.points.size(), 1u);
  EXPECT_EQ(found[0].result.points[0].type, tritri::Type::VB_ON_TA);
  EXPECT_EQ(found[0].result.points[0].id0, 0);

  Eigen::MatrixXd DA(3, 3), DB(3, 3);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      DA(r, c) = CGAL::to_double(VA(r, c));
      DB(r, c) = CGAL::to_double(VB(r, c));
    }
  const auto rounded = tritri::intersections(DA, F, DB, F);
  EXPECT_TRUE(rounded.empty() || rounded[0].result.points != found[0].result.points);

  // In one mesh: the same contact, between two triangles that share no vertex.
  RationalMatrix V(6, 3);
  V << VA, VB;
  const Eigen::MatrixXi F2 = (Eigen::MatrixXi(2, 3) << 0, 1, 2, 3, 4, 5).finished();
  const auto self = tritri::self_intersections(V, F2);
  ASSERT_EQ(self.size(), 1u);
  EXPECT_EQ(self[0].result.points, found[0].result.points);
}

TEST(RationalBatch, BadInputThrowsNamingTheMatrix) {
  const Eigen::MatrixXi F = (Eigen::MatrixXi(1, 3) << 0, 1, 2).finished();
  RationalMatrix V(3, 3);
  V << Gmpq(0), Gmpq(0), Gmpq(0), Gmpq(1), Gmpq(0), Gmpq(0), Gmpq(0), Gmpq(1), Gmpq(0);
  auto message = [](auto&& call) {
    try {
      call();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  RationalMatrix huge = V;
  huge(1, 2) = Gmpq(DBL_MAX) * Gmpq(2);
  EXPECT_NE(message([&] { tritri::self_intersections(huge, F); }).find("self_intersections: V(1, 2) is beyond"),
            std::string::npos);
  EXPECT_NE(message([&] { tritri::intersections(V, F, huge, F); }).find("intersections: V2(1, 2) is beyond"),
            std::string::npos);
  huge(1, 2) = -Gmpq(DBL_MAX);  // the largest magnitude itself is fine
  EXPECT_NO_THROW(tritri::self_intersections(huge, F));
  const Eigen::Matrix<Gmpq, Eigen::Dynamic, Eigen::Dynamic> two_columns(3, 2);
  EXPECT_NE(message([&] { tritri::self_intersections(two_columns, F); }).find("V must have 3 columns"),
            std::string::npos);
  const Eigen::MatrixXi out_of_range = (Eigen::MatrixXi(1, 3) << 0, 1, 3).finished();
  EXPECT_NE(message([&] { tritri::self_intersections(V, out_of_range); }).find("F(0, 2) = 3 is out of range"),
            std::string::npos);
}

}  // namespace
