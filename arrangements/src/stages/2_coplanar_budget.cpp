// The end of stage 2: the coplanar-cluster budget (see 2_coplanar_budget.h).
#include "stages/2_coplanar_budget.h"

#include <string>

#include "arrangements/input_error.h"

namespace arrangements {

void refuse_huge_coplanar_clusters(std::size_t triangles, const std::vector<std::pair<int, int>>& coplanar) {
  if (coplanar.size() < 3) return;
  std::vector<std::size_t> start(triangles + 1, 0);
  for (const auto& [t, u] : coplanar) ++start[t + 1];  // forward adjacency: t < u
  std::size_t edges = 0;
  for (std::size_t t = 0; t < triangles; ++t) edges += start[t + 1], start[t + 1] = edges;
  if (edges < 3) return;
  std::vector<int> next(edges);
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (const auto& [t, u] : coplanar) next[fill[t]++] = u;  // sorted pairs: each list ascending
  }
  // Triples t < u < v with (t, u), (t, v), (u, v) all coplanar candidate pairs.
  std::vector<int> mark(triangles, -1);
  std::uint64_t triples = 0, work = 0;
  std::size_t cluster = 0;  // the triangles of the largest neighbourhood seen, for the message
  int where = -1;
  for (std::size_t t = 0; t < triangles; ++t) {
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

}  // namespace arrangements
