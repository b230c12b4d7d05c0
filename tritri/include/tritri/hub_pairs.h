// tritri/hub_pairs.h
//
// for_each_candidate_pair(V, F, threads, group, visit, keys = {}): the candidate pairs of a triangle
// mesh or soup without the pairwise enumeration of the triangles around a vertex of high
// degree (a hub: the apex of a fan, a cylinder cap's centre, a cone's tip). Every box
// around a hub holds the hub, so a box search pairs all of its n triangles: n^2 / 2 pairs
// that, on a fan, meet only in the hub or a shared edge.
//   V, F, threads, group, keys  as for_each_overlapping_pair (tritri/box_pairs.h)
//   visit                 visit(i, j), i < j, const, callable from several threads at once
// visit is called once for every pair (outside one group) of for_each_overlapping_pair
// without keys, except pairs of triangles around one hub whose directions from the hub are
// disjoint: those meet only in the hub; with keys, pairs whose keys share a value may also
// be skipped (within a star always, where its arcs are searched by the grid). The set does
// not depend on `threads`.
// Method: a hub is a vertex of at least kHubDegree triangles; each triangle incident to a
// hub (and in no group of the caller) joins the star of its hub of highest degree (ties:
// the smaller vertex id). Stars are used only when their own pairs (s^2 / 2 for a star of
// s triangles, summed) outnumber the triangles; otherwise this is for_each_overlapping_pair. The box search runs with the stars as groups (box_pairs.h: a
// star's own pairs are never listed; the others through an R-tree of the star). Within a
// star of hub v, the triangle (v, a, b) sees from v the great-circle arc of directions
// from a - v to b - v (its angle at v is below pi); two triangles of the star that meet in
// a point p != v meet in the segment vp (their intersection is convex and holds v), so
// their arcs share the direction of p - v. The arcs' boxes on the unit sphere are searched
// for overlaps like triangle boxes; pairs whose arc boxes are apart meet only in v.
// Exactness: the arcs' boxes are computed in double arithmetic and widened by 2^-30 (the
// rounding of a - v, of the normalisation and of the arc's bulge is below 2^-48 on unit
// vectors), so they contain the exact arcs: no pair that meets elsewhere than v is lost.
// A difference a - v whose largest component is subnormal is scaled by a power of two first
// (exact). An arc of nearly pi (1 + cos below 2^-20) gets the box of the whole sphere.
// Cost: the box search (box_pairs.h) plus O(s log s) per star of s triangles; memory about
// 3 x 64 bytes per triangle of a star.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "tritri/box_pairs.h"

namespace tritri {
namespace detail::hub_pairs {

constexpr int kHubDegree = 32;

// The unit vector of d (nonzero), computed in double arithmetic.
inline std::array<double, 3> unit(std::array<double, 3> d) {
  const double m = std::max({std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2])});
  int e = 0;
  std::frexp(m, &e);
  for (double& x : d) x = std::ldexp(x, -e);  // exact: a power of two, into [0.5, 1)
  const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  for (double& x : d) x /= n;
  return d;
}

// A box on the unit sphere holding the great-circle arc from the direction of a - v to
// that of b - v (the shorter arc; a, b, v not collinear).
inline CGAL::Bbox_3 arc_box(const std::array<double, 3>& v, const std::array<double, 3>& a,
                            const std::array<double, 3>& b) {
  constexpr double margin = 0x1p-30;
  const auto u1 = unit({a[0] - v[0], a[1] - v[1], a[2] - v[2]});
  const auto u2 = unit({b[0] - v[0], b[1] - v[1], b[2] - v[2]});
  const double c = 1 + u1[0] * u2[0] + u1[1] * u2[1] + u1[2] * u2[2];
  if (!(c > 0x1p-20)) return {-2, -2, -2, 2, 2, 2};
  // The arc lies in the triangle (u1, u2, w), w where the tangents at u1 and u2 meet.
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    const double w = (u1[k] + u2[k]) / c;
    lo[k] = std::min({u1[k], u2[k], w}) - margin;
    hi[k] = std::max({u1[k], u2[k], w}) + margin;
  }
  return {lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]};
}

}  // namespace detail::hub_pairs

