// Idempotence on every shared mesh (issue 14): the exact arrangement of a mesh, arranged
// again on the exact path, finds no new point (no LPI, no TPI), keeps every vertex and
// triangle, and both outputs pass the exact validity check. The exact coordinates go
// through the writer and the loader, as `arrange M -o A.obj --exact; arrange A.obj` does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "arrangements/arrange.h"
#include "arrangements/as_input.h"
#include "arrangements/check_arrangement.h"
#include "arrangements/load_triangle_soup.h"
#include "arrangements/write_mesh.h"
#include "support/exact_soups.h"
#include "support/loadable_meshes.h"
#include "support/shared_meshes.h"
#include "support/temp_dir.h"
#include "support/test_scale.h"

namespace {

namespace fs = std::filesystem;
using namespace arrangements;

TEST(Iterate, ArrangingAnExactArrangementAgainFindsNothingNew) {
  const fs::path dir = tritri_test::shared_meshes_dir();
  TRITRI_REQUIRE_DATA(dir);
  tritri_test::TempDir tmp;
  // Below scale 1 (sanitizer runs), every n-th file only.
  const double scale = tritri_test::test_scale();
  const std::size_t every = scale < 1 ? static_cast<std::size_t>(std::lround(1 / scale)) : 1;
  std::size_t index = 0;
  int iterated = 0, with_new_points = 0;
  tritri_test::for_each_loadable_mesh(dir, [&](const fs::path& f, const TriangleSoup& input) {
    if (index++ % every != 0) return;
    const ArrangeResult first = arrange(input, ArrangeOptions{});
    const fs::path exact_file = tmp.path() / "a.obj";
    write_mesh(exact_file.string(), first.mesh, WriteOptions{.exact = true});
    const AnyTriangleSoup loaded = load_mesh_files({exact_file.string()});
    const std::string name = f.string();
    const ExactTriangleSoup* exact = std::get_if<ExactTriangleSoup>(&loaded);
    ExactTriangleSoup converted;
    if (!exact) {  // no new point, or all of them doubles: the file holds doubles only
      converted = arrangements::to_exact(std::get<TriangleSoup>(loaded));
      exact = &converted;
    }
    const ExactArrangeResult again = arrange(*exact, ArrangeOptions{});
    const ArrangeStats& s = again.stats;
    EXPECT_EQ(s.intersection_points, 0u) << name;
    EXPECT_EQ(s.tpi, 0u) << name;
    EXPECT_EQ(s.intersecting_pairs, 0u) << name;
    EXPECT_EQ(s.merged_vertices + s.removed_degenerate + s.removed_duplicate, 0u) << name;
    EXPECT_EQ(s.out_vertices, first.stats.out_vertices) << name;
    EXPECT_EQ(s.out_triangles, first.stats.out_triangles) << name;
    const ArrangementCheck c1 = check_arrangement(first.mesh);
    EXPECT_TRUE(c1.ok()) << name << ": " << (c1.examples.empty() ? "" : c1.examples.front());
    const ArrangementCheck c2 = check_arrangement(again.mesh);
    EXPECT_TRUE(c2.ok()) << name << " (again): " << (c2.examples.empty() ? "" : c2.examples.front());
    with_new_points += first.stats.intersection_points > 0;
    ++iterated;
  });
  EXPECT_GT(with_new_points, 0);
  std::printf("iterated %d shared meshes (%d with intersection points)\n", iterated, with_new_points);
}

}  // namespace
