// tritri/detail/ordered_parallel.h
//
// collect_in_order<T>(n, chunk, visit): the one parallel loop over candidate pairs that
// every mesh-level classification uses (tritri's batch API in mesh_pairs.h and the
// arrangement pipeline's classification stage). [0, n) is cut into fixed chunks of
// `chunk` items; visit(c, begin, end, out) handles chunk c = [begin, end) and appends
// what it finds to `out`, its own vector; the vectors are concatenated in chunk order.
// So the result depends only on the inputs, never on scheduling or on the number of
// threads (oneTBB; the caller's arena or global_control limits apply). Per-chunk state
// (e.g. predicate counters) can be indexed by c.
// Cost: n visits, parallel; one extra copy of the results (collect_chunks_in_order: none).
#pragma once

#include <tbb/parallel_for.h>

#include <cstddef>
#include <vector>

namespace tritri::detail {

// The same loop, the per-chunk containers (Chunk: std::vector<T>, or any default-
// constructible container the visitor fills) returned as they are (no concatenated copy:
// at millions of results that copy doubles the peak memory); in order, chunk by chunk.
template <class Chunk, class Visit>
std::vector<Chunk> collect_chunks_in_order(std::size_t n, std::size_t chunk, const Visit& visit) {
  const std::size_t chunks = (n + chunk - 1) / chunk;
  std::vector<Chunk> found(chunks);
  tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
    const std::size_t begin = c * chunk, end = begin + chunk < n ? begin + chunk : n;
    visit(c, begin, end, found[c]);
  });
  return found;
}

template <class T, class Visit>
std::vector<T> collect_in_order(std::size_t n, std::size_t chunk, const Visit& visit) {
  std::vector<std::vector<T>> found = collect_chunks_in_order<std::vector<T>>(n, chunk, visit);
  std::size_t total = 0;
  for (const auto& f : found) total += f.size();
  std::vector<T> out;
  out.reserve(total);
  for (auto& f : found) out.insert(out.end(), f.begin(), f.end());
  return out;
}

}  // namespace tritri::detail
