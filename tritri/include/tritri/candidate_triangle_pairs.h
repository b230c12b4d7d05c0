// tritri/candidate_triangle_pairs.h
//
// candidate_triangle_pairs(Vlo, Vhi, F, threads = 0, group = {}): the pairs of triangles
// that may meet, the candidates of the batch API (self_intersections, intersections): the
// pairs of overlapping_triangle_pairs (tritri/box_pairs.h: closed boxes overlap, never two
// triangles of one group) minus those that share no corner and whose slabs along 10
// diagonal directions are apart (tritri/direction_slabs.h: such triangles do not meet).
//   Vlo, Vhi  each vertex's box (the same span for double coordinates)
//   F, threads, group  as for overlapping_triangle_pairs
// returns the pairs (i, j), i < j, sorted, each once; the result does not depend on
// `threads`. Long thin triangles lying across their boxes' diagonals make most box pairs
// (EMBER 79741+65004: 16.7 M box pairs, 0.45 M candidates), and the list is never built
// whole.
// Exactness: the slabs are certified outer bounds (direction_slabs.h), so no pair that
// meets is dropped. Cost: the box search plus O(1) per box pair; memory: 96 bytes per
// triangle plus the candidates.
#pragma once

#include <tbb/enumerable_thread_specific.h>
#include <tbb/task_arena.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "tritri/box_pairs.h"
#include "tritri/direction_slabs.h"

namespace tritri {

inline std::vector<std::pair<int, int>> candidate_triangle_pairs(std::span<const std::array<double, 3>> Vlo,
                                                                 std::span<const std::array<double, 3>> Vhi,
                                                                 std::span<const std::array<int, 3>> F,
                                                                 int threads = 0,
                                                                 std::span<const std::int64_t> group = {}) {
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  std::vector<DirectionSlabs> slabs;
  arena.execute([&] { slabs = triangle_slabs(Vlo, Vhi, F); });
  tbb::enumerable_thread_specific<detail::box_pairs::Pairs, tbb::cache_aligned_allocator<detail::box_pairs::Pairs>,
                                  tbb::ets_key_per_instance>
      found;  // visit runs on several threads
  for_each_overlapping_pair(Vlo, Vhi, F, threads, group, [&](int i, int j) {
    if (!apart_by_slabs(F[i], F[j], slabs[i], slabs[j])) found.local().emplace_back(i, j);
  });
  std::vector<std::pair<int, int>> all;
  arena.execute([&] { all = detail::box_pairs::sorted_unique(found); });
  return all;
}

}  // namespace tritri
