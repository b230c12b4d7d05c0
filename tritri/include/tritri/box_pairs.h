// tritri/box_pairs.h
//
// overlapping_triangle_pairs(V, F, threads = 0, group = {}): the candidate pairs of a
// triangle mesh or soup, the first step of every mesh-level use of tritri::classify (the
// batch API self_intersections / intersections, and the arrangement pipeline's detection
// stage).
//   V        vertex coordinates (finite)
//   F        triangles, indices into V (in range)
//   threads  worker threads; <= 0: all cores (runs inside its own tbb::task_arena, so the
//            rest of the program keeps its own parallelism)
//   group    #F or empty: triangles with the same id >= 0 are never paired (the triangles
//            of one polygon face, known to meet only in shared corners and edges; or all
//            triangles of one mesh, when only pairs between two meshes are wanted); -1: none
// returns every pair (i, j), i < j, of triangles whose closed axis-aligned bounding boxes
// overlap (boxes that only touch count), except pairs within one group, sorted
// lexicographically, each once. The result does not depend on `threads`.
// Preconditions: finite coordinates, indices in range (the callers check them once, at
// their boundary: tritri::detail::checked_vertices / checked_triangles, the pipeline's
// input validation).
// Exactness: the boxes are the exact minima and maxima of the corners' coordinates, so no
// pair that touches is missed.
// Method: a hierarchy of uniform grids (tritri/detail/box_grid.h) unless its cells would be
// crowded; otherwise CGAL's box_intersection_d segment tree (closed boxes). In parallel the boxes are
// sorted by xmin and cut into chunks, one task per chunk; below ~4000 triangles, or with
// one thread, one sequential call. Groups are single boxes in that search, expanded
// through a Boost.Geometry R-tree of their triangles' boxes.
// Cost: O(n log^3 n + k) expected for n triangles and k pairs; memory about 3 copies of 64
// bytes per triangle, plus the pairs.
#pragma once

#include <CGAL/Bbox_3.h>
#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/box_intersection_d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "tritri/detail/box_grid.h"
// Boost 1.81's R-tree includes a header Boost itself has deprecated: not ours to fix.
#ifndef BOOST_ALLOW_DEPRECATED_HEADERS
#define BOOST_ALLOW_DEPRECATED_HEADERS
#endif
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/index/rtree.hpp>

namespace tritri {
namespace detail::box_pairs {

// ID_EXPLICIT numbers boxes from a global counter (CGAL tells boxes apart by it); the
// triangle index travels as the box's info.
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int, CGAL::Box_intersection_d::ID_EXPLICIT>;
using Pairs = std::vector<std::pair<int, int>>;

// Vlo, Vhi: each vertex's box (the same span for points with double coordinates).
inline std::vector<Box> triangle_boxes(std::span<const std::array<double, 3>> Vlo,
                                       std::span<const std::array<double, 3>> Vhi,
                                       std::span<const std::array<int, 3>> F) {
  std::vector<Box> boxes;
  boxes.reserve(F.size());
  for (std::size_t t = 0; t < F.size(); ++t) {
    double lo[3], hi[3];
    for (int axis = 0; axis < 3; ++axis) {
      lo[axis] = std::min({Vlo[F[t][0]][axis], Vlo[F[t][1]][axis], Vlo[F[t][2]][axis]});
      hi[axis] = std::max({Vhi[F[t][0]][axis], Vhi[F[t][1]][axis], Vhi[F[t][2]][axis]});
    }
    boxes.emplace_back(CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]), static_cast<int>(t));
  }
  return boxes;
}

