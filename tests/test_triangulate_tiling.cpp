// tests/test_triangulate_tiling.cpp
//
// The triangulation stage (stages/5_triangulate.h), checked exactly: every output
// triangle lies in its source triangle, and per soup triangle the output triangles
// covering it tile it exactly (areas as rationals); owner and label set follow from which
// soup triangles cover it; a coplanar overlap is emitted once. On the generated scenes and
// the small hand-made configurations of the shared collection (with the graph and
// all-pairs checks too); the tiling check refuses wrong output.
// Sizes scale with TRITRI_TEST_SCALE (default 1; sanitizer runs use 0.1).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "arrangements/load_triangle_soup.h"
#include "support/arrangement_scenes.h"
#include "support/exact_oracle.h"
#include "support/test_scale.h"
#include "support/triangulation_checks.h"
#include "support/shared_meshes.h"

namespace {

using namespace tritri_test::arrangement;
using tritri_test::area2;
using tritri_test::exact;
using tritri_test::Q;
using tritri_test::test_scale;
namespace fs = std::filesystem;

TEST(Triangulate, OutputTrianglesTileTheirSourcesExactly) {
  for (const auto& [name, soup] : generated_scenes()) {
    if (name.rfind("rotated", 0) == 0) continue;  // covered below at a smaller size
    for (Classifier c : kClassifiers)
      expect_no_problems(tiling_problems(run_stages(soup, c)), name + " (" + name_of(c) + ")");
  }
  expect_no_problems(
      tiling_problems(run_stages(rotated_copies(uv_sphere({0, 0, 0}, 1.0, 5, 6), 3), Classifier::Tritri)),
      "rotated spheres");
  expect_no_problems(tiling_problems(run_stages(rotated_copies(box({0, 0, 0}, {2, 1, 1}), 4), Classifier::Tritri)),
                     "rotated boxes");
  expect_no_problems(tiling_problems(run_stages(rotated_copies(grid(3, 1.0, 0.0), 3), Classifier::Tritri)),
                     "rotated grids");
  expect_no_problems(tiling_problems(run_stages(overlapping_triangles(true), Classifier::Native)),
                     "overlapping triangles");
}

// Coplanar overlaps are emitted once: the total area is the area of the union, by hand.
TEST(Triangulate, CoplanarOverlapIsEmittedOnce) {
  struct Case {
    std::string name;
    TriangleSoup soup;
    Q union_area2;  // twice the area of the union in the XY projection
  };
  const std::vector<Case> cases = {
      {"overlapping squares", overlapping_squares(), Q(2 * 7)},            // 4 + 4 - 1
      {"overlapping triangles", overlapping_triangles(false), Q(2 * 14)},  // 8 + 8 - 2
      {"coplanar grids", coplanar_grids(), Q(2 * 36)},                     // the second grid is inside the first
      {"grids sharing cells", grids_sharing_cells(), Q(2 * 20)},           // [0,5] x [0,4]
      {"star of David", kIntegerStar.soup(), Q(2 * 96)},                   // 72 + 72 - 48 (hexagon)
  };
  for (const auto& cs : cases)
    for (Classifier c : kClassifiers) {
      const ArrangeResult r = run_arrange(cs.soup, c);
      Q total = 0;
      for (const Tri& t : r.mesh.triangles)
        total +=
            abs(area2(exact(r.mesh.vertices[t[0]]), exact(r.mesh.vertices[t[1]]), exact(r.mesh.vertices[t[2]]), 2));
      EXPECT_EQ(total, cs.union_area2) << cs.name << " (" << name_of(c) << ")";
    }
}

// The tiling check must be able to fail: a triangulation with a triangle moved out of its
// source, or with a triangle missing, is refused.
TEST(Triangulate, TilingCheckRefusesWrongOutput) {
  Pipeline p = run_stages(two_triangles_crossing(), Classifier::Tritri);
  Pipeline missing = p;
  missing.tr.triangles.pop_back();
  missing.tr.owner.pop_back();
  missing.tr.label_set.pop_back();
  EXPECT_TRUE(mentions(tiling_problems(missing), "covered area"));
  Pipeline wrong_owner = p;
  wrong_owner.tr.owner[0] = 1 - wrong_owner.tr.owner[0];
  EXPECT_TRUE(mentions(tiling_problems(wrong_owner), "owner"));
  EXPECT_TRUE(tiling_problems(p).empty());
}

// The small hand-made configurations of the shared collection (2 and 3 triangles touching
// in every degenerate way) and its two_spheres / three_cubes: tiling, graph and an
// independent all-pairs check of the output.
TEST(Triangulate, SmallSharedConfigurationsPassAllExactChecks) {
  const fs::path dir = tritri_test::shared_meshes_dir() / "cherchi_arrangements";
  TRITRI_REQUIRE_DATA(dir);
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  int checked = 0;
  for (const fs::path& f : files) {
    const std::string ext = f.extension().string();
    if (ext != ".off" && ext != ".stl") continue;
    const TriangleSoup input = load_triangle_soup(f.string());
    if (input.triangles.size() > static_cast<std::size_t>(4000 * test_scale())) continue;
    for (Classifier c : kClassifiers) {
      const std::string what = f.filename().string() + " (" + name_of(c) + ")";
      const Pipeline p = run_stages(input, c);
      expect_no_problems(tiling_problems(p), what);
      expect_no_problems(graph_problems(p), what);
      if (p.tr.triangles.size() <= 400) expect_no_problems(all_pairs_problems(p.tr.points, p.tr.triangles), what);
    }
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

}  // namespace
