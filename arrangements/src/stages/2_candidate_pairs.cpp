// Stage 2: bounding-box candidate pairs (see 2_candidate_pairs.h): the same search as
// tritri's batch API (tritri/box_pairs.h), with the pipeline's thread cap.
#include "stages/2_candidate_pairs.h"

#include <stdexcept>
#include <string>

#include <tritri/box_pairs.h>

#include "arrangements/thread_count.h"

namespace arrangements {

std::vector<std::pair<int, int>> candidate_pairs(const std::vector<Vec3>& V, const std::vector<Tri>& F, int threads,
                                                 std::span<const std::int64_t> polygon) {
  if (threads > kMaxThreads)
    throw std::invalid_argument("candidate_pairs: threads must be at most " + std::to_string(kMaxThreads));
  return tritri::overlapping_triangle_pairs(V, F, threads, polygon);
}

}  // namespace arrangements