// Sequential: CGAL's segment tree on all boxes. Parallel: the boxes sorted by xmin are cut
// into chunks; task j finds the pairs inside chunk j and the pairs between chunk j and the
// earlier boxes whose x-extent reaches its first xmin (no other earlier box can meet it),
// so each pair is found by exactly one task. (CGAL's own Parallel_tag splits both ranges
// into 4 x 4 copies; measured on 2 cores it did twice the work of the sequential call.)
// keys: as for_each_overlapping_pair (used by the grid only).
template <class Visit>
void visit_overlapping_pairs(std::vector<Box>& boxes, int workers, const Visit& visit,
                             std::span<const std::array<int, 3>> keys = {}) {
  auto report = [&visit](const Box& a, const Box& b) {
    const int i = a.info(), j = b.info();
    if (i != j) visit(std::min(i, j), std::max(i, j));
  };
  const CGAL::Box_intersection_d::Box_traits_d<Box> traits;
  constexpr std::ptrdiff_t cutoff = 10;  // CGAL's default: below it, boxes are compared pairwise
  constexpr auto closed = CGAL::Box_intersection_d::CLOSED;
  constexpr std::size_t kMinChunk = 2048;         // below this, splitting costs more than it saves
  if (visit_pairs_in_grid(boxes, visit, keys)) return;  // the grid hierarchy when that is cheap
  const std::size_t chunks = std::min<std::size_t>(4 * static_cast<std::size_t>(workers), boxes.size() / kMinChunk);
  if (workers <= 1 || chunks <= 1) {
    CGAL::box_self_intersection_d<CGAL::Sequential_tag>(boxes.begin(), boxes.end(), report, traits, cutoff, closed);
    return;
  }
  tbb::parallel_sort(boxes.begin(), boxes.end(),
                     [](const Box& a, const Box& b) { return a.min_coord(0) < b.min_coord(0); });
  auto first_of = [&](std::size_t chunk) { return chunk * boxes.size() / chunks; };
  // Chunk j reports the pairs whose later box (in x order) lies in it: one complete
  // self-intersection search over its boxes plus the earlier boxes that reach into it,
  // keeping pairs with a box of the chunk. (CGAL's bipartite mode loses pairs of closed
  // boxes that only touch, so it is not used.)
  tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t j) {
    const double start = boxes[first_of(j)].min_coord(0);
    std::vector<Box> local;
    for (std::size_t i = 0; i < first_of(j); ++i)
      if (boxes[i].max_coord(0) >= start) local.push_back(boxes[i]);
    const std::size_t reaching = local.size();
    std::vector<char> in_chunk(boxes.size(), 0);  // by triangle index
    local.insert(local.end(), boxes.begin() + first_of(j), boxes.begin() + first_of(j + 1));
    for (std::size_t i = reaching; i < local.size(); ++i) in_chunk[local[i].info()] = 1;
    auto report_chunk = [&](const Box& a, const Box& b) {
      if (in_chunk[a.info()] || in_chunk[b.info()]) report(a, b);
    };
    CGAL::box_self_intersection_d<CGAL::Sequential_tag>(local.begin(), local.end(), report_chunk, traits, cutoff,
                                                        closed);
  });
}

// Sorts the pairs the workers found and drops repeats.
template <class PerThreadPairs>  // a tbb::enumerable_thread_specific of Pairs
Pairs sorted_unique(PerThreadPairs& found) {
  Pairs all;
  std::size_t n = 0;
  for (const Pairs& p : found) n += p.size();
  all.reserve(n);
  for (const Pairs& p : found) all.insert(all.end(), p.begin(), p.end());
  tbb::parallel_sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

inline Pairs overlapping_pairs(std::vector<Box>& boxes, int workers) {
  tbb::enumerable_thread_specific<Pairs> found;  // the visitor runs on several threads
  visit_overlapping_pairs(boxes, workers, [&found](int i, int j) { found.local().emplace_back(i, j); });
  return sorted_unique(found);
}

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using RPoint = bg::model::point<double, 3, bg::cs::cartesian>;
using RBox = bg::model::box<RPoint>;
using RTree = bgi::rtree<std::pair<RBox, int>, bgi::quadratic<16>>;

inline RBox rbox(const Box& b) {
  return {RPoint(b.min_coord(0), b.min_coord(1), b.min_coord(2)),
          RPoint(b.max_coord(0), b.max_coord(1), b.max_coord(2))};
}

// With groups: a group's triangles never pair with each other, and a big group (a polygon
// face, a whole mesh) can give up to n^2 / 2 overlapping boxes, so they are never
// enumerated. Each group is one box (the union of its triangles') in the box search,
// beside the other triangles; a pair of items that involves a group is expanded by
// querying the group's R-tree of triangle boxes (closed boxes: touching counts, as above)
// with the other item's triangle boxes.
template <class Visit>
void visit_overlapping_pairs_with_groups(const std::vector<Box>& boxes, std::span<const std::int64_t> group,
                                         int workers, const Visit& visit) {
  // Items in one flat list (no allocation per triangle): the ungrouped triangles, one item
  // each, then the groups in id order (deterministic), each its triangles in index order.
  // Item i holds member[first[i] .. first[i + 1]).
  std::vector<std::pair<std::int64_t, int>> grouped;  // (group id, triangle)
  std::vector<int> member;
  member.reserve(boxes.size());
  for (std::size_t t = 0; t < boxes.size(); ++t) {
    if (group[t] >= 0)
      grouped.emplace_back(group[t], static_cast<int>(t));
    else
      member.push_back(static_cast<int>(t));
  }
  const std::size_t first_face = member.size();  // items from here on are groups
  std::vector<std::size_t> first(first_face + 1);
  std::iota(first.begin(), first.end(), std::size_t{0});
  std::sort(grouped.begin(), grouped.end());
  for (std::size_t k = 0; k < grouped.size(); ++k) {
    if (k > 0 && grouped[k].first != grouped[k - 1].first) first.push_back(member.size());
    member.push_back(grouped[k].second);
  }
  if (!grouped.empty()) first.push_back(member.size());
  const std::size_t items = first.size() - 1;
  auto size = [&](std::size_t i) { return first[i + 1] - first[i]; };
  std::vector<Box> item_boxes;
  item_boxes.reserve(items);
  for (std::size_t i = 0; i < items; ++i) {
    CGAL::Bbox_3 b = boxes[member[first[i]]].bbox();
    for (std::size_t k = first[i]; k < first[i + 1]; ++k) b += boxes[member[k]].bbox();
    item_boxes.emplace_back(b, static_cast<int>(i));
  }
  std::vector<RTree> trees(items - first_face);  // one per group
  tbb::parallel_for(first_face, items, [&](std::size_t i) {
    std::vector<std::pair<RBox, int>> values;
    values.reserve(size(i));
    for (std::size_t k = first[i]; k < first[i + 1]; ++k) values.emplace_back(rbox(boxes[member[k]]), member[k]);
    trees[i - first_face] = RTree(values.begin(), values.end());  // bulk loading (packing)
  });
  // Each triangle is in one item and item pairs are visited once, so each triangle pair is
  // visited once; the item pairs are never stored (memory independent of their count).
  visit_overlapping_pairs(item_boxes, workers, [&](int a, int b) {
    if (size(a) > size(b)) std::swap(a, b);  // query the larger one
    if (size(b) == 1) {
      const int i = member[first[a]], j = member[first[b]];
      visit(std::min(i, j), std::max(i, j));
      return;
    }
    const RTree& tree = trees[b - first_face];  // b has two triangles or more: a group
    for (std::size_t k = first[a]; k < first[a + 1]; ++k) {
      const int t = member[k];
      for (auto it = tree.qbegin(bgi::intersects(rbox(boxes[t]))); it != tree.qend(); ++it)
        visit(std::min(t, it->second), std::max(t, it->second));
    }
  });
}

}  // namespace detail::box_pairs

