// arrangements/src/stages/2_coplanar_budget.h
//
// refuse_huge_coplanar_clusters<M>(V, F, pairs, planes): the end of stage 2, for input whose
// coplanar overlaps would make stages 3-5 blow up (issue 36). Stage 5 triangulates every
// triangle with the segments of all its coplanar partners and computes their crossings inside it, so a
// cluster of coplanar triangles that all overlap each other costs per triple of mutually
// overlapping triangles (t, u, v: the crossings of u and v inside t are computed again in
// t), up to the fourth power of the cluster's size: 100 thin wedges through one region
// (1.6e5 triples) took 30 s, 3,000 (4.5e9 triples) ran out of memory, and so did the fan a
// self-intersecting polygon face of 2,001 corners is split into (triangulate_polygon.h).
// A run whose candidate pairs (stage 2, after its exact early-outs) hold more than
// kMaxCoplanarTriples triples of triangles that are pairwise coplanar candidates is
// refused (InputError too_large, with the count and a triangle of the cluster) before
// stage 3 allocates anything for them. Coplanar: every corner of one triangle in the
// other's plane, by exact orient3d. The budget is a proxy, not the output size: ten
// different tessellations of one square of 200 triangles each (4e5 triples, but each
// crossing lies in few triangles) arrange in 3 s and pass; clusters between 1.6e5 and 1e6
// triples that overlap in one region (130 to 180 such wedges) still pass and take minutes.
// Cost: 3 orient3d per pair plus, per pair (t, u), t < u, u's forward coplanar degree; the
// count stops as soon as it exceeds the budget, and after kMaxTripleWork adjacency steps
// without reaching it (a weave of coplanar strips has no triples) the run goes on.
// Coplanar pairs are found with the stage's cached planes first (M::certified_side_of_plane
// for doubles: no exact orient3d for the pairs it decides), then exact orient3d.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "arrangements/triangle_soup.h"

namespace arrangements {

inline constexpr std::uint64_t kMaxCoplanarTriples = 1'000'000;
inline constexpr std::uint64_t kMaxTripleWork = 400'000'000;  // adjacency steps of the count

template <class M>
void refuse_huge_coplanar_clusters(const std::vector<typename M::Vertex>& V, const std::vector<Tri>& F,
                                   const std::vector<std::pair<int, int>>& pairs,
                                   std::span<const typename M::PlaneCache> planes);

}  // namespace arrangements
