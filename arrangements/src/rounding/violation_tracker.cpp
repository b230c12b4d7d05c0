// ViolationTracker (rounding/violation_tracker.h).
#include "rounding/violation_tracker.h"

#include <algorithm>
#include <cstring>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "arrangements/check_arrangement.h"

namespace arrangements {
namespace {

// A 64-bit mix of the corners' bits (splitmix64's finaliser per coordinate); -0 counts as 0,
// since the corners are compared with ==.
std::uint64_t hash_corners(const std::array<Vec3, 3>& c) {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (const Vec3& p : c)
    for (double x : p) {
      std::uint64_t bits;
      const double y = x == 0 ? 0.0 : x;
      std::memcpy(&bits, &y, sizeof bits);
      h ^= bits + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
      h ^= h >> 30;
      h *= 0xbf58476d1ce4e5b9ull;
      h ^= h >> 27;
      h *= 0x94d049bb133111ebull;
      h ^= h >> 31;
    }
  return h;
}

}  // namespace

std::vector<std::pair<int, int>> ViolationTracker::violations(const RoundedMesh& mesh) {
  const std::size_t nt = mesh.triangles.size();
  // In parallel, and matched by hashes: on meshes of a million triangles, binary searches
  // through the sorted corners were most of a round of rerouting.
  std::vector<Corners> current(nt);
  std::vector<Keyed> keys(nt);
  tbb::parallel_for(std::size_t{0}, nt, [&](std::size_t t) {
    Corners& c = current[t];
    for (int k = 0; k < 3; ++k) c[k] = mesh.vertices[mesh.triangles[t][k]];
    std::sort(c.begin(), c.end());
    keys[t] = {hash_corners(c), static_cast<int>(t)};
  });
  tbb::parallel_sort(keys.begin(), keys.end());
  // The triangle of `keys` (sorted) with corners c, or -1; `corners` by index.
  auto find = [](const std::vector<Keyed>& sorted, const std::vector<Corners>& corners, const Corners& c,
                 std::uint64_t h) {
    for (auto it = std::lower_bound(sorted.begin(), sorted.end(), Keyed{h, -1}); it != sorted.end() && it->hash == h;
         ++it)
      if (corners[it->index] == c) return it->index;
    return -1;
  };
  std::vector<std::pair<int, int>> violating;
  std::vector<char> changed;
  std::size_t changed_count = nt;
  if (!first_) {
    // A merge of the two sorted key lists; within a run of equal hashes, corners compared.
    changed.assign(nt, 1);
    std::size_t j = 0;
    for (std::size_t i = 0; i < nt;) {
      const std::uint64_t h = keys[i].hash;
      std::size_t i_end = i;
      while (i_end < nt && keys[i_end].hash == h) ++i_end;
      while (j < previous_keys_.size() && previous_keys_[j].hash < h) ++j;
      std::size_t j_end = j;
      while (j_end < previous_keys_.size() && previous_keys_[j_end].hash == h) ++j_end;
      for (std::size_t a = i; a < i_end; ++a)
        for (std::size_t b = j; b < j_end; ++b)
          if (current[keys[a].index] == previous_[previous_keys_[b].index]) {
            changed[keys[a].index] = 0;
            break;
          }
      i = i_end;
      j = j_end;
    }
    changed_count = static_cast<std::size_t>(std::count(changed.begin(), changed.end(), 1));
  }
  // Where most triangles changed, the full check (stage 2's parallel search) costs less
  // than the changed ones' box search against all.
  if (changed_count > nt / 4) {
    violating = check_arrangement(mesh, 0).violating_pairs;
    first_ = false;
  } else {
    violating = check_arrangement_touching(mesh, changed, 0).violating_pairs;
    if (!previous_violating_.empty()) {
      for (const auto& [x, y] : previous_violating_) {
        const int i = find(keys, current, x, hash_corners(x)), j = find(keys, current, y, hash_corners(y));
        if (i >= 0 && j >= 0) violating.emplace_back(std::min(i, j), std::max(i, j));
      }
      std::sort(violating.begin(), violating.end());
      violating.erase(std::unique(violating.begin(), violating.end()), violating.end());
    }
  }
  previous_violating_.clear();
  for (const auto& [i, j] : violating) previous_violating_.emplace_back(current[i], current[j]);
  previous_ = std::move(current);
  previous_keys_ = std::move(keys);
  return violating;
}

}  // namespace arrangements
