// arrangements/src/support/mesh_counts.h
//
// mesh_counts(F): simplex counts of a triangle mesh, as the arrangement statistics report
// them: vertices referenced by a triangle, unique undirected edges, triangles, and the
// Euler characteristic V - E + F of that complex. Cost: O(#F + #V) plus sorting each
// vertex's neighbours (a handful each); the passes over triangles and buckets in parallel
// (oneTBB, the caller's arena), the same counts for any thread count.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "arrangements/triangle_soup.h"

namespace arrangements {

struct MeshCounts {
  std::size_t vertices = 0, edges = 0, triangles = 0;
  long long euler = 0;
  friend bool operator==(const MeshCounts&, const MeshCounts&) = default;
};

// Edges are bucketed by their smaller end (a counting sort), then each bucket, a vertex's
// few neighbours, is sorted and counted: linear, no global sort. The counting sort runs
// over blocks of triangles, each block with its own counts (shared atomic counters
// measured no faster than one thread), at most kMaxBlocks of them (extra memory: that
// many counts per vertex); only the offsets' prefix pass over the vertices is serial.
inline MeshCounts mesh_counts(const std::vector<Tri>& F) {
  constexpr std::size_t kMaxBlocks = 8, kMinBlockTriangles = std::size_t{1} << 15;
  MeshCounts c;
  c.triangles = F.size();
  const int top = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, F.size()), -1,
      [&](const tbb::blocked_range<std::size_t>& r, int m) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) m = std::max({m, F[i][0], F[i][1], F[i][2]});
        return m;
      },
      [](int a, int b) { return std::max(a, b); });
  const std::size_t n = static_cast<std::size_t>(top + 1);
  const std::size_t workers = static_cast<std::size_t>(tbb::this_task_arena::max_concurrency());
  const std::size_t blocks = std::max<std::size_t>(1, std::min({workers, kMaxBlocks, F.size() / kMinBlockTriangles}));
  auto block_begin = [&](std::size_t b) { return b * F.size() / blocks; };
  // at[b][v]: block b's count of edges with smaller end v; then the position of its next
  // such edge within v's bucket.
  std::vector<std::vector<std::uint32_t>> at(blocks);
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    at[b].assign(n, 0);
    for (std::size_t i = block_begin(b); i < block_begin(b + 1); ++i)
      for (int k = 0; k < 3; ++k) ++at[b][static_cast<std::size_t>(std::min(F[i][k], F[i][(k + 1) % 3]))];
  });
  std::vector<std::size_t> first(n + 1, 0);  // bucket offsets
  for (std::size_t v = 0; v < n; ++v) {
    std::uint32_t in_bucket = 0;
    for (std::size_t b = 0; b < blocks; ++b) in_bucket += std::exchange(at[b][v], in_bucket);
    first[v + 1] = first[v] + in_bucket;
  }
  std::vector<int> other(first[n]);  // larger ends, bucketed by smaller end
  std::vector<char> used(n, 0);
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    for (std::size_t i = block_begin(b); i < block_begin(b + 1); ++i)
      for (int k = 0; k < 3; ++k) {
        const int a = F[i][k], e = F[i][(k + 1) % 3];
        const auto v = static_cast<std::size_t>(std::min(a, e));
        other[first[v] + at[b][v]++] = std::max(a, e);
        std::atomic_ref<char>(used[static_cast<std::size_t>(a)]).store(1, std::memory_order_relaxed);
      }
  });
  at = {};
  c.vertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
  c.edges = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n), std::size_t{0},
      [&](const tbb::blocked_range<std::size_t>& r, std::size_t edges) {
        for (std::size_t v = r.begin(); v < r.end(); ++v) {
          const auto begin = other.begin() + static_cast<std::ptrdiff_t>(first[v]);
          const auto end = other.begin() + static_cast<std::ptrdiff_t>(first[v + 1]);
          std::sort(begin, end);
          edges += static_cast<std::size_t>(std::unique(begin, end) - begin);
        }
        return edges;
      },
      std::plus<>());
  c.euler = static_cast<long long>(c.vertices) - static_cast<long long>(c.edges) + static_cast<long long>(c.triangles);
  return c;
}

}  // namespace arrangements
