// ViolationTracker (rounding/violation_tracker.h).
#include "rounding/violation_tracker.h"

#include <algorithm>

#include "arrangements/check_arrangement.h"

namespace arrangements {

std::vector<std::pair<int, int>> ViolationTracker::violations(const RoundedMesh& mesh) {
  const std::size_t nt = mesh.triangles.size();
  auto corners_of = [&](std::size_t t) {
    Corners c;
    for (int k = 0; k < 3; ++k) c[k] = mesh.vertices[mesh.triangles[t][k]];
    std::sort(c.begin(), c.end());
    return c;
  };
  std::vector<Entry> current(nt);
  for (std::size_t t = 0; t < nt; ++t) current[t] = {corners_of(t), static_cast<int>(t)};
  auto by_corners = [](const Entry& a, const Entry& b) { return a.first < b.first; };
  std::vector<std::pair<int, int>> violating;
  std::vector<char> changed;
  std::size_t changed_count = nt;
  if (!first_) {
    if (!previous_sorted_) std::sort(previous_.begin(), previous_.end(), by_corners);
    changed.resize(nt);
    changed_count = 0;
    for (std::size_t t = 0; t < nt; ++t)
      changed_count += changed[t] =
          !std::binary_search(previous_.begin(), previous_.end(), current[t], by_corners);
  }
  bool current_sorted = false;
  // Where most triangles changed, the full check (stage 2's parallel search) costs less
  // than the changed ones' box search against all.
  if (changed_count > nt / 4) {
    violating = check_arrangement(mesh, 0).violating_pairs;
    first_ = false;
  } else {
    violating = check_arrangement_touching(mesh, changed, 0).violating_pairs;
    if (!previous_violating_.empty()) {
      std::sort(current.begin(), current.end(), by_corners);
      current_sorted = true;
      auto find = [&](const Corners& c) {
        const auto it = std::lower_bound(current.begin(), current.end(), Entry{c, 0}, by_corners);
        return it != current.end() && it->first == c ? it->second : -1;
      };
      for (const auto& [x, y] : previous_violating_) {
        const int i = find(x), j = find(y);
        if (i >= 0 && j >= 0) violating.emplace_back(std::min(i, j), std::max(i, j));
      }
      std::sort(violating.begin(), violating.end());
      violating.erase(std::unique(violating.begin(), violating.end()), violating.end());
    }
  }
  previous_violating_.clear();
  for (const auto& [i, j] : violating) previous_violating_.emplace_back(corners_of(i), corners_of(j));
  previous_ = std::move(current);
  previous_sorted_ = current_sorted;
  return violating;
}

}  // namespace arrangements
