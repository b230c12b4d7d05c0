// tests/test_arrange_threads.cpp
//
// The arrangement does not depend on the number of threads: one and two threads give the
// same output (triangles, provenance, labels, exact vertices) on generated scenes and on
// two meshes of the shared collection, for both classifiers.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "arrangements/load_triangle_soup.h"
#include "support/arrangement_scenes.h"
#include "support/test_scale.h"
#include "support/triangulation_checks.h"
#include "support/shared_meshes.h"

namespace {

using namespace tritri_test::arrangement;
using tritri_test::test_scale;
namespace fs = std::filesystem;

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

}  // namespace
