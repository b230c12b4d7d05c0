// arrangements/src/stages/2_early_outs.h
//
// early_out<M>(V, F, planes, i, j): stage 2's exact decision on one box pair of triangles,
// i and j of F over vertices V (point model M, models/point_model.h), with planes[t] =
// M::plane_cache of triangle t. `settled` when the two provably meet only in what they share
// by index (or not at all), so that no classifier reports anything for the pair; else kept,
// with `flat` when the two lie in one plane. The early-outs are listed in
// 2_candidate_pairs.h. Shared by detect_pairs and by check_arrangement on rounded meshes.
// Preconditions (stage 1's): equal indices are equal points and distinct indices distinct
// points; neither triangle is degenerate; the two are not one triangle twice.
// Exact: every decision is an exact sign. Cost: 1 to 12 plane signs (filtered) and at most
// one projection test.
#pragma once

#include <array>
#include <vector>

#include <tritri/shared_vertices.h>

#include "arrangements/triangle_soup.h"

namespace arrangements {

struct EarlyOut {
  bool settled = false;
  bool flat = false;  // when kept: every free corner of one in the other's plane
};

template <class M>
EarlyOut early_out(const std::vector<typename M::Vertex>& V, const std::vector<Tri>& F,
                   const std::vector<typename M::PlaneCache>& planes, int i, int j) {
  using Vertex = typename M::Vertex;
  const Tri& a = F[i];
  const Tri& b = F[j];
  int in_b[3];
  const bool shares = tritri::detail::shared_corners(a, b, in_b) > 0;
  // Projections that meet only in what the two share (or not at all) rule out other
  // contact, for any pair (tritri/shared_vertices.h).
  auto in_projection = [&] {
    const typename M::Kernel k;
    const std::array<Vertex, 3> pa{V[a[0]], V[a[1]], V[a[2]]}, pb{V[b[0]], V[b[1]], V[b[2]]};
    return shares ? tritri::meet_in_shared_in_projection(k, pa, a, pb, b) : tritri::separated_in_projection(k, pa, pb);
  };
  // side(t, k): corner k of the other triangle against the plane of triangle t (0: a),
  // each evaluated at most once.
  tritri::Sign known[2][3];
  bool have[2][3] = {};
  // Whether the projection test ran (before the first plane sign the filter left
  // undecided: an exact orient3d costs far more than the orient2d of a projection, and
  // exactly coplanar contacts, common where parts touch, are all such signs), and
  // whether it settled the pair, in which case the plane tests' answers are discarded.
  bool projection_tried = false, settled_in_projection = false;
  auto side = [&](int t, int corner) {
    if (!have[t][corner]) {
      const Tri& p = t == 0 ? a : b;
      const Tri& o = t == 0 ? b : a;
      const auto& plane = planes[t == 0 ? i : j];
      if constexpr (!M::kProjectionFirst) {
        if (const auto s = M::certified_side_of_plane(plane, V[p[0]], V[o[corner]])) {
          known[t][corner] = *s;
          have[t][corner] = true;
          return *s;
        }
        if (settled_in_projection) return tritri::Sign::Zero;  // discarded
        if (!projection_tried) {
          projection_tried = true;
          settled_in_projection = in_projection();
          if (settled_in_projection) return tritri::Sign::Zero;  // discarded
        }
      }
      known[t][corner] = M::side_of_plane(plane, V[p[0]], V[p[1]], V[p[2]], V[o[corner]]);
      have[t][corner] = true;
    }
    return known[t][corner];
  };
  // Coplanar: b's free corners (not shared with a) all in plane(a). Usually a known
  // nonzero sign answers at once.
  auto coplanar = [&] {
    for (int c = 0; c < 3; ++c)
      if (b[c] != a[0] && b[c] != a[1] && b[c] != a[2] && side(0, c) != tritri::Sign::Zero) return false;
    return true;
  };
  constexpr EarlyOut kSettled{true, false};
  if constexpr (M::kProjectionFirst) {
    // Projections first: for rational points an exact zero (coplanar pieces of one
    // input triangle, common in an arrangement arranged again) costs far more than the
    // orient2d that the intervals decide.
    projection_tried = true;
    if (in_projection()) return kSettled;
  }
  bool settled = shares ? tritri::meet_only_in_shared_by_sides(a, b, side) : tritri::separated_by_plane(side);
  if (settled_in_projection) return kSettled;
  bool flat = false;  // every kept pair gets here unsettled, so flat is known for it
  if (!settled) {
    const typename M::Kernel k;
    const std::array<Vertex, 3> pa{V[a[0]], V[a[1]], V[a[2]]}, pb{V[b[0]], V[b[1]], V[b[2]]};
    flat = coplanar();
    if (settled_in_projection) return kSettled;
    if (!flat) {  // one triangle touching the other's plane without crossing it
      const tritri::Sign sb[3] = {side(0, 0), side(0, 1), side(0, 2)};
      if (settled_in_projection) return kSettled;
      settled = tritri::touches_only_in_shared(k, pa, a, pb, b, sb);
      if (!settled) {  // a's signs only now: most pairs are settled by b's
        const tritri::Sign sa[3] = {side(1, 0), side(1, 1), side(1, 2)};
        if (settled_in_projection) return kSettled;
        settled = tritri::touches_only_in_shared(k, pb, b, pa, a, sa);
      }
    }
    // Coplanar, or each straddling the other's plane: projections that meet only in what
    // the two share (or not at all) rule out other contact.
    if (!settled && !projection_tried) settled = in_projection();
  }
  return settled ? kSettled : EarlyOut{false, flat};
}

}  // namespace arrangements
