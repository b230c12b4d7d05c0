// ViolationTracker (rounding/violation_tracker.h).
#include "rounding/violation_tracker.h"

#include <algorithm>
#include <cstring>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "arrangements/check_arrangement.h"

namespace arrangements {
namespace {

// A 64-bit mix of coordinates (splitmix64's finaliser per coordinate); -0 counts as 0,
// since positions are compared with ==.
std::uint64_t mix(std::uint64_t h, double x) {
  std::uint64_t bits;
  const double y = x == 0 ? 0.0 : x;
  std::memcpy(&bits, &y, sizeof bits);
  h ^= bits + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ull;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebull;
  h ^= h >> 31;
  return h;
}
std::uint64_t hash_position(const Vec3& p) { return mix(mix(mix(0x9e3779b97f4a7c15ull, p[0]), p[1]), p[2]); }
std::uint64_t hash_corners(const std::array<Vec3, 3>& c) {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (const Vec3& p : c)
    for (double x : p) h = mix(h, x);
  return h;
}

// Whether two of the mesh's corners are distinct vertices at one position: then whether a
// pair violates depends on vertex identities, not on positions alone.
bool repeats_a_position(const RoundedMesh& mesh) {
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const Tri& f : mesh.triangles)
    for (int v : f) used[v] = 1;
  std::vector<std::pair<std::uint64_t, int>> keys;
  for (std::size_t v = 0; v < used.size(); ++v)
    if (used[v]) keys.emplace_back(hash_position(mesh.vertices[v]), static_cast<int>(v));
  tbb::parallel_sort(keys.begin(), keys.end());
  for (std::size_t i = 0; i < keys.size(); ++i)
    for (std::size_t j = i + 1; j < keys.size() && keys[j].first == keys[i].first; ++j)
      if (mesh.vertices[keys[i].second] == mesh.vertices[keys[j].second]) return true;
  return false;
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
  // Two vertices at one position, or one triangle twice: checked in full, and so is the
  // next mesh (this one's verdicts depended on vertex identities).
  bool ambiguous = repeats_a_position(mesh);
  for (std::size_t i = 0; i + 1 < nt && !ambiguous; ++i)
    for (std::size_t j = i + 1; j < nt && keys[j].hash == keys[i].hash && !ambiguous; ++j)
      ambiguous = current[keys[i].index] == current[keys[j].index];
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
  if (full_check_costs_less(changed_count, nt) || ambiguous || previous_ambiguous_) {
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
  previous_ambiguous_ = ambiguous;
  return violating;
}

}  // namespace arrangements
