// tests/test_arrangement_validity.cpp
//
// The arrangement's output triangles meet only in shared vertices and shared edges:
// check_arrangement (what `arrange --check` runs) on the generated scenes and on every
// shared mesh up to a size limit, and an independent all-pairs classification of the
// output (support/triangulation_checks.h) on small scenes; that check refuses bad meshes.
// Both classifiers. Sizes scale with TRITRI_TEST_SCALE (default 1; sanitizer runs use 0.1).
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "arrangements/check_arrangement.h"
#include "arrangements/input_error.h"
#include "arrangements/load_triangle_soup.h"
#include "support/arrangement_scenes.h"
#include "support/test_scale.h"
#include "support/triangulation_checks.h"
#include "support/shared_meshes.h"

namespace {

using namespace tritri_test::arrangement;
using tritri_test::test_scale;
namespace fs = std::filesystem;

TEST(Arrangement, GeneratedScenesPassCheckArrangement) {
  for (const auto& [name, soup] : generated_scenes()) {
    const ArrangeResult native = run_arrange(soup, Classifier::Native);
    const ArrangeResult tritri = run_arrange(soup, Classifier::Tritri);
    for (const ArrangeResult* r : {&native, &tritri}) {
      expect_stats_match_mesh(*r, name);
      if (r == &tritri && same_output(tritri.mesh, native.mesh)) continue;  // checked already
      const ArrangementCheck check = check_arrangement(r->mesh);
      EXPECT_TRUE(check.ok()) << name << " (" << r->stats.classifier << "): " << check.violations << " violations, "
                              << check.degenerate_triangles << " degenerate; "
                              << (check.examples.empty() ? "" : check.examples.front());
      EXPECT_GT(check.pairs_checked, 0u) << name;
    }
  }
}

TEST(Arrangement, SmallScenesPassIndependentAllPairsCheck) {
  for (const auto& [name, soup] : std::vector<std::pair<std::string, TriangleSoup>>{
           {"two triangles crossing", two_triangles_crossing()},
           {"triangle pierced", triangle_pierced()},
           {"cube through cube", cube_through_cube()},
           {"overlapping squares", overlapping_squares()},
           {"overlapping triangles", overlapping_triangles(false)},
           {"star of David", kIntegerStar.soup()},
           {"rational star", kRationalStar.soup()},
           {"grids sharing cells", grids_sharing_cells()},
           {"rotated grids", rotated_copies(grid(2, 1.0, 0.0), 3)},
           {"small spheres", concatenate(uv_sphere({0, 0, 0}, 1, 4, 6), uv_sphere({0.5, 0.2, 0.1}, 0.9, 5, 5))}})
    for (Classifier c : kClassifiers) {
      const ArrangeResult r = run_arrange(soup, c);
      expect_no_problems(all_pairs_problems(r.mesh.vertices, r.mesh.triangles), name + " (" + name_of(c) + ")");
    }
}

// The checker itself must be able to fail: an overlapping pair, a crossing pair and two
// vertices at one position are refused.
TEST(Arrangement, IndependentCheckRefusesBadMeshes) {
  auto P = [](double x, double y, double z) { return ImplicitPoint::explicit_point(x, y, z); };
  // Two coplanar triangles overlapping (sharing an edge, folded onto the same side).
  const std::vector<ImplicitPoint> pts = {P(0, 0, 0), P(4, 0, 0), P(0, 4, 0), P(1, 1, 0), P(0, 0, 0)};
  EXPECT_TRUE(mentions(all_pairs_problems(pts, {{0, 1, 2}, {0, 1, 3}}), "improperly"));
  // Same position under two ids.
  EXPECT_TRUE(mentions(all_pairs_problems(pts, {{0, 1, 2}, {4, 2, 1}}), "two vertices"));
  // A proper pair sharing an edge passes.
  std::vector<ImplicitPoint> fine = pts;
  fine.push_back(P(2, -2, 0));
  EXPECT_TRUE(all_pairs_problems(fine, {{0, 1, 2}, {1, 0, 5}}).empty());
  OutputMesh m;
  m.vertices = pts;
  m.triangles = {{0, 1, 2}, {0, 1, 3}};
  EXPECT_FALSE(check_arrangement(m).ok());
}

// check_arrangement_touching finds exactly the violations of check_arrangement that have a
// marked triangle: random soups (crossing, touching, sharing vertices), random marks.
TEST(Arrangement, CheckTouchingIsTheFullCheckRestrictedToTheMarks) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> coordinate(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    RoundedMesh m;
    for (int v = 0; v < 60; ++v) m.vertices.push_back({coordinate(rng), coordinate(rng), coordinate(rng) / 8});
    std::uniform_int_distribution<int> vertex(0, 59);
    while (m.triangles.size() < 40) {
      const Tri f{vertex(rng), vertex(rng), vertex(rng)};
      if (f[0] != f[1] && f[1] != f[2] && f[0] != f[2]) m.triangles.push_back(f);
    }
    m.source.assign(m.triangles.size(), 0);
    m.label_set.assign(m.triangles.size(), 0);
    m.label_sets = {{0}};
    const ArrangementCheck full = check_arrangement(m, 0);
    ASSERT_GT(full.violations, 0u) << trial;
    std::vector<char> marked(m.triangles.size());
    for (char& c : marked) c = rng() % 4 == 0;
    std::vector<std::pair<int, int>> expected;
    for (const auto& [i, j] : full.violating_pairs)
      if (marked[i] || marked[j]) expected.emplace_back(i, j);
    const ArrangementCheck part = check_arrangement_touching(m, marked, 0);
    EXPECT_EQ(part.violating_pairs, expected) << trial;
    EXPECT_LE(part.pairs_checked, full.pairs_checked) << trial;
    EXPECT_EQ(check_arrangement_touching(m, std::vector<char>(m.triangles.size(), 1), 0).violating_pairs,
              full.violating_pairs)
        << trial;
    EXPECT_TRUE(check_arrangement_touching(m, std::vector<char>(m.triangles.size(), 0), 0).ok()) << trial;
  }
  EXPECT_THROW(check_arrangement_touching(RoundedMesh{}, std::vector<char>(1), 0), std::invalid_argument);
}

