// pair_fault: the rule of check_arrangement (arrangements/check_arrangement.h) for one pair of
// triangles, shared by the check and by nudge_conflicts (rounding/round_nudged.cpp), which weighs
// moves of one vertex by the pairs they make or mend.
#pragma once

#include <algorithm>
#include <array>
#include <type_traits>

#include <tritri/classify.h>
#include <tritri/constructed_plane_sides.h>
#include <tritri/shared_vertices.h>

#include "arrangements/output_mesh.h"

namespace arrangements {

enum class PairFault {
  none,                 // they meet exactly in what they share by vertex id
  same_vertices,        // the same three vertices
  beyond_shared,        // they meet beyond their shared vertices (result: what tritri found)
  shared_not_reported,  // a shared vertex is not where they meet
  unexpected_segments,  // a shared edge is not their intersection, or a vertex is a segment
  degenerate            // one of them is degenerate (the check reports it per triangle)
};

// The fault shown by tritri's classification r of a and b, which share `shared` corners.
inline PairFault classified_fault(const Tri& a, const Tri& b, int shared, const tritri::Result& r,
                                  tritri::Result* result) {
  if (result) *result = r;
  if (r.degenerate) return PairFault::degenerate;
  int on_shared = 0;
  for (const auto& p : r.points) {
    if (p.type != tritri::Type::VA_ON_VB || a[p.id0] != b[p.id1]) return PairFault::beyond_shared;
    ++on_shared;
  }
  if (on_shared != shared) return PairFault::shared_not_reported;
  if (r.segments.size() != (shared == 2 ? 1u : 0u)) return PairFault::unexpected_segments;
  return PairFault::none;
}

// a, b: the triangles' vertex ids; pa, pb: their corners (kernel K). `result`, when given,
// receives tritri's classification when one was made. Exact; one classification at most
// (neighbours that provably meet only in what they share skip it: tritri's sufficient
// conditions, each proved in shared_vertices.h, in a projection first, then by plane signs;
// for implicit points, plane signs against the source planes first, constructed_plane_sides.h).
// `planes`, for implicit points: a's and b's tritri::source_plane when the caller found
// them once per triangle (else the planes are found here, and classify does not use them).
template <class K>
PairFault pair_fault(const Tri& a, const std::array<typename K::Point, 3>& pa, const Tri& b,
                     const std::array<typename K::Point, 3>& pb, tritri::Result* result = nullptr,
                     const std::array<const tritri::SourcePlane*, 2>* planes = nullptr) {
  int shared = 0;
  for (int x : a) shared += std::count(b.begin(), b.end(), x) > 0;
  if (shared == 3) return PairFault::same_vertices;
  if constexpr (std::is_same_v<typename K::Point, tritri::ImplicitPoint>) {
    // Plane signs against the source planes the triangles were built on, not their own
    // corners (cheaper: three explicit operands), unless both lie on one of them
    // (coplanar: the tests in a projection decide). Where a triangle has no such plane its
    // own corners stand in, so meet_only_in_shared would repeat these signs.
    const tritri::ConstructedPlaneSides sides =
        planes ? tritri::ConstructedPlaneSides(pa, pb, (*planes)[0]->corners, (*planes)[1]->corners)
               : tritri::ConstructedPlaneSides(pa, pb);
    if (!sides.same_plane() &&
        (shared == 0 ? tritri::separated_by_plane(sides) : tritri::meet_only_in_shared_by_sides(a, b, sides)))
      return PairFault::none;
    if (shared > 0 && tritri::meet_in_shared_in_projection(K{}, pa, a, pb, b)) return PairFault::none;
    if (shared == 0 && tritri::separated_in_projection(K{}, pa, pb)) return PairFault::none;
    const tritri::SourcePlaneKernel k{&sides, {planes ? (*planes)[0]->orientation : 0,
                                               planes ? (*planes)[1]->orientation : 0}};
    return classified_fault(a, b, shared, tritri::classify(k, pa[0], pa[1], pa[2], pb[0], pb[1], pb[2]), result);
  } else if (shared > 0 && (tritri::meet_in_shared_in_projection(K{}, pa, a, pb, b) ||
                            tritri::meet_only_in_shared(K{}, pa, a, pb, b))) {
    return PairFault::none;
  }
  if (shared == 0 && tritri::separated_in_projection(K{}, pa, pb)) return PairFault::none;
  return classified_fault(a, b, shared, tritri::classify<K>(pa[0], pa[1], pa[2], pb[0], pb[1], pb[2]), result);
}

}  // namespace arrangements