// (See the top of this file.)
template <class Visit>
void for_each_candidate_pair(std::span<const std::array<double, 3>> V, std::span<const std::array<int, 3>> F,
                             int threads, std::span<const std::int64_t> group, const Visit& visit,
                             std::span<const std::array<int, 3>> keys = {}) {
  using namespace detail::hub_pairs;
  using detail::box_pairs::Box;
  if (!group.empty() && group.size() != F.size())
    throw std::invalid_argument("tritri::for_each_candidate_pair: group must be empty or have one entry per triangle");
  if (!keys.empty() && keys.size() != F.size())
    throw std::invalid_argument("tritri::for_each_candidate_pair: keys must be empty or have one entry per triangle");
  std::vector<int> degree(V.size(), 0);
  for (const auto& t : F)
    for (int v : t) ++degree[static_cast<std::size_t>(v)];
  std::vector<std::int64_t> groups;
  std::vector<int> hub_of(F.size(), -1);
  for (std::size_t t = 0; t < F.size(); ++t) {
    if (!group.empty() && group[t] >= 0) continue;
    for (int v : F[t]) {
      const int h = hub_of[t];
      if (degree[v] >= kHubDegree && (h < 0 || degree[v] > degree[h] || (degree[v] == degree[h] && v < h)))
        hub_of[t] = v;
    }
  }
  // Stars pay for their group search only when their own pairs would be many: more than
  // the triangles (a fan), not a few CAD vertices of degree 40 among 10^4 triangles.
  std::vector<std::size_t> star_size(V.size(), 0);
  for (int h : hub_of)
    if (h >= 0) ++star_size[static_cast<std::size_t>(h)];
  double star_pairs = 0;
  for (std::size_t s : star_size) star_pairs += 0.5 * static_cast<double>(s) * static_cast<double>(s);
  if (!(star_pairs > static_cast<double>(F.size()))) {
    for_each_overlapping_pair(V, F, threads, group, visit, keys);
    return;
  }
  // The caller's group ids renumbered 0 .. G - 1, stars G + hub: no id can collide or
  // overflow, whatever the caller's ids.
  std::vector<std::int64_t> ids;
  for (std::int64_t id : group)
    if (id >= 0) ids.push_back(id);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  const auto stars_from = static_cast<std::int64_t>(ids.size());
  groups.assign(F.size(), -1);
  for (std::size_t t = 0; t < F.size(); ++t) {
    if (hub_of[t] >= 0)
      groups[t] = stars_from + hub_of[t];
    else if (!group.empty() && group[t] >= 0)
      groups[t] = std::lower_bound(ids.begin(), ids.end(), group[t]) - ids.begin();
  }
  // (No keys here: the search with groups does not use them, see box_pairs.h.)
  for_each_overlapping_pair(V, F, threads, groups, visit);
  // Within each star: overlapping arc boxes. Stars in hub order (deterministic).
  std::vector<std::pair<int, int>> members;  // (hub, triangle)
  for (std::size_t t = 0; t < F.size(); ++t)
    if (hub_of[t] >= 0) members.emplace_back(hub_of[t], static_cast<int>(t));
  std::sort(members.begin(), members.end());
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    std::vector<Box> arcs;
    for (std::size_t s = 0; s < members.size();) {
      std::size_t e = s;
      const int v = members[s].first;
      arcs.clear();
      for (; e < members.size() && members[e].first == v; ++e) {
        const auto& t = F[members[e].second];
        const int k = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
        arcs.emplace_back(arc_box(V[v], V[t[(k + 1) % 3]], V[t[(k + 2) % 3]]), members[e].second);
      }
      detail::box_pairs::visit_overlapping_pairs(arcs, arena.max_concurrency(), visit, keys);
      s = e;
    }
  });
}

}  // namespace tritri
