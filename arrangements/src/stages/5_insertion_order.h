// arrangements/src/stages/5_insertion_order.h (internal to stage 5)
//
// The orders in which stage 5 inserts points and constraints into a local triangulation,
// and the triangles around each of its vertices. None is a predicate: any order is
// correct, these are fast and deterministic.
//
// spatial_order<M>(lt, ids, plane): the local vertices `ids` of a local triangulation in
// the order of a Morton curve over their boxes' centres in the projection `plane`, ties
// by local id (deterministic). Inserted in this order, each visibility walk starts near
// its point instead of crossing the triangulation (100 coplanar wedges: most orient2d
// calls were the walks' before). Cost: O(n log n) for n ids.
// shuffled_order(n): 0 .. n-1 shuffled by a fixed-seed xorshift (Fisher-Yates): the
// constraints' order, a randomized incremental construction that is deterministic.
// triangles_around(lt): the local triangles at each vertex as CSR (first[v] .. first[v+1]
// in around), for seeds of floods.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "stages/5_local_triangulation.h"

namespace arrangements::local {

template <class M>
std::vector<int> spatial_order(const LocalTriangulation<M>& lt, std::vector<int> ids, tritri::Plane plane) {
  if (ids.empty()) return ids;
  const auto [i, j] = tritri::plane_axes(plane);
  std::vector<std::array<double, 2>> centre;
  centre.reserve(ids.size());
  for (const int l : ids) {
    const auto box = M::box(lt.pts[l]);
    auto mid = [](const tritri::XBounds& b) {
      const double m = 0.5 * b.lo + 0.5 * b.hi;
      return std::isfinite(m) ? m : 0.0;
    };
    centre.push_back({mid(box[i]), mid(box[j])});
  }
  std::array<double, 2> lo = centre[0], hi = centre[0];
  for (const auto& c : centre)
    for (int a = 0; a < 2; ++a) {
      lo[a] = std::min(lo[a], c[a]);
      hi[a] = std::max(hi[a], c[a]);
    }
  auto cell = [&](double x, int a) {  // 0 .. 2^21 - 1
    const double span = hi[a] - lo[a];
    const double f = span > 0 && std::isfinite(span) ? (x - lo[a]) / span : 0.0;
    return static_cast<std::uint64_t>(std::clamp(f, 0.0, 1.0) * 2097151.0);
  };
  auto spread = [](std::uint64_t v) {  // bit k of v to bit 2k
    std::uint64_t r = 0;
    for (int b = 0; b < 21; ++b) r |= ((v >> b) & 1u) << (2 * b);
    return r;
  };
  std::vector<std::pair<std::uint64_t, int>> keyed(ids.size());
  for (std::size_t k = 0; k < ids.size(); ++k)
    keyed[k] = {spread(cell(centre[k][0], 0)) | (spread(cell(centre[k][1], 1)) << 1), ids[k]};
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t k = 0; k < ids.size(); ++k) ids[k] = keyed[k].second;
  return ids;
}

inline std::vector<int> shuffled_order(std::size_t n) {
  std::vector<int> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<int>(i);
  std::uint64_t seed = 0x2545F4914F6CDD1Dull;
  for (std::size_t i = n; i > 1; --i) {
    seed ^= seed << 13;
    seed ^= seed >> 7;
    seed ^= seed << 17;
    std::swap(order[i - 1], order[seed % i]);
  }
  return order;
}

struct TrianglesAround {
  std::vector<int> first, around;
};

template <class M>
TrianglesAround triangles_around(const LocalTriangulation<M>& lt) {
  const std::size_t nv = lt.pts.size(), nt = lt.tris.size();
  TrianglesAround r{std::vector<int>(nv + 1, 0), std::vector<int>(3 * nt)};
  for (const LocalTriangle& T : lt.tris)
    for (int k = 0; k < 3; ++k) ++r.first[T.v[k] + 1];
  for (std::size_t v = 0; v < nv; ++v) r.first[v + 1] += r.first[v];
  std::vector<int> fill(r.first.begin(), r.first.end() - 1);
  for (std::size_t T = 0; T < nt; ++T)
    for (int k = 0; k < 3; ++k) r.around[fill[lt.tris[T].v[k]]++] = static_cast<int>(T);
  return r;
}

}  // namespace arrangements::local
