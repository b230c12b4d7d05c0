// tests/support/brute_force_box_pairs.h
//
// brute_force_box_pairs(V, F): every pair (i, j), i < j, of triangles whose closed
// axis-aligned boxes overlap (touching counts), by the definition: all pairs, exact
// comparisons of the corners' minima and maxima. The reference of the box-search tests
// (test_candidate_pairs, test_box_grid). Cost: O(#F^2).
#pragma once

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace tritri_test {

inline std::vector<std::pair<int, int>> brute_force_box_pairs(const std::vector<std::array<double, 3>>& V,
                                                              const std::vector<std::array<int, 3>>& F) {
  std::vector<std::array<double, 6>> box(F.size());
  for (std::size_t t = 0; t < F.size(); ++t)
    for (int a = 0; a < 3; ++a) {
      box[t][a] = std::min({V[F[t][0]][a], V[F[t][1]][a], V[F[t][2]][a]});
      box[t][a + 3] = std::max({V[F[t][0]][a], V[F[t][1]][a], V[F[t][2]][a]});
    }
  std::vector<std::pair<int, int>> out;
  for (std::size_t i = 0; i < F.size(); ++i)
    for (std::size_t j = i + 1; j < F.size(); ++j) {
      bool overlap = true;
      for (int a = 0; a < 3; ++a) overlap = overlap && box[i][a] <= box[j][a + 3] && box[j][a] <= box[i][a + 3];
      if (overlap) out.emplace_back(static_cast<int>(i), static_cast<int>(j));
    }
  return out;
}

}  // namespace tritri_test
