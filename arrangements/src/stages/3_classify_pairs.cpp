#include "stages/3_classify_pairs.h"

#include <tritri/counting_kernel.h>
#include <tritri/detail/ordered_parallel.h>
#include <tritri/double_kernel.h>
#include <tritri/shared_vertices.h>

#include "stages/3_classify_native.h"
#include "stages/3_classify_tritri.h"

namespace arrangements {
namespace {

// Pairs [begin, end) with the predicates of kernel k, the intersecting ones appended to
// `found`. Neighbours that meet only in what they share contribute nothing (both
// classifiers drop such pairs): settled by 1 to 4 orient3d instead of a full
// classification.
template <class K>
void classify_range(const K& k, const std::vector<Vec3>& V, const std::vector<Tri>& F,
                    const std::vector<std::pair<int, int>>& pairs, std::size_t begin, std::size_t end,
                    Classifier classifier, std::vector<PairIntersection>& found) {
  PairIntersection record;
  for (std::size_t i = begin; i < end; ++i) {
    const Tri& a = F[pairs[i].first];
    const Tri& b = F[pairs[i].second];
    if (tritri::meet_only_in_shared(k, {V[a[0]], V[a[1]], V[a[2]]}, a, {V[b[0]], V[b[1]], V[b[2]]}, b)) continue;
    bool hit = false;
    switch (classifier) {
      case Classifier::Native:
        hit = classify_pair_native(k, V, F, pairs[i].first, pairs[i].second, record);
        break;
      case Classifier::Tritri:
        hit = classify_pair_tritri(k, V, F, pairs[i].first, pairs[i].second, record);
        break;
    }
    if (hit) found.push_back(record);
  }
}

}  // namespace

std::vector<PairIntersection> classify_pairs(const std::vector<Vec3>& V, const std::vector<Tri>& F,
                                             const std::vector<std::pair<int, int>>& pairs, Classifier classifier,
                                             tritri::PredicateCounts* counts) {
  // Fixed chunks, concatenated in order (the loop tritri's batch API uses too): the
  // output does not depend on scheduling.
  constexpr std::size_t chunk = 2048;
  // Counting: one PredicateCounts per chunk (one worker at a time), summed at the end.
  std::vector<tritri::PredicateCounts> chunk_counts(counts ? (pairs.size() + chunk - 1) / chunk : 0);
  std::vector<PairIntersection> all = tritri::detail::collect_in_order<PairIntersection>(
      pairs.size(), chunk,
      [&](std::size_t c, std::size_t begin, std::size_t end, std::vector<PairIntersection>& found) {
        if (counts)
          classify_range(tritri::CountingKernel<tritri::DoubleKernel>(chunk_counts[c]), V, F, pairs, begin, end,
                         classifier, found);
        else
          classify_range(tritri::DoubleKernel{}, V, F, pairs, begin, end, classifier, found);
      });
  for (const auto& n : chunk_counts) {
    counts->orient3d += n.orient3d;
    counts->orient2d += n.orient2d;
    counts->equal += n.equal;
    counts->less += n.less;
  }
  return all;
}

}  // namespace arrangements
