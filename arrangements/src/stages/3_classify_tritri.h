// arrangements/src/stages/3_classify_tritri.h
//
// classify_pair_tritri: the drop-in classifier: tritri::classify on the pair (double
// backend), converted by an adapter into the same PairIntersection record the native
// classifier fills (docs/ARCHITECTURE.md, stage [3]):
//   VA_ON_VB                     the shared vertex (nothing new);
//   VA_ON_EB, VB_ON_EA, V*_ON_T* the existing vertex, recorded on that edge / face;
//   EA_CROSS_TB / EB_CROSS_TA    a new LPI: the edge's line with the other triangle's plane;
//   EA_CROSS_EB                  a new LPI: non-coplanar, the line of an edge that crosses
//                                the other plane (an edge lying in it would give an undefined
//                                point); coplanar, A's edge line with the plane through B's
//                                edge and B's auxiliary point (well defined; the authors'
//                                tool builds an undefined point here).
// A pair whose only contact is shared mesh vertices (all points VA_ON_VB) is dropped.
//
// Inputs, output, exactness and cost: as classify_pair_native (the same kernel k, the same
// two instantiations): k serves tritri::classify and the adapter's own orient3d calls.
#pragma once

#include <vector>

#include <tritri/counting_kernel.h>
#include <tritri/double_kernel.h>
#include <tritri/plane_filter.h>

#include "stages/3_pair_intersection.h"
#include "arrangements/triangle_soup.h"

namespace arrangements {

template <class K>
bool classify_pair_tritri(const K& k, const std::vector<typename K::Point>& V, const std::vector<Tri>& F, int ta,
                          int tb, PairIntersection& out);
extern template bool classify_pair_tritri(const tritri::DoubleKernel&, const std::vector<Vec3>&,
                                          const std::vector<Tri>&, int, int, PairIntersection&);
extern template bool classify_pair_tritri(const tritri::PlaneCachedKernel&, const std::vector<Vec3>&,
                                          const std::vector<Tri>&, int, int, PairIntersection&);
extern template bool classify_pair_tritri(const tritri::CountingKernel<tritri::DoubleKernel>&, const std::vector<Vec3>&,
                                          const std::vector<Tri>&, int, int, PairIntersection&);

inline bool classify_pair_tritri(const std::vector<Vec3>& V, const std::vector<Tri>& F, int ta, int tb,
                                 PairIntersection& out) {
  return classify_pair_tritri(tritri::DoubleKernel{}, V, F, ta, tb, out);
}

}  // namespace arrangements
