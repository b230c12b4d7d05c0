// tests/test_arrange_counts.cpp
//
// Simplex counts, Euler characteristics and TPIs of the arrangement of small scenes,
// derived by hand (in each case's comment), for both classifiers; triple points are single
// exact TPIs.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "support/arrangement_scenes.h"
#include "support/exact_oracle.h"
#include "support/triangulation_checks.h"

namespace {

using namespace tritri_test::arrangement;
using tritri_test::exact;
using tritri_test::Q;
using tritri_test::Q3;

// A triangulated polygon (a disc) with B boundary and I interior vertices and no other
// vertices has F = 2I + B - 2 triangles and E = 3I + 2B - 3 edges, whatever the
// triangulation (V - E + F = 1 and 3F + B = 2E). Gluing complexes: chi(X u Y) = chi(X) +
// chi(Y) - chi(X n Y).

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
  const std::set<Q3> ends = {{Q(-1), Q(0), Q(0)}, {Q(2), Q(0), Q(0)},  {Q(0), Q(-1), Q(0)},
                             {Q(0), Q(1), Q(0)},  {Q(0), Q(0), Q(-1)}, {Q(0), Q(0), Q(1)}};
  for (Classifier c : kClassifiers) {
    const Pipeline p = run_stages(three_triangles_triple_point(), c);
    std::set<Q3> lpis;
    for (std::size_t i = p.graph.num_input_vertices; i < p.graph.points.size(); ++i)
      lpis.insert(exact(p.graph.points[i]));
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

}  // namespace
