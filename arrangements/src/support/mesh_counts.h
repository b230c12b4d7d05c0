// arrangements/src/support/mesh_counts.h
//
// mesh_counts(F): simplex counts of a triangle mesh, as the arrangement statistics report
// them: vertices referenced by a triangle, unique undirected edges, triangles, and the
// Euler characteristic V - E + F of that complex. Cost: O(#F + #V) plus sorting each
// vertex's neighbours (a handful each); the per-vertex part in parallel (oneTBB).
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
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

// Edges are bucketed by their smaller end (counting sort), then each bucket, a vertex's
// few neighbours, is sorted and counted in parallel: linear, no global sort.
inline MeshCounts mesh_counts(const std::vector<Tri>& F) {
  MeshCounts c;
  c.triangles = F.size();
  int top = -1;
  for (const Tri& t : F) top = std::max({top, t[0], t[1], t[2]});
  const std::size_t n = static_cast<std::size_t>(top + 1);
  std::vector<std::size_t> first(n + 1, 0);  // bucket offsets, by smaller end
  std::vector<char> used(n, 0);
  for (const Tri& t : F)
    for (int k = 0; k < 3; ++k) {
      used[t[k]] = 1;
      ++first[std::min(t[k], t[(k + 1) % 3]) + 1];
    }
  for (std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
  std::vector<int> other(first[n]);
  std::vector<std::size_t> fill(first.begin(), first.end() - 1);
  for (const Tri& t : F)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      other[fill[std::min(a, b)]++] = std::max(a, b);
    }
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
