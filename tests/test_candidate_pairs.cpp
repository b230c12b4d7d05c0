// Specification of candidate_pairs (arrangements/src/stages/2_candidate_pairs.h):
// - exactly the pairs i < j whose closed bounding boxes overlap, touching boxes included,
//   boxes one ulp apart excluded; pairs that share vertices included;
// - sorted and unique, and the same for every thread count;
// - equal to a brute-force all-pairs box test on generated soups (grid soups with many
//   touching boxes, random soups) and on a real mesh of the shared collection.
#include <gtest/gtest.h>

#include <arrangements/arrange.h>
#include "stages/2_candidate_pairs.h"
#include <arrangements/thread_count.h>
#include <arrangements/load_triangle_soup.h>
#include "support/mesh_generators.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include "support/brute_force_box_pairs.h"
#include "support/shared_meshes.h"

namespace {

using arrangements::arrange;
using arrangements::ArrangeOptions;
using arrangements::candidate_pairs;
using arrangements::kMaxThreads;
using arrangements::Tri;
using arrangements::TriangleSoup;
using arrangements::Vec3;
using Pairs = std::vector<std::pair<int, int>>;

// All pairs i < j whose closed boxes overlap, by the definition.
Pairs brute_force_pairs(const std::vector<Vec3>& V, const std::vector<Tri>& F) {
  return tritri_test::brute_force_box_pairs(V, F);
}

TEST(CandidatePairs, TouchingBoxesCountAndBoxesOneUlpApartDoNot) {
  const double gap = std::nextafter(1.0, 2.0);
  const std::vector<Vec3> V = {
      {0, 0, 0},   {1, 0, 0},   {0, 1, 1},    // 0: box x in [0, 1]
      {1, 0, 0.5}, {2, 1, 0.5}, {2, 0, 0.5},  // 1: x in [1, 2], shares only the plane x = 1
      {gap, 0, 0}, {2, 0, 1},   {2, 1, 0},    // 2: x in [1 + ulp, 2]: misses 0
      {5, 5, 5},   {6, 5, 5},   {5, 6, 5},    // 3: far away
  };
  const std::vector<Tri> F = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}};
  EXPECT_EQ(candidate_pairs(V, F), (Pairs{{0, 1}, {1, 2}}));
}

TEST(CandidatePairs, IncludesPairsThatShareVerticesAndIdenticalTriangles) {
  const std::vector<Vec3> V = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {3, 3, 3}, {4, 3, 3}, {3, 4, 3}};
  const std::vector<Tri> F = {{0, 1, 2}, {1, 3, 2}, {2, 1, 0}, {4, 5, 6}};
  EXPECT_EQ(candidate_pairs(V, F), (Pairs{{0, 1}, {0, 2}, {1, 2}}));
}

TEST(CandidatePairs, FewerThanTwoTrianglesGiveNoPairs) {
  const std::vector<Vec3> V = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_TRUE(candidate_pairs(V, {}).empty());
  EXPECT_TRUE(candidate_pairs(V, {{0, 1, 2}}).empty());
}

// oneTBB crashes on huge arenas: the library refuses what the tools refuse (thread_count.h).
TEST(CandidatePairs, RefusesThreadCountsAboveTheCapInTheLibraryToo) {
  const std::vector<Vec3> V = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<Tri> F = {{0, 1, 2}, {0, 2, 1}};
  EXPECT_EQ(candidate_pairs(V, F, kMaxThreads).size(), 1u);
  EXPECT_THROW(candidate_pairs(V, F, kMaxThreads + 1), std::invalid_argument);
  EXPECT_THROW(candidate_pairs(V, F, 100000), std::invalid_argument);
  TriangleSoup soup;
  soup.vertices = V;
  soup.triangles = F;
  soup.label_set = {0, 0};
  soup.label_sets = {{0}};
  soup.source = {0, 1};
  ArrangeOptions options;
  options.threads = 100000;
  EXPECT_THROW(arrange(soup, options), std::invalid_argument);
  options.threads = 2;
  EXPECT_EQ(arrange(soup, options).mesh.triangles.size(), 1u);  // the duplicate is merged
}

// Triangles with integer corners base + [0, spread) with base in [0, range): boxes touch
// and coincide a lot.
void grid_soup(std::mt19937& rng, int n, int range, int spread, std::vector<Vec3>& V, std::vector<Tri>& F) {
  V.clear();
  F.clear();
  for (int t = 0; t < n; ++t) {
    const double base[3] = {double(rng() % range), double(rng() % range), double(rng() % range)};
    Tri tri;
    for (int i = 0; i < 3; ++i) {
      tri[i] = static_cast<int>(V.size());
      V.push_back({base[0] + rng() % spread, base[1] + rng() % spread, base[2] + rng() % spread});
    }
    F.push_back(tri);
  }
  // Some triangles share an edge with an existing one (shared vertices).
  for (int t = 0; t < n / 4; ++t) {
    const Tri k = F[rng() % F.size()];
    const Vec3& c = V[k[0]];
    V.push_back({c[0] + rng() % spread, c[1] + rng() % spread, c[2] - 1.0 * (rng() % spread)});
    F.push_back({k[1], k[0], static_cast<int>(V.size()) - 1});
  }
}

