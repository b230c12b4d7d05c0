// The end of stage 2: the coplanar-cluster budget (see 2_coplanar_budget.h).
#include "stages/2_coplanar_budget.h"

#include <tbb/parallel_for.h>

#include <string>

#include "arrangements/input_error.h"
#include "models/double_model.h"
#include "models/exact_model.h"

namespace arrangements {

template <class M>
void refuse_huge_coplanar_clusters(const std::vector<typename M::Vertex>& V, const std::vector<Tri>& F,
                                   const std::vector<std::pair<int, int>>& pairs,
                                   std::span<const typename M::PlaneCache> planes) {
  if (pairs.size() < 3) return;
  std::vector<char> coplanar(pairs.size(), 0);
  tbb::parallel_for(std::size_t{0}, pairs.size(), [&](std::size_t i) {
    const Tri& a = F[pairs[i].first];
    const Tri& b = F[pairs[i].second];
    bool c = true;
    for (int k = 0; k < 3 && c; ++k) {
      if constexpr (!M::kProjectionFirst) {  // the cached plane decides most corners at once
        if (const auto sign = M::certified_side_of_plane(planes[pairs[i].first], V[a[0]], V[b[k]])) {
          c = *sign == tritri::Sign::Zero;
          continue;
        }
      }
      c = M::orient3d(V[a[0]], V[a[1]], V[a[2]], V[b[k]]) == tritri::Sign::Zero;
    }
    coplanar[i] = c;
  });
  std::vector<std::size_t> start(F.size() + 1, 0);
  for (std::size_t i = 0; i < pairs.size(); ++i)
    if (coplanar[i]) ++start[pairs[i].first + 1];  // forward adjacency: t < u
  std::size_t edges = 0;
  for (std::size_t t = 0; t < F.size(); ++t) edges += start[t + 1], start[t + 1] = edges;
  if (edges < 3) return;
  std::vector<int> next(edges);
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < pairs.size(); ++i)  // pairs are sorted: each list ascending
      if (coplanar[i]) next[fill[pairs[i].first]++] = pairs[i].second;
  }
  // Triples t < u < v with (t, u), (t, v), (u, v) all coplanar candidate pairs.
  std::vector<int> mark(F.size(), -1);
  std::uint64_t triples = 0, work = 0;
  std::size_t cluster = 0;  // the triangles of the largest neighbourhood seen, for the message
  int where = -1;
  for (std::size_t t = 0; t < F.size(); ++t) {
    if (start[t + 1] - start[t] < 2) continue;
    for (std::size_t i = start[t]; i < start[t + 1]; ++i) mark[next[i]] = static_cast<int>(t);
    for (std::size_t i = start[t]; i < start[t + 1]; ++i) {
      const int u = next[i];
      for (std::size_t j = start[u]; j < start[u + 1]; ++j) triples += mark[next[j]] == static_cast<int>(t);
      work += start[u + 1] - start[u];
    }
    if (start[t + 1] - start[t] > cluster) cluster = start[t + 1] - start[t], where = static_cast<int>(t);
    if (triples > kMaxCoplanarTriples)
      throw InputError(InputErrorKind::too_large,
                       "coplanar triangles overlap each other too densely: more than " +
                           std::to_string(kMaxCoplanarTriples) +
                           " triples of coplanar triangles that pairwise may overlap (triangle " +
                           std::to_string(where) + " of the preprocessed input pairs with " + std::to_string(cluster) +
                           " coplanar triangles after it; the fan a self-intersecting polygon face is split into "
                           "is such a cluster). Arranging them would take time and memory growing with the "
                           "triples (budget: " + std::to_string(kMaxCoplanarTriples) +
                           "); split the cluster or resolve the overlaps first");
    if (work > kMaxTripleWork) return;  // no verdict without a bounded count: arranged as before
  }
}

template void refuse_huge_coplanar_clusters<DoubleModel>(const std::vector<Vec3>&, const std::vector<Tri>&,
                                                         const std::vector<std::pair<int, int>>&,
                                                         std::span<const DoubleModel::PlaneCache>);
template void refuse_huge_coplanar_clusters<ExactModel>(const std::vector<ExactModel::Vertex>&,
                                                        const std::vector<Tri>&,
                                                        const std::vector<std::pair<int, int>>&,
                                                        std::span<const ExactModel::PlaneCache>);

}  // namespace arrangements
