// tritri/candidate_triangle_pairs.h
//
// candidate_triangle_pairs(Vlo, Vhi, F, threads = 0, group = {}, embedded = {}): the pairs
// of triangles that may meet beyond what they share, the candidates of the batch API
// (self_intersections, intersections): the pairs of overlapping_triangle_pairs
// (tritri/box_pairs.h: closed boxes overlap, never two triangles of one group) minus those
// that share a vertex v with embedded[v] (tritri/embedded_stars.h: they meet only in what
// they share) and those that share no corner and whose slabs along 10 diagonal directions
// are apart (tritri/direction_slabs.h: such triangles do not meet).
//   Vlo, Vhi  each vertex's box (the same span for double coordinates)
//   F, threads, group  as for overlapping_triangle_pairs
//   embedded  #V or empty: tritri::embedded_stars(V, F) for double coordinates
// returns the pairs (i, j), i < j, sorted, each once; the result does not depend on
// `threads`. Long thin triangles lying across their boxes' diagonals make most box pairs
// (EMBER 79741+65004: 16.7 M box pairs, 0.45 M candidates), and the list is never built
// whole.
// Exactness: the slabs are certified outer bounds (direction_slabs.h) and the stars exact
// certificates, so no pair that meets beyond what it shares is dropped. Cost: the box
// search plus O(1) per box pair; memory: 96 bytes per triangle plus the candidates.
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
#include "tritri/embedded_stars.h"

namespace tritri {

inline std::vector<std::pair<int, int>> candidate_triangle_pairs(std::span<const std::array<double, 3>> Vlo,
                                                                 std::span<const std::array<double, 3>> Vhi,
                                                                 std::span<const std::array<int, 3>> F,
                                                                 int threads = 0,
                                                                 std::span<const std::int64_t> group = {},
                                                                 std::span<const std::uint8_t> embedded = {}) {
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  std::vector<DirectionSlabs> slabs;
  arena.execute([&] { slabs = triangle_slabs(Vlo, Vhi, F); });
  tbb::enumerable_thread_specific<detail::box_pairs::Pairs, tbb::cache_aligned_allocator<detail::box_pairs::Pairs>,
                                  tbb::ets_key_per_instance>
      found;  // visit runs on several threads
  for_each_overlapping_pair(Vlo, Vhi, F, threads, group, [&](int i, int j) {
    if (!embedded.empty() && share_embedded_star(F[i], F[j], embedded)) return;
    if (!apart_by_slabs(F[i], F[j], slabs[i], slabs[j])) found.local().emplace_back(i, j);
  });
  std::vector<std::pair<int, int>> all;
  arena.execute([&] { all = detail::box_pairs::sorted_unique(found); });
  return all;
}

}  // namespace tritri
