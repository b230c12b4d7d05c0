// Stage 6, first half: sides of output triangles grouped into cells around every edge
// (see 6_side_cells.h).
#include "stages/6_side_cells.h"

#include <tbb/blocked_range.h>
#include <tbb/concurrent_vector.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "arrangements/boolean.h"
#include "arrangements/memory_budget.h"
#include "booleans/fan_order.h"
#include "booleans/point_orient.h"
#include "models/double_model.h"
#include "models/exact_model.h"
#include "support/union_find.h"

namespace arrangements {
namespace {

std::string point_text(const Vec3& p) {
  char buf[120];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g, %.17g)", p[0], p[1], p[2]);
  return buf;
}

// One triangle's use of an edge of the arrangement, with what the edge's fan needs of it
// (gathered in one pass over the triangles: the fans then read one contiguous array instead
// of the triangles, their corners and jumps at random).
struct HalfEdge {
  std::uint64_t key;      // the undirected edge a * nV + b, a < b
  int edge_slot;          // 3 f + k: triangle f's edge from corner k to corner k + 1
  std::uint32_t packed;   // bit 0: runs a -> b; bits 1-8: its one jump signed by that
                          // direction, plus 128 (0: none, several, an operand >= 2^23 or a
                          // jump beyond +-127: see deltas); bits 9-31: its operand
};

constexpr std::uint32_t kForward = 1;
constexpr int kJumpShift = 1, kOperandShift = 9;

std::uint32_t packed_jump(const OperandWeights& deltas, std::size_t f, bool forward) {
  const auto *p = deltas.row_begin(f), *pe = deltas.row_end(f);
  const std::uint32_t dir = forward ? kForward : 0;
  if (pe - p != 1 || p->first < 0 || p->first >= (1 << (32 - kOperandShift)) || p->second < -127 || p->second > 127)
    return dir;
  const int signed_jump = forward ? p->second : -p->second;
  return dir | static_cast<std::uint32_t>(signed_jump + 128) << kJumpShift |
         static_cast<std::uint32_t>(p->first) << kOperandShift;
}

// Whether two packed jumps cancel (one operand, opposite signed jumps); nullopt when either
// is not packed.
std::optional<bool> packed_jumps_cancel(std::uint32_t x, std::uint32_t y) {
  const std::uint32_t jx = (x >> kJumpShift) & 0xff, jy = (y >> kJumpShift) & 0xff;
  if (jx == 0 || jy == 0) return std::nullopt;
  return (x >> kOperandShift) == (y >> kOperandShift) && jx + jy == 256;
}

// Half-edges in (key, edge_slot) order, with the start of each run of one key (one edge's fan)
// and the end. A counting sort by the smaller endpoint, then each vertex's few half-edges
// sorted: the order one global sort gives, in linear time (the global sort was a quarter
// of this stage).
struct EdgeFans {
  std::vector<HalfEdge> half;
  std::vector<std::size_t> run_start;
};

EdgeFans edge_fans(const std::vector<Tri>& triangles, std::uint64_t nV, const OperandWeights& deltas) {
  EdgeFans out;
  std::vector<std::size_t> bucket(nV + 1, 0);
  for (const Tri& t : triangles)
    for (int k = 0; k < 3; ++k) ++bucket[static_cast<std::size_t>(std::min(t[k], t[(k + 1) % 3])) + 1];
  for (std::size_t v = 0; v < nV; ++v) bucket[v + 1] += bucket[v];
  out.half.resize(3 * triangles.size());
  {
    std::vector<std::size_t> next(bucket.begin(), bucket.end() - 1);
    for (std::size_t f = 0; f < triangles.size(); ++f) {
      detail::memory_checkpoint();
      const Tri& t = triangles[f];
      for (int k = 0; k < 3; ++k) {
        const std::uint64_t a = t[k], b = t[(k + 1) % 3];
        out.half[next[std::min(a, b)]++] = {std::min(a, b) * nV + std::max(a, b), static_cast<int>(3 * f + k),
                                            packed_jump(deltas, f, a < b)};
      }
    }
  }
  auto before = [](const HalfEdge& x, const HalfEdge& y) {
    return x.key != y.key ? x.key < y.key : x.edge_slot < y.edge_slot;
  };
  tbb::parallel_for(std::size_t{0}, static_cast<std::size_t>(nV), [&](std::size_t v) {
    std::sort(out.half.begin() + static_cast<std::ptrdiff_t>(bucket[v]),
              out.half.begin() + static_cast<std::ptrdiff_t>(bucket[v + 1]), before);
  });
  for (std::size_t i = 0; i < out.half.size(); ++i)
    if (i == 0 || out.half[i].key != out.half[i - 1].key) out.run_start.push_back(i);
  out.run_start.push_back(out.half.size());
  return out;
}

// Whether the jumps of triangles f and g cancel around an edge that both run the same way
// (same_way) or opposite ways: rows are sorted by operand, without zeros.
bool jumps_cancel(const OperandWeights& deltas, int f, int g, bool same_way) {
  const auto *p = deltas.row_begin(f), *pe = deltas.row_end(f), *q = deltas.row_begin(g);
  if (pe - p != deltas.row_end(g) - q) return false;
  for (; p != pe; ++p, ++q)
    if (p->first != q->first || p->second != (same_way ? -q->second : q->second)) return false;
  return true;
}

}  // namespace

