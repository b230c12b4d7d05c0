// mesh_counts (arrangements/src/support/mesh_counts.h): the counts the statistics report
// (vertices used by a triangle, unique undirected edges, triangles, Euler characteristic),
// computed by a parallel counting sort over blocks of triangles. Checked here against an
// oracle written apart from it (std::set of vertex ids and of ordered edge pairs) on
// meshes chosen to stress the blocking: many blocks (hundreds of thousands of triangles),
// edges repeated across blocks (non-manifold fans, duplicated triangles, both
// orientations), unused vertex ids below the largest one, and tiny inputs (no triangle,
// one triangle, fewer triangles than a block); at 1, 2, 3 and 8 worker threads, which
// must all give the oracle's counts.
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "support/mesh_counts.h"

namespace {

using arrangements::MeshCounts;
using arrangements::mesh_counts;
using arrangements::Tri;

MeshCounts oracle(const std::vector<Tri>& F) {
  std::set<int> vertices;
  std::set<std::pair<int, int>> edges;
  for (const Tri& t : F)
    for (int k = 0; k < 3; ++k) {
      vertices.insert(t[k]);
      edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
    }
  MeshCounts c;
  c.vertices = vertices.size();
  c.edges = edges.size();
  c.triangles = F.size();
  c.euler = static_cast<long long>(c.vertices) - static_cast<long long>(c.edges) + static_cast<long long>(F.size());
  return c;
}

// Counts at several thread counts, in an arena of each size (mesh_counts sizes its blocks
// from the arena it runs in).
void expect_oracle_counts(const std::vector<Tri>& F, const char* what) {
  const MeshCounts expected = oracle(F);
  for (const int threads : {1, 2, 3, 8}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    tbb::task_arena arena(threads);
    MeshCounts got;
    arena.execute([&] { got = mesh_counts(F); });
    EXPECT_EQ(got, expected) << what << " at " << threads << " threads: vertices " << got.vertices << " / "
                             << expected.vertices << ", edges " << got.edges << " / " << expected.edges;
  }
}

// A strip of quads over a w x h grid of vertex ids (two triangles per cell), every
// vertex id multiplied by `stride` (ids between them unused).
std::vector<Tri> grid(int w, int h, int stride) {
  std::vector<Tri> F;
  auto id = [&](int x, int y) { return (y * (w + 1) + x) * stride; };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      F.push_back({id(x, y), id(x + 1, y), id(x + 1, y + 1)});
      F.push_back({id(x, y), id(x + 1, y + 1), id(x, y + 1)});
    }
  return F;
}

TEST(MeshCounts, TinyInputs) {
  expect_oracle_counts({}, "no triangle");
  expect_oracle_counts({{0, 1, 2}}, "one triangle");
  expect_oracle_counts({{5, 9, 7}}, "one triangle, unused ids below it");
  expect_oracle_counts({{0, 1, 2}, {2, 1, 0}, {0, 1, 2}}, "one triangle thrice, both orientations");
  expect_oracle_counts(grid(3, 2, 1), "a small grid");
}

TEST(MeshCounts, GridsOfManyBlocks) {
  // 2 * 400 * 300 = 240,000 triangles: several blocks of 2^15 at every thread count.
  const std::vector<Tri> F = grid(400, 300, 1);
  const MeshCounts c = oracle(F);
  // The closed form of a triangulated grid, as a check of the oracle itself.
  EXPECT_EQ(c.vertices, 401u * 301u);
  EXPECT_EQ(c.edges, 400u * 301u + 401u * 300u + 400u * 300u);
  EXPECT_EQ(c.euler, 1);
  expect_oracle_counts(F, "grid 400 x 300");
  expect_oracle_counts(grid(400, 300, 3), "grid 400 x 300, ids spaced by 3");
}

TEST(MeshCounts, EdgesRepeatedAcrossBlocks) {
  // The grid, then the same triangles again reversed and shuffled: every edge is met in
  // blocks far apart; plus non-manifold fans around a few hub vertices (one edge in
  // thousands of triangles, spread over all blocks).
  std::vector<Tri> F = grid(300, 200, 1);
  std::vector<Tri> again = F;
  for (Tri& t : again) std::swap(t[1], t[2]);
  std::mt19937 rng(7);
  std::shuffle(again.begin(), again.end(), rng);
  F.insert(F.end(), again.begin(), again.end());
  const int base = 301 * 201;
  std::uniform_int_distribution<int> pick(0, base - 1);
  for (int i = 0; i < 60000; ++i) {
    const int hub = i % 5;
    F.push_back({hub, base + hub, pick(rng)});
  }
  std::shuffle(F.begin(), F.end(), rng);
  expect_oracle_counts(F, "grid twice, shuffled, with fans");
}

TEST(MeshCounts, RandomTriangles) {
  // Random triangles over few vertices (heavy repetition) and over many (little).
  std::mt19937 rng(11);
  for (const int vertices : {50, 5000, 500000}) {
    std::uniform_int_distribution<int> pick(0, vertices - 1);
    std::vector<Tri> F;
    while (F.size() < 150000) {
      const Tri t{pick(rng), pick(rng), pick(rng)};
      if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) F.push_back(t);
    }
    expect_oracle_counts(F, vertices == 50 ? "random over 50" : vertices == 5000 ? "random over 5000" : "random over 500000");
  }
}

}  // namespace
