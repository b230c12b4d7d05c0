// arrangements/src/support/mesh_counts.h
//
// mesh_counts(F): simplex counts of a triangle mesh, as the arrangement statistics report
// them: vertices referenced by a triangle, unique undirected edges, triangles, and the
// Euler characteristic V - E + F of that complex. Cost: O(#F log #F).
#pragma once

#include <algorithm>
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

inline MeshCounts mesh_counts(const std::vector<Tri>& F) {
  std::vector<int> v;
  std::vector<std::pair<int, int>> e;
  v.reserve(F.size() * 3);
  e.reserve(F.size() * 3);
  for (const Tri& t : F)
    for (int k = 0; k < 3; ++k) {
      v.push_back(t[k]);
      e.emplace_back(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
    }
  std::sort(v.begin(), v.end());
  std::sort(e.begin(), e.end());
  MeshCounts c;
  c.vertices = static_cast<std::size_t>(std::unique(v.begin(), v.end()) - v.begin());
  c.edges = static_cast<std::size_t>(std::unique(e.begin(), e.end()) - e.begin());
  c.triangles = F.size();
  c.euler = static_cast<long long>(c.vertices) - static_cast<long long>(c.edges) + static_cast<long long>(c.triangles);
  return c;
}

}  // namespace arrangements