// Whether triangles i and j of m meet beyond what they share by index, by CGAL's exact
// intersection on rationals: independent of tritri and of stage 2's early-outs.
bool meet_beyond_shared(const RoundedMesh& m, int i, int j) {
  using EK = CGAL::Simple_cartesian<CGAL::Gmpq>;
  auto point = [&](int v) { return EK::Point_3(m.vertices[v][0], m.vertices[v][1], m.vertices[v][2]); };
  auto triangle = [&](const Tri& f) { return EK::Triangle_3(point(f[0]), point(f[1]), point(f[2])); };
  const Tri &a = m.triangles[i], &b = m.triangles[j];
  std::vector<int> shared;
  for (int v : a)
    if (std::find(b.begin(), b.end(), v) != b.end()) shared.push_back(v);
  if (shared.size() == 3) return true;
  if (!CGAL::do_intersect(triangle(a), triangle(b))) return false;
  const auto meet = CGAL::intersection(triangle(a), triangle(b));
  if (shared.empty()) return true;
  if (shared.size() == 1) {
    const EK::Point_3* p = boost::get<EK::Point_3>(&*meet);
    return p == nullptr || *p != point(shared[0]);
  }
  const EK::Segment_3* s = boost::get<EK::Segment_3>(&*meet);
  const EK::Segment_3 edge(point(shared[0]), point(shared[1]));
  return s == nullptr || (*s != edge && *s != edge.opposite());
}

