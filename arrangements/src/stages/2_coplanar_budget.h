// arrangements/src/stages/2_coplanar_budget.h
//
// refuse_huge_coplanar_clusters(triangles, coplanar): the end of stage 2, for input whose
// coplanar overlaps would make stages 3-5 blow up (issue 36). Coplanar partners receive
// each other's points and segments (stage 4), so a cluster of coplanar triangles that all
// overlap each other holds per triple of mutually overlapping triangles (t, u, v: the
// crossings of u and v are listed again in t) and costs that in stage 4's sharing and
// memory, up to the fourth power of the cluster's size: 3,000 thin wedges through one
// region (4.5e9 triples) ran out of memory, and so did the fan a self-intersecting
// polygon face of 2,001 corners is split into (triangulate_polygon.h). (Stage 5
// triangulates such a cluster whole, 5_triangulate_cluster.h, not once per triangle as it
// did: 100 wedges, 1.6e5 triples, went from 71 s to 1.1 s.)
// A run whose candidate pairs (stage 2, after its exact early-outs) hold more than
// kMaxCoplanarTriples triples of triangles that are pairwise coplanar candidates is
// refused (InputError too_large, with the count and a triangle of the cluster) before
// stage 3 allocates anything for them. coplanar: the pairs i < j (sorted) whose
// triangles lie in one plane, from stage 2's exact plane signs (BasicDetectedPairs). The
// budget is a proxy, not the output size: ten different tessellations of one square of 200
// triangles each (4e5 triples, but each crossing lies in few triangles) arrange in 3 s and
// pass; 180 such wedges (9.7e5 triples) pass and take 6.3 s.
// Cost: per coplanar pair (t, u), t < u, u's forward coplanar degree; the
// count stops as soon as it exceeds the budget, and after kMaxTripleWork adjacency steps
// without reaching it (a weave of coplanar strips has no triples) the run goes on.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace arrangements {

inline constexpr std::uint64_t kMaxCoplanarTriples = 1'000'000;
inline constexpr std::uint64_t kMaxTripleWork = 400'000'000;  // adjacency steps of the count

void refuse_huge_coplanar_clusters(std::size_t triangles, const std::vector<std::pair<int, int>>& coplanar);

}  // namespace arrangements
