#include "stages/3_classify_pairs.h"

#include <span>
#include <type_traits>

#include <tritri/counting_kernel.h>
#include <tritri/detail/ordered_parallel.h>
#include <tritri/double_kernel.h>
#include <tritri/plane_filter.h>

#include "arrangements/memory_budget.h"
#include "stages/3_classify_native.h"
#include "stages/3_classify_tritri.h"
#include "models/exact_model.h"

namespace arrangements {
namespace {

template <class K>
bool classify_one(const K& k, const std::vector<typename K::Point>& V, const std::vector<Tri>& F, int ta, int tb,
                  Classifier classifier, PairIntersection& record) {
  switch (classifier) {
    case Classifier::Native:
      return classify_pair_native(k, V, F, ta, tb, record);
    case Classifier::Tritri:
      return classify_pair_tritri(k, V, F, ta, tb, record);
  }
  return false;
}

// Pairs [begin, end), the intersecting ones appended to `found`: with the predicates of
// kernel k, or (planes given, no counting) with each pair's two cached planes
// (tritri::PlaneCachedKernel: the same exact answers, cheaper). (Neighbours that meet
// only in what they share, and pairs separated by a plane, usually never get here: stage
// 2 drops them. The classifiers report nothing for them.)
template <class K, class Cache>
void classify_range(const K& k, const std::vector<typename K::Point>& V, const std::vector<Tri>& F,
                    std::span<const Cache> planes, const std::vector<std::pair<int, int>>& pairs,
                    std::size_t begin, std::size_t end, Classifier classifier, PairRecordChunk& found) {
  PairIntersection record;
  for (std::size_t i = begin; i < end; ++i) {
    detail::memory_checkpoint();
    const auto [ta, tb] = pairs[i];
    bool hit;
    if constexpr (std::is_same_v<K, tritri::DoubleKernel>) {
      if (!planes.empty()) {
        const Vec3* a[3] = {&V[F[ta][0]], &V[F[ta][1]], &V[F[ta][2]]};
        const Vec3* b[3] = {&V[F[tb][0]], &V[F[tb][1]], &V[F[tb][2]]};
        hit = classify_one(tritri::PlaneCachedKernel(a, planes[ta], b, planes[tb]), V, F, ta, tb, classifier, record);
        if (hit) found.push_back(record);
        continue;
      }
    }
    hit = classify_one(k, V, F, ta, tb, classifier, record);
    if (hit) found.push_back(record);
  }
  found.shrink_to_fit();
}

}  // namespace

template <class M>
PairRecords classify_pairs(const std::vector<typename M::Vertex>& V, const std::vector<Tri>& F,
                           const std::vector<std::pair<int, int>>& pairs, Classifier classifier,
                           tritri::PredicateCounts* counts, std::span<const typename M::PlaneCache> planes) {
  using K = typename M::Kernel;
  // Fixed chunks, concatenated in order (the loop tritri's batch API uses too): the
  // output does not depend on scheduling.
  constexpr std::size_t chunk = 2048;
  // Counting: one PredicateCounts per chunk (one worker at a time), summed at the end.
  std::vector<tritri::PredicateCounts> chunk_counts(counts ? (pairs.size() + chunk - 1) / chunk : 0);
  PairRecords all(tritri::detail::collect_chunks_in_order<PairRecordChunk>(
      pairs.size(), chunk, [&](std::size_t c, std::size_t begin, std::size_t end, PairRecordChunk& found) {
        if (counts)
          classify_range(tritri::CountingKernel<K>(chunk_counts[c]), V, F, std::span<const typename M::PlaneCache>{},
                         pairs, begin, end, classifier, found);
        else
          classify_range(K{}, V, F, planes, pairs, begin, end, classifier, found);
      }));
  for (const auto& n : chunk_counts) {
    counts->orient3d += n.orient3d;
    counts->orient2d += n.orient2d;
    counts->equal += n.equal;
    counts->less += n.less;
  }
  return all;
}

template PairRecords classify_pairs<DoubleModel>(const std::vector<Vec3>&, const std::vector<Tri>&,
                                                 const std::vector<std::pair<int, int>>&, Classifier,
                                                 tritri::PredicateCounts*, std::span<const tritri::PlaneFilter>);
template PairRecords classify_pairs<ExactModel>(const std::vector<ExactModel::Vertex>&, const std::vector<Tri>&,
                                                const std::vector<std::pair<int, int>>&, Classifier,
                                                tritri::PredicateCounts*, std::span<const ExactModel::PlaneCache>);

}  // namespace arrangements