template <class M>
SideCells side_cells(const BasicOutputMesh<typename M::Point>& mesh, const OperandWeights& deltas,
                     const BasicTriangleSoup<typename M::Vertex>& soup, const std::vector<int>& emitted_by,
                     int scale_exponent) {
  using Point = typename M::Point;
  // The corners of soup triangle t's plane, in the mesh's frame (exact: see M::unscaled).
  auto corner = [&](int t, int k) {
    const Point p = M::explicit_point(soup.vertices[soup.triangles[t][k]]);
    return scale_exponent == 0 ? p : M::unscaled(p, scale_exponent);
  };
  const std::size_t nT = mesh.triangles.size();
  const std::uint64_t nV = mesh.vertices.size();
  EdgeFans fans = edge_fans(mesh.triangles, nV, deltas);
  const auto& half = fans.half;
  const auto& run_start = fans.run_start;
  const std::size_t runs = run_start.size() - 1;

  // Per run: the balance check, then one pair of sides to unite per wedge.
  std::vector<std::pair<int, int>> unite(half.size());
  tbb::concurrent_vector<std::pair<std::size_t, int>> unbalanced;  // (run, operand)
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, runs), [&](const tbb::blocked_range<std::size_t>& range) {
    detail::memory_checkpoint();
    std::vector<std::pair<int, int>> sum;  // reused by the runs of this range
    std::vector<int> order;
    std::vector<const Point*> third;
    std::vector<char> opposite;
    std::vector<std::array<Point, 3>> plane;  // per item, the corners of its emitting plane
    for (std::size_t r = range.begin(); r != range.end(); ++r) {
      const std::size_t s = run_start[r], e = run_start[r + 1];
      auto face = [&](std::size_t i) { return half[i].edge_slot / 3; };
      // Whether the triangle runs a -> b along the edge (a the smaller endpoint).
      auto forward = [&](std::size_t i) { return (half[i].packed & kForward) != 0; };
      // The wedge after triangle j (by angle) is faced by j's side towards increasing angle
      // (front if it runs a -> b) and by the next triangle's side towards decreasing angle.
      auto unite_wedge = [&](std::size_t slot, std::size_t x, std::size_t y) {
        unite[slot] = {2 * face(x) + (forward(x) ? 0 : 1), 2 * face(y) + (forward(y) ? 1 : 0)};
      };
      // Most edges have two triangles (inside a cut triangle or a clean surface): no sums to
      // sort, no order to find.
      if (e - s == 2) {
        const std::optional<bool> packed = packed_jumps_cancel(half[s].packed, half[s + 1].packed);
        if (packed ? *packed : jumps_cancel(deltas, face(s), face(s + 1), forward(s) == forward(s + 1))) {
          unite_wedge(s, s, s + 1);
          unite_wedge(s + 1, s + 1, s);
          continue;
        }
      }
      sum.clear();
      for (std::size_t i = s; i < e; ++i)
        for (auto it = deltas.row_begin(face(i)); it != deltas.row_end(face(i)); ++it)
          sum.emplace_back(it->first, forward(i) ? it->second : -it->second);
      std::sort(sum.begin(), sum.end());
      for (std::size_t i = 0; i < sum.size();) {
        std::size_t j = i;
        int total = 0;
        for (; j < sum.size() && sum[j].first == sum[i].first; ++j) total += sum[j].second;
        if (total != 0) unbalanced.push_back({r, sum[i].first});
        i = j;
      }
      order.resize(e - s);
      for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
      if (order.size() > 2) {
        third.resize(order.size());
        plane.resize(order.size());
        for (std::size_t i = 0; i < order.size(); ++i) {
          const Tri& t = mesh.triangles[face(s + i)];
          const int k = half[s + i].edge_slot % 3;
          third[i] = &mesh.vertices[t[(k + 2) % 3]];
          const int emitter = emitted_by[face(s + i)];
          plane[i] = {corner(emitter, 0), corner(emitter, 1), corner(emitter, 2)};
        }
        // Pieces of the reference's own input triangle lie in its plane, across the edge.
        opposite.assign(order.size(), 0);
        for (std::size_t i = 1; i < order.size(); ++i)
          opposite[i] = mesh.source[face(s + i)] == mesh.source[face(s)];
        // orient3d(a, b, third x, third y): the plane through a, b and x's third corner is
        // the plane of the soup triangle that emitted x, whose orientation x keeps (the
        // same normal when x runs a -> b, else the opposite). Three explicit corners: far
        // cheaper than orient3d on the implicit a, b and x's corner (degree 6 against up
        // to 15; this was most of the stage on meshes with many crossings).
        auto side = [&](int x, int y) {
          const tritri::Sign sign = orient3d_points(plane[x][0], plane[x][1], plane[x][2], *third[y]);
          return forward(s + x) ? sign : -sign;
        };
        order_around_axis(order, 0, side, &opposite);
      }
      for (std::size_t j = 0; j < order.size(); ++j)
        unite_wedge(s + j, s + order[j], s + order[(j + 1) % order.size()]);
    }
  });
  if (!unbalanced.empty()) {
    std::vector<std::pair<std::size_t, int>> u(unbalanced.begin(), unbalanced.end());
    std::sort(u.begin(), u.end(), [](const auto& x, const auto& y) {
      return x.second != y.second ? x.second < y.second : x.first < y.first;
    });
    std::size_t count = 0;
    for (const auto& x : u) count += x.second == u[0].second;
    const std::uint64_t key = half[run_start[u[0].first]].key;
    const std::string edge = point_text(M::to_double(mesh.vertices[key / nV])) + " - " +
                             point_text(M::to_double(mesh.vertices[key % nV]));
    OpenOperandError error("operand " + std::to_string(u[0].second) + " is not closed: " + std::to_string(count) +
                           " edge" + (count == 1 ? "" : "s") +
                           " of the arrangement where its triangles do not balance (open, or inconsistently "
                           "oriented); the first: " + edge);
    error.operand = u[0].second;
    error.open_edges = count;
    throw error;
  }
  fans = {};
  UnionFind sets(2 * nT);
  for (const auto& [x, y] : unite) sets.unite(x, y);
  SideCells out;
  out.cell.assign(2 * nT, -1);
  std::vector<int> cell_of_root(2 * nT, -1);
  for (std::size_t side = 0; side < 2 * nT; ++side) {
    int& c = cell_of_root[sets.find(static_cast<int>(side))];
    if (c < 0) c = out.cells++;
    out.cell[side] = c;
  }
  return out;
}

template SideCells side_cells<DoubleModel>(const OutputMesh&, const OperandWeights&, const TriangleSoup&,
                                           const std::vector<int>&, int);
template SideCells side_cells<ExactModel>(const BasicOutputMesh<ExactModel::Point>&, const OperandWeights&,
                                          const BasicTriangleSoup<ExactModel::Vertex>&, const std::vector<int>&,
                                          int);

}  // namespace arrangements