// for_each_overlapping_pair(V, F, threads, group, visit, keys = {}): the same search without
// the list: visit(i, j) (i < j, const, callable from several threads at once) is called once
// for every pair that overlapping_triangle_pairs would return, in no particular order.
// For callers that filter or classify pairs as they are found, so that millions of
// candidate pairs are never stored. Same preconditions, exactness and search cost.
// keys: empty, or three ints per triangle: a hint that pairs whose keys share a value need
// no visit (e.g. tritri::embedded_corner_keys: triangles meeting at an embedded vertex). The
// grid skips them in its cells, where it holds the keys beside the boxes, so on a clean
// mesh, where such pairs are nearly all box pairs, they cost no visit; the other searches
// (the segment tree of crowded inputs, the groups) visit them, as a lookup per pair would
// cost more there than it saves. So visit still sees some of them and must settle them.
// With Vlo, Vhi in place of V: vertices known only to lie in a box each (points with
// rational coordinates and their certified intervals); pairs of triangles whose boxes
// (of their corners' boxes) overlap.
template <class Visit>
void for_each_overlapping_pair(std::span<const std::array<double, 3>> Vlo, std::span<const std::array<double, 3>> Vhi,
                               std::span<const std::array<int, 3>> F, int threads,
                               std::span<const std::int64_t> group, const Visit& visit,
                               std::span<const std::array<int, 3>> keys = {}) {
  using namespace detail::box_pairs;
  if (!group.empty() && group.size() != F.size())
    throw std::invalid_argument(
        "tritri::overlapping_triangle_pairs: group must be empty or have one entry per triangle");
  if (!keys.empty() && keys.size() != F.size())
    throw std::invalid_argument("tritri::for_each_overlapping_pair: keys must be empty or have one entry per triangle");
  if (F.size() < 2) return;
  std::vector<Box> boxes = triangle_boxes(Vlo, Vhi, F);
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  const bool groups = std::any_of(group.begin(), group.end(), [](std::int64_t id) { return id >= 0; });
  arena.execute([&] {
    if (groups)
      visit_overlapping_pairs_with_groups(boxes, group, arena.max_concurrency(), visit);
    else
      visit_overlapping_pairs(boxes, arena.max_concurrency(), visit, keys);
  });
}

template <class Visit>
void for_each_overlapping_pair(std::span<const std::array<double, 3>> V, std::span<const std::array<int, 3>> F,
                               int threads, std::span<const std::int64_t> group, const Visit& visit,
                               std::span<const std::array<int, 3>> keys = {}) {
  for_each_overlapping_pair(V, V, F, threads, group, visit, keys);
}

// The same with a box per vertex (Vlo, Vhi: lower and upper bounds of each coordinate, e.g.
// of a rational one).
inline std::vector<std::pair<int, int>> overlapping_triangle_pairs(std::span<const std::array<double, 3>> Vlo,
                                                                   std::span<const std::array<double, 3>> Vhi,
                                                                   std::span<const std::array<int, 3>> F,
                                                                   int threads = 0,
                                                                   std::span<const std::int64_t> group = {}) {
  tbb::enumerable_thread_specific<detail::box_pairs::Pairs> found;  // visit runs on several threads
  for_each_overlapping_pair(Vlo, Vhi, F, threads, group,
                            [&found](int i, int j) { found.local().emplace_back(i, j); });
  return detail::box_pairs::sorted_unique(found);
}

inline std::vector<std::pair<int, int>> overlapping_triangle_pairs(std::span<const std::array<double, 3>> V,
                                                                   std::span<const std::array<int, 3>> F,
                                                                   int threads = 0,
                                                                   std::span<const std::int64_t> group = {}) {
  return overlapping_triangle_pairs(V, V, F, threads, group);
}

}  // namespace tritri
