// Stage 4: bounding-box candidate pairs (see candidate_pairs.h).
#include "stages/2_candidate_pairs.h"

#include <CGAL/Bbox_3.h>
#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/box_intersection_d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>

#include <algorithm>
// Boost 1.81's R-tree includes a header Boost itself has deprecated: not ours to fix.
#define BOOST_ALLOW_DEPRECATED_HEADERS
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "arrangements/thread_count.h"

namespace arrangements {
namespace {

// ID_EXPLICIT numbers boxes from a global counter (CGAL tells boxes apart by it); the
// triangle index travels as the box's info.
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int, CGAL::Box_intersection_d::ID_EXPLICIT>;
using Pairs = std::vector<std::pair<int, int>>;

std::vector<Box> triangle_boxes(const std::vector<Vec3>& V, const std::vector<Tri>& F) {
  std::vector<Box> boxes;
  boxes.reserve(F.size());
  const long long nv = static_cast<long long>(V.size());
  for (std::size_t t = 0; t < F.size(); ++t) {
    double lo[3], hi[3];
    for (int axis = 0; axis < 3; ++axis) lo[axis] = hi[axis] = 0;
    for (int i = 0; i < 3; ++i) {
      const int v = F[t][i];
      if (v < 0 || v >= nv)
        throw std::invalid_argument("candidate_pairs: triangle " + std::to_string(t) + " has vertex index " +
                                    std::to_string(v) + " out of range");
      for (int axis = 0; axis < 3; ++axis) {
        const double c = V[v][axis];
        if (!std::isfinite(c))
          throw std::invalid_argument("candidate_pairs: vertex " + std::to_string(v) + " is not finite");
        lo[axis] = i == 0 ? c : std::min(lo[axis], c);
        hi[axis] = i == 0 ? c : std::max(hi[axis], c);
      }
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
Pairs overlapping_pairs(std::vector<Box>& boxes, int workers) {
  tbb::enumerable_thread_specific<Pairs> found;  // the callback runs on several threads
  auto report = [&found](const Box& a, const Box& b) {
    const int i = a.info(), j = b.info();
    if (i != j) found.local().emplace_back(std::min(i, j), std::max(i, j));
  };
  const CGAL::Box_intersection_d::Box_traits_d<Box> traits;
  constexpr std::ptrdiff_t cutoff = 10;  // CGAL's default: below it, boxes are compared pairwise
  constexpr auto closed = CGAL::Box_intersection_d::CLOSED;
  constexpr std::size_t kMinChunk = 2048;  // below this, splitting costs more than it saves
  const std::size_t chunks = std::min<std::size_t>(4 * static_cast<std::size_t>(workers), boxes.size() / kMinChunk);
  if (workers <= 1 || chunks <= 1) {
    CGAL::box_self_intersection_d<CGAL::Sequential_tag>(boxes.begin(), boxes.end(), report, traits, cutoff, closed);
  } else {
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
  Pairs all;
  std::size_t n = 0;
  for (const Pairs& p : found) n += p.size();
  all.reserve(n);
  for (const Pairs& p : found) all.insert(all.end(), p.begin(), p.end());
  tbb::parallel_sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using RPoint = bg::model::point<double, 3, bg::cs::cartesian>;
using RBox = bg::model::box<RPoint>;
using RTree = bgi::rtree<std::pair<RBox, int>, bgi::quadratic<16>>;

RBox rbox(const Box& b) {
  return {RPoint(b.min_coord(0), b.min_coord(1), b.min_coord(2)), RPoint(b.max_coord(0), b.max_coord(1), b.max_coord(2))};
}

// With polygon faces: a face's triangles never pair with each other, and a big face can
// give up to n^2 / 2 overlapping boxes (its triangles may all share a corner), so they are
// never enumerated. Each face is one box (the union of its triangles') in the box search,
// beside the other triangles; a pair of items that involves a face is expanded by querying
// the face's R-tree of triangle boxes (closed boxes: touching counts, as above) with the
// other item's triangle boxes.
Pairs overlapping_pairs_with_faces(const std::vector<Box>& boxes, std::span<const std::int64_t> polygon, int workers) {
  std::map<std::int64_t, std::vector<int>> faces_by_id;  // deterministic face order
  std::vector<std::vector<int>> items;                   // triangles of each item
  for (std::size_t t = 0; t < boxes.size(); ++t) {
    if (polygon[t] >= 0)
      faces_by_id[polygon[t]].push_back(static_cast<int>(t));
    else
      items.push_back({static_cast<int>(t)});
  }
  const std::size_t first_face = items.size();  // items from here on are faces
  for (auto& [id, triangles] : faces_by_id) items.push_back(std::move(triangles));
  std::vector<Box> item_boxes;
  item_boxes.reserve(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) {
    CGAL::Bbox_3 b = boxes[items[i][0]].bbox();
    for (int t : items[i]) b += boxes[t].bbox();
    item_boxes.emplace_back(b, static_cast<int>(i));
  }
  std::vector<RTree> trees(items.size() - first_face);  // one per face
  tbb::parallel_for(first_face, items.size(), [&](std::size_t i) {
    std::vector<std::pair<RBox, int>> values;
    values.reserve(items[i].size());
    for (int t : items[i]) values.emplace_back(rbox(boxes[t]), t);
    trees[i - first_face] = RTree(values.begin(), values.end());  // bulk loading (packing)
  });
  const Pairs item_pairs = overlapping_pairs(item_boxes, workers);
  tbb::enumerable_thread_specific<Pairs> found;
  tbb::parallel_for(std::size_t(0), item_pairs.size(), [&](std::size_t k) {
    int a = item_pairs[k].first, b = item_pairs[k].second;
    if (items[a].size() > items[b].size()) std::swap(a, b);  // query the larger one
    Pairs& out = found.local();
    if (items[b].size() == 1) {
      out.emplace_back(std::min(items[a][0], items[b][0]), std::max(items[a][0], items[b][0]));
      return;
    }
    const RTree& tree = trees[b - first_face];  // b has two triangles or more: a face
    for (int t : items[a])
      for (auto it = tree.qbegin(bgi::intersects(rbox(boxes[t]))); it != tree.qend(); ++it)
        out.emplace_back(std::min(t, it->second), std::max(t, it->second));
  });
  Pairs all;
  for (const Pairs& p : found) all.insert(all.end(), p.begin(), p.end());
  tbb::parallel_sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

}  // namespace

std::vector<std::pair<int, int>> candidate_pairs(const std::vector<Vec3>& V, const std::vector<Tri>& F,
                                                 int threads, std::span<const std::int64_t> polygon) {
  if (threads > kMaxThreads)
    throw std::invalid_argument("candidate_pairs: threads must be at most " + std::to_string(kMaxThreads));
  if (!polygon.empty() && polygon.size() != F.size())
    throw std::invalid_argument("candidate_pairs: polygon must be empty or have one entry per triangle");
  std::vector<Box> boxes = triangle_boxes(V, F);
  if (boxes.size() < 2) return {};
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  Pairs pairs;
  const bool faces = std::any_of(polygon.begin(), polygon.end(), [](std::int64_t id) { return id >= 0; });
  arena.execute([&] {
    pairs = faces ? overlapping_pairs_with_faces(boxes, polygon, arena.max_concurrency())
                  : overlapping_pairs(boxes, arena.max_concurrency());
  });
  return pairs;
}

}  // namespace arrangements
