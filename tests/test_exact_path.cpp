// The exact path (ExactModel: rational input, rational points) against the double path
// and against itself:
//   - on double input converted exactly, both paths build the same arrangement: the same
//     counts and the same set of exact vertex coordinates (numbering and triangulation
//     may differ: the models order new points differently);
//   - arranging an exact arrangement again finds nothing new (no LPI, no TPI, the same
//     vertices and triangle count) and both pass the exact validity check;
//   - the same at 2^k scalings and large offsets.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "arrangements/arrange.h"
#include "arrangements/as_input.h"
#include "arrangements/check_arrangement.h"
#include "support/arrangement_scenes.h"
#include "support/exact_soups.h"

namespace {

using namespace arrangements;
using namespace tritri_test;
using namespace tritri_test::arrangement;

void expect_same_arrangement(const ArrangeStats& a, const ArrangeStats& b, const std::string& what) {
  EXPECT_EQ(a.intersecting_pairs, b.intersecting_pairs) << what;
  EXPECT_EQ(a.coplanar_pairs, b.coplanar_pairs) << what;
  EXPECT_EQ(a.intersection_points, b.intersection_points) << what;
  EXPECT_EQ(a.tpi, b.tpi) << what;
  EXPECT_EQ(a.out_vertices, b.out_vertices) << what;
  EXPECT_EQ(a.out_triangles, b.out_triangles) << what;
  EXPECT_EQ(a.euler, b.euler) << what;
}

void expect_idempotent(const ExactOutputMesh& mesh, const ArrangeStats& first, const std::string& what) {
  const ExactArrangeResult again = arrange(as_input(mesh), ArrangeOptions{});
  EXPECT_EQ(again.stats.intersection_points, 0u) << what;
  EXPECT_EQ(again.stats.tpi, 0u) << what;
  EXPECT_EQ(again.stats.out_vertices, first.out_vertices) << what;
  EXPECT_EQ(again.stats.out_triangles, first.out_triangles) << what;
  EXPECT_EQ(again.stats.removed_degenerate, 0u) << what;
  EXPECT_EQ(again.stats.removed_duplicate, 0u) << what;
  EXPECT_TRUE(check_arrangement(again.mesh).ok()) << what;
  EXPECT_EQ(sorted_vertices(again.mesh), sorted_vertices(mesh)) << what;
}

TriangleSoup offset(TriangleSoup s, double d) {
  for (Vec3& v : s.vertices)
    for (double& x : v) x += d;
  return s;
}

TEST(ExactPath, AgreesWithTheDoublePathOnGeneratedScenes) {
  for (const auto& [name, soup] : generated_scenes()) {
    for (const auto& [variant, input] : {std::pair<std::string, TriangleSoup>{"", soup},
                                         {" x 2^-40", scaled_pow2(soup, -40)},
                                         {" x 2^60", scaled_pow2(soup, 60)},
                                         {" + 2^30", offset(soup, std::ldexp(1.0, 30))}}) {
      const std::string what = name + variant;
      const ArrangeResult d = arrange(input, ArrangeOptions{});
      const ExactArrangeResult e = arrange(to_exact(input), ArrangeOptions{});
      expect_same_arrangement(d.stats, e.stats, what);
      EXPECT_EQ(sorted_vertices(exact_mesh(d.mesh)), sorted_vertices(e.mesh)) << what;
      EXPECT_TRUE(check_arrangement(e.mesh).ok()) << what;
    }
  }
}

TEST(ExactPath, ArrangingAnArrangementAgainFindsNothingNew) {
  for (const auto& [name, soup] : generated_scenes()) {
    const ArrangeResult d = arrange(soup, ArrangeOptions{});
    expect_idempotent(exact_mesh(d.mesh), d.stats, name + " (double path's result)");
    const ExactArrangeResult e = arrange(to_exact(soup), ArrangeOptions{});
    expect_idempotent(e.mesh, e.stats, name + " (exact path's result)");
  }
}

TEST(ExactPath, ThreadsAndClassifiersAgree) {
  const TriangleSoup soup = three_spheres(6);
  ArrangeOptions one;
  one.threads = 1;
  ArrangeOptions native;
  native.classifier = Classifier::Native;
  const ExactArrangeResult a = arrange(to_exact(soup), one);
  const ExactArrangeResult b = arrange(to_exact(soup), native);
  expect_same_arrangement(a.stats, b.stats, "native vs tritri, 1 vs all threads");
  EXPECT_EQ(a.mesh.vertices, b.mesh.vertices);  // same classifier output: same numbering
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
}

}  // namespace
