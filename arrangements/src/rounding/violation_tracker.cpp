// ViolationTracker (rounding/violation_tracker.h).
#include "rounding/violation_tracker.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <unordered_map>

#include "arrangements/check_arrangement.h"

namespace arrangements {

std::size_t ViolationTracker::CornersHash::operator()(const Corners& c) const {
  std::uint64_t h = 0;
  for (const Vec3& p : c)
    for (double x : p) h = (h ^ std::bit_cast<std::uint64_t>(x)) * 0x9E3779B97F4A7C15ull;
  return static_cast<std::size_t>(h ^ (h >> 29));
}

std::size_t ViolationTracker::PairHash::operator()(const std::pair<Corners, Corners>& p) const {
  const CornersHash h;
  return h(p.first) * 31 + h(p.second);
}

std::vector<std::pair<int, int>> ViolationTracker::violations(const RoundedMesh& mesh) {
  const std::size_t nt = mesh.triangles.size();
  std::vector<Corners> corners(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    for (int k = 0; k < 3; ++k) corners[t][k] = mesh.vertices[mesh.triangles[t][k]];
    std::sort(corners[t].begin(), corners[t].end());
  }
  std::vector<std::pair<int, int>> violating;
  std::vector<char> changed;
  std::size_t changed_count = nt;
  if (!first_) {
    changed.resize(nt);
    changed_count = 0;
    for (std::size_t t = 0; t < nt; ++t) changed_count += changed[t] = !previous_.contains(corners[t]);
  }
  // Where most triangles changed, the full check (stage 2's parallel search) costs less
  // than the changed ones' box search against all.
  if (changed_count > nt / 4) {
    violating = check_arrangement(mesh, 0).violating_pairs;
    first_ = false;
  } else {
    std::unordered_map<Corners, int, CornersHash> index;
    for (std::size_t t = 0; t < nt; ++t) index.emplace(corners[t], static_cast<int>(t));
    violating = check_arrangement_touching(mesh, changed, 0).violating_pairs;
    for (const auto& [x, y] : previous_violating_) {
      const auto i = index.find(x), j = index.find(y);
      if (i != index.end() && j != index.end())
        violating.emplace_back(std::min(i->second, j->second), std::max(i->second, j->second));
    }
    std::sort(violating.begin(), violating.end());
    violating.erase(std::unique(violating.begin(), violating.end()), violating.end());
  }
  previous_ = std::unordered_set<Corners, CornersHash>(corners.begin(), corners.end());
  previous_violating_.clear();
  for (const auto& [i, j] : violating) previous_violating_.emplace(corners[i], corners[j]);
  return violating;
}

}  // namespace arrangements
