// arrangements/src/booleans/unbalanced_edges.h (internal)
//
// unbalanced_edges(mesh): the number of edges of a rounded mesh (RoundedMesh: double
// coordinates) used more often in one direction than in the other, vertices compared by
// exact position (two vertices rounded onto one double point are one). 0 for a closed,
// consistently oriented surface, the promise of a Boolean's output; `arrange --boolean
// --round safe` checks it on what it writes (rounding can open a solid where it reroutes
// triangles through vertices it moved onto edges).
// Exact (double equality); O(T log T).
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "arrangements/output_mesh.h"

namespace arrangements {

inline std::size_t unbalanced_edges(const RoundedMesh& mesh) {
  // positions -> ids
  std::vector<int> order(mesh.vertices.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return mesh.vertices[a] < mesh.vertices[b]; });
  std::vector<int> id(mesh.vertices.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    id[order[k]] = k > 0 && mesh.vertices[order[k]] == mesh.vertices[order[k - 1]] ? id[order[k - 1]]
                                                                                   : static_cast<int>(k);
  std::vector<std::pair<std::pair<int, int>, int>> uses;  // (undirected edge, +1 / -1)
  uses.reserve(3 * mesh.triangles.size());
  for (const Tri& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = id[t[k]], b = id[t[(k + 1) % 3]];
      if (a != b) uses.push_back({{std::min(a, b), std::max(a, b)}, a < b ? 1 : -1});
    }
  std::sort(uses.begin(), uses.end());
  std::size_t unbalanced = 0;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    int sum = 0;
    for (; j < uses.size() && uses[j].first == uses[i].first; ++j) sum += uses[j].second;
    unbalanced += sum != 0;
    i = j;
  }
  return unbalanced;
}

}  // namespace arrangements
