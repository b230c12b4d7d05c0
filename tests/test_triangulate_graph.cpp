// tests/test_triangulate_graph.cpp
//
// The intersection graph survives the triangulation: every intersection point is an
// output vertex and every constraint segment a chain of output edges (stage by stage; the
// check refuses missing pieces); through arrange(), every graph point's exact position is
// an output vertex and every output triangle lies in the input triangle its source names.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <set>
#include <string>

#include "pipeline.h"
#include "support/arrangement_scenes.h"
#include "support/exact_oracle.h"
#include "support/triangulation_checks.h"

namespace {

using namespace tritri_test::arrangement;
using tritri_test::exact;
using tritri_test::in_closed_triangle;
using tritri_test::orient3d;
using tritri_test::projection_axis;
using tritri_test::Q3;

TEST(Triangulate, GraphPointsAndConstraintsAreInTheOutput) {
  for (const auto& [name, soup] : generated_scenes())
    for (Classifier c : kClassifiers)
      expect_no_problems(graph_problems(run_stages(soup, c)), name + " (" + name_of(c) + ")");
}

// The check must be able to fail: drop the output triangles at one intersection point.
TEST(Triangulate, GraphCheckRefusesMissingPieces) {
  Pipeline p = run_stages(two_triangles_crossing(), Classifier::Tritri);
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

}  // namespace