// check_arrangement on rounded meshes (stage 2's early-outs, then tritri on what they keep)
// and check_arrangement_touching list exactly the pairs CGAL's exact intersection finds
// meeting beyond what they share (rationals): two height fields over offset grids crossing each other,
// with flat (coplanar) runs of triangles, and a fan of 48 triangles (a hub) through them;
// with and without a repeated triangle (which stage 2's preconditions exclude).
TEST(Arrangement, CheckOfRoundedMeshesEqualsExactIntersectionsOfEveryPair) {
  std::mt19937 rng(38);
  for (int trial = 0; trial < 6; ++trial) {
    RoundedMesh m;
    auto field = [&](double offset, int n) {
      const int first = static_cast<int>(m.vertices.size());
      std::uniform_int_distribution<int> height(0, 2);
      for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) m.vertices.push_back({x + offset, y + offset, height(rng) / 2.0});
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
          const int v = first + y * (n + 1) + x;
          m.triangles.push_back({v, v + 1, v + n + 2});
          m.triangles.push_back({v, v + n + 2, v + n + 1});
        }
    };
    field(0, 5);
    field(0.5, 4);
    const int hub = static_cast<int>(m.vertices.size());
    m.vertices.push_back({2.25, 2.75, 0.5});
    for (int k = 0; k < 48; ++k) {
      const double angle = 2 * M_PI * k / 48, tilt = 0.3 * std::sin(3 * angle) * (trial + 1) / 6;
      m.vertices.push_back({2.25 + 2 * std::cos(angle), 2.75 + 2 * std::sin(angle), 0.5 + tilt});
    }
    for (int k = 0; k < 48; ++k) m.triangles.push_back({hub, hub + 1 + k, hub + 1 + (k + 1) % 48});
    if (trial % 2 == 1) m.triangles.push_back(m.triangles[trial]);
    m.source.assign(m.triangles.size(), 0);
    m.label_set.assign(m.triangles.size(), 0);
    m.label_sets = {{0}};
    std::vector<std::pair<int, int>> expected;
    const int nt = static_cast<int>(m.triangles.size());
    for (int i = 0; i < nt; ++i)
      for (int j = i + 1; j < nt; ++j)
        if (meet_beyond_shared(m, i, j)) expected.emplace_back(i, j);
    ASSERT_GT(expected.size(), 20u) << trial;
    EXPECT_EQ(check_arrangement(m, 0).violating_pairs, expected) << trial;
    std::vector<char> marked(m.triangles.size());
    for (char& c : marked) c = rng() % 3 == 0;
    std::vector<std::pair<int, int>> touching;
    for (const auto& [i, j] : expected)
      if (marked[i] || marked[j]) touching.emplace_back(i, j);
    EXPECT_EQ(check_arrangement_touching(m, marked, 0).violating_pairs, touching) << trial;
  }
}

// Every shared mesh up to a size limit, both classifiers.
TEST(Arrangement, SharedMeshesPassCheckArrangement) {
  const fs::path dir = tritri_test::shared_meshes_dir();
  TRITRI_REQUIRE_DATA(dir);
  const std::size_t max_triangles = static_cast<std::size_t>(20000 * test_scale());
  const std::vector<fs::path> files = tritri_test::mesh_files(dir);
  // Below scale 1, every n-th file only (n about 1 / scale), so sanitizer runs stay short.
  const std::size_t every = test_scale() < 1 ? static_cast<std::size_t>(std::lround(1 / test_scale())) : 1;
  std::size_t eligible = 0;
  int arranged = 0, refused = 0, skipped = 0, skipped_check = 0;
  for (const fs::path& f : files) {
    TriangleSoup input;
    try {
      input = load_triangle_soup(f.string());
    } catch (const InputError&) {
      ++refused;  // bad files of the collection: test_load_triangle_soup's business
      continue;
    }
    if (input.triangles.size() > max_triangles || eligible++ % every != 0) {
      ++skipped;
      continue;
    }
    // Both classifiers; the (costly) check runs once when they give the same output.
    std::vector<ArrangeResult> results;
    for (Classifier c : kClassifiers) {
      results.push_back(run_arrange(input, c));  // valid input is never refused
    }
    for (std::size_t i = 0; i < results.size(); ++i) {
      const ArrangeResult& r = results[i];
      expect_stats_match_mesh(r, f.string());
      if (i > 0 && same_output(r.mesh, results[0].mesh)) continue;
      if (r.mesh.triangles.size() > max_triangles) {  // the check costs by output size
        ++skipped_check;
        continue;
      }
      const ArrangementCheck check = check_arrangement(r.mesh);
      EXPECT_TRUE(check.ok()) << f << " (" << r.stats.classifier << "): " << check.violations << " violations, "
                              << check.degenerate_triangles << " degenerate; "
                              << (check.examples.empty() ? "" : check.examples.front());
    }
    ++arranged;
  }
  EXPECT_GT(arranged, 0);
  std::printf("arranged %d shared meshes (%d outputs too large to check), refused %d, skipped (size or sampling) %d\n",
              arranged, skipped_check, refused, skipped);
}

}  // namespace