// Small random triangles of varied size in a unit cube.
void random_soup(std::mt19937& rng, int n, std::vector<Vec3>& V, std::vector<Tri>& F) {
  std::uniform_real_distribution<double> unit(0, 1), size(0.001, 0.2);
  V.clear();
  F.clear();
  for (int t = 0; t < n; ++t) {
    const Vec3 c = {unit(rng), unit(rng), unit(rng)};
    const double s = size(rng);
    Tri tri;
    for (int i = 0; i < 3; ++i) {
      tri[i] = static_cast<int>(V.size());
      V.push_back({c[0] + s * unit(rng), c[1] + s * unit(rng), c[2] + s * unit(rng)});
    }
    F.push_back(tri);
  }
}

// Random triangles plus "needles" that span the whole x range: their boxes reach into
// every part of an x-sorted split.
void needle_soup(std::mt19937& rng, int n, std::vector<Vec3>& V, std::vector<Tri>& F) {
  random_soup(rng, n, V, F);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int t = 0; t < n / 20; ++t) {
    const double y = unit(rng), z = unit(rng);
    const int first = static_cast<int>(V.size());
    V.push_back({-0.1, y, z});
    V.push_back({1.2, y + 0.01, z});
    V.push_back({0.5 * unit(rng), y, z + 0.01});
    F.push_back({first, first + 1, first + 2});
  }
}

// Large enough soups take the parallel path (more than two chunks of 2048 triangles).
TEST(CandidatePairs, EqualsBruteForceOnGeneratedSoupsForEveryThreadCount) {
  std::mt19937 rng(31337);
  std::vector<Vec3> V;
  std::vector<Tri> F;
  for (int trial = 0; trial < 24; ++trial) {
    const int n = trial < 18 ? 50 + trial * 60 : 9000;
    switch (trial % 3) {
      case 0:
        n < 9000 ? grid_soup(rng, n, 1, 2 + trial % 5, V, F) : grid_soup(rng, n, 30, 3, V, F);
        break;
      case 1:
        random_soup(rng, n, V, F);
        break;
      case 2:
        needle_soup(rng, n, V, F);
        break;
    }
    const Pairs expected = brute_force_pairs(V, F);
    for (int threads : {1, 2, 3, 0}) ASSERT_EQ(candidate_pairs(V, F, threads), expected) << trial << " " << threads;
  }
}

// Polygon faces (TriangleSoup::polygon): the same pairs minus those inside one face, for
// faces of every size (singletons, small, most of the soup) and any thread count.
TEST(CandidatePairs, WithPolygonFacesEqualsBruteForceMinusPairsInsideOneFace) {
  std::mt19937 rng(4242);
  std::vector<Vec3> V;
  std::vector<Tri> F;
  for (int trial = 0; trial < 12; ++trial) {
    const int n = 100 + trial * 150;
    trial % 2 ? grid_soup(rng, n, 1, 2 + trial % 4, V, F) : needle_soup(rng, n, V, F);
    std::vector<std::int64_t> polygon(F.size(), -1);
    const int max_face = trial < 4 ? 3 : trial < 8 ? 40 : n;
    std::uniform_int_distribution<int> size(1, max_face), coin(0, 2);
    for (std::size_t t = 0; t < F.size();) {  // runs of consecutive triangles, some left single
      const std::size_t end = std::min(F.size(), t + size(rng));
      if (coin(rng)) std::fill(polygon.begin() + t, polygon.begin() + end, static_cast<std::int64_t>(t));
      t = end;
    }
    Pairs expected;
    for (const auto& [i, j] : brute_force_pairs(V, F))
      if (polygon[i] < 0 || polygon[i] != polygon[j]) expected.emplace_back(i, j);
    for (int threads : {1, 2, 0})
      ASSERT_EQ(candidate_pairs(V, F, threads, polygon), expected) << trial << " " << threads;
  }
}

TEST(CandidatePairs, EqualsBruteForceOnRealMeshes) {
  // box.STL: axis-aligned faces whose flat boxes only touch, on the parallel path.
  for (const char* name : {"cherchi_arrangements/two_spheres.stl", "libigl_tutorial/bunny.off", "trimesh/box.STL"}) {
    const std::filesystem::path file = tritri_test::shared_meshes_dir() / name;
    TRITRI_REQUIRE_DATA(file);
    const arrangements::TriangleSoup s = arrangements::load_triangle_soup(file.string());
    const Pairs expected = brute_force_pairs(s.vertices, s.triangles);
    ASSERT_GT(expected.size(), s.triangles.size()) << name;  // neighbours share vertices: many pairs
    // Repeated calls: CGAL numbers boxes from a global counter, and a bug that depended on
    // those numbers only showed on later calls.
    for (int threads : {1, 2, 0, 1, 2}) EXPECT_EQ(candidate_pairs(s.vertices, s.triangles, threads), expected) << name;
  }
}

// Regression: closed boxes that only touch across the parallel split (flat boxes of
// axis-aligned faces at the split coordinate) were lost by CGAL's bipartite search.
TEST(CandidatePairs, TouchingAxisAlignedCubesOnTheParallelPath) {
  std::vector<Vec3> V;
  std::vector<Tri> F;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      for (int k = 0; k < 10; ++k) {
        const auto cube = arrangements::box({double(i), double(j), double(k)}, {i + 1.0, j + 1.0, k + 1.0});
        const int base = static_cast<int>(V.size());
        V.insert(V.end(), cube.vertices.begin(), cube.vertices.end());
        for (const Tri& t : cube.triangles) F.push_back({base + t[0], base + t[1], base + t[2]});
      }
  const Pairs expected = brute_force_pairs(V, F);
  for (int threads : {1, 2, 3}) EXPECT_EQ(candidate_pairs(V, F, threads), expected) << threads;
}

}  // namespace
