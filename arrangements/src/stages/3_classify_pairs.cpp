#include "stages/3_classify_pairs.h"

#include <tbb/parallel_for.h>
#include <tritri/counting_kernel.h>
#include <tritri/double_kernel.h>
#include <tritri/shared_vertices.h>

#include "stages/3_classify_native.h"
#include "stages/3_classify_tritri.h"
#include "support/predicate_counts.h"

namespace arrangements {
namespace {

// Neighbours that meet only in what they share contribute nothing (both classifiers drop
// such pairs): settled by 1 to 4 orient3d instead of a full classification.
bool settled_as_neighbours(const std::vector<Vec3>& V, const Tri& a, const Tri& b, tritri::PredicateCounts* counts) {
  const std::array<Vec3, 3> pa = {V[a[0]], V[a[1]], V[a[2]]}, pb = {V[b[0]], V[b[1]], V[b[2]]};
  if (counts) return tritri::meet_only_in_shared(tritri::CountingKernel<tritri::DoubleKernel>(*counts), pa, a, pb, b);
  return tritri::meet_only_in_shared(tritri::DoubleKernel{}, pa, a, pb, b);
}

}  // namespace

std::vector<PairIntersection> classify_pairs(const std::vector<Vec3>& V, const std::vector<Tri>& F,
                                             const std::vector<std::pair<int, int>>& pairs,
                                             Classifier classifier, tritri::PredicateCounts* counts) {
  // Fixed chunks, concatenated in order: the output does not depend on scheduling.
  constexpr std::size_t chunk = 2048;
  const std::size_t chunks = (pairs.size() + chunk - 1) / chunk;
  std::vector<std::vector<PairIntersection>> found(chunks);
  std::vector<tritri::PredicateCounts> chunk_counts(counts ? chunks : 0);
  tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
    // The counter is per chunk (one worker at a time), installed for this thread.
    tritri::PredicateCounts*& installed = classification_counts();
    tritri::PredicateCounts* const outer = installed;
    installed = counts ? &chunk_counts[c] : nullptr;
    PairIntersection record;
    const std::size_t end = std::min(pairs.size(), (c + 1) * chunk);
    for (std::size_t i = c * chunk; i < end; ++i) {
      if (settled_as_neighbours(V, F[pairs[i].first], F[pairs[i].second], installed)) continue;
      bool hit = false;
      switch (classifier) {
        case Classifier::Native:
          hit = classify_pair_native(V, F, pairs[i].first, pairs[i].second, record);
          break;
        case Classifier::Tritri:
          hit = classify_pair_tritri(V, F, pairs[i].first, pairs[i].second, record);
          break;
      }
      if (hit) found[c].push_back(record);
    }
    installed = outer;
  });
  for (const auto& n : chunk_counts) {
    counts->orient3d += n.orient3d;
    counts->orient2d += n.orient2d;
  }
  std::vector<PairIntersection> all;
  for (auto& f : found) all.insert(all.end(), f.begin(), f.end());
  return all;
}

}  // namespace arrangements
