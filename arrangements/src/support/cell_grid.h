// CellGrid: points bucketed in cubic cells, to find the points near a point without
// comparing all pairs. Shared by the snapping of round_mesh.cpp (new points to a double
// vertex nearby) and merge_close_input_vertices (rounding/round_merged_input.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "arrangements/triangle_soup.h"

namespace arrangements::detail {

class CellGrid {
 public:
  // cell > 0. Cell indices are floor(coordinate / cell), exact as integers while
  // |coordinate| / cell < 2^53 (callers' cells are at least an ulp of the largest magnitude).
  explicit CellGrid(double cell) : cell_(cell) {}

  void add(const Vec3& p, int id) { cells_.emplace_back(key_of(p), id); }

  // After the last add and before the first query. O(n log n).
  void finish() { std::sort(cells_.begin(), cells_.end()); }

  // Calls f(id) for every point added in the 27 cells around p's cell: a superset of the
  // points within `cell` of p (the caller decides exactly which are near). O(log n) per
  // cell plus the points found.
  template <class F>
  void for_each_near(const Vec3& p, F&& f) const {
    const Key k = key_of(p);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const Key c{k[0] + dx, k[1] + dy, k[2] + dz};
          for (auto it = std::lower_bound(cells_.begin(), cells_.end(), std::pair<Key, int>{c, -1});
               it != cells_.end() && it->first == c; ++it)
            f(it->second);
        }
  }

 private:
  using Key = std::array<long long, 3>;
  Key key_of(const Vec3& p) const {
    return {static_cast<long long>(std::floor(p[0] / cell_)), static_cast<long long>(std::floor(p[1] / cell_)),
            static_cast<long long>(std::floor(p[2] / cell_))};
  }
  double cell_;
  std::vector<std::pair<Key, int>> cells_;
};

}  // namespace arrangements::detail
