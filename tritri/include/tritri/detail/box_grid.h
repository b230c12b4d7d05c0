// tritri/detail/box_grid.h
//
// visit_pairs_in_grid(boxes, visit, keys = {}): every pair of overlapping closed boxes, found with a
// hierarchy of uniform grids instead of a segment tree, for inputs where that is cheap:
// meshes whose triangles are mostly of one size, with or without some long ones (scans,
// CAD). Returns false, having visited nothing, when cells would be crowded (many boxes
// overlapping one another); the caller then uses CGAL's box_intersection_d (box_pairs.h).
//
//   boxes  3D boxes with min_coord / max_coord / info() (the triangle index), finite
//   visit  visit(i, j), i < j triangle indices; called once per overlapping pair, from
//          several threads at once (oneTBB, the caller's arena)
//   keys   empty, or three ints per triangle index: pairs whose keys share a value are not
//          visited (a filter applied in the cells, where the keys are gathered with the
//          boxes: cheaper than a visit per pair when such pairs are most of them)
//
// Method: level 0 is a grid of cell size h, twice the median box extent (grown until it has
// at most ~8 cells per box); level l has cells of size h 2^l over the same origin. Each box
// lives on the first level where it meets at most 8 cells, and is listed in each of them
// (counting sort into one array per level). A pair on one level is tested in the cells
// they share; a pair on levels i < j is tested by the box of level i in the level-j cells
// it meets. Either way it is reported only by the level-j cell (j the higher of the two
// levels) that holds the minimum corner of the two boxes' intersection: each pair once,
// with no global list or sort. Long triangles thus sit on coarse levels instead of being
// listed in thousands of cells. Declines when the pairwise tests would exceed
// 40 n log2 n (about a segment tree's cost, measured).
// Speed: a box's level and cell range are found once; a cell's boxes are gathered into one
// array per coordinate and each is tested against the later ones without branches (a box
// test was a mispredicted branch per comparison); the coarser levels also keep contiguous
// copies of their boxes, which the finer boxes beneath them scan. On clean 70-120 k triangle
// meshes this made the search 11-27% faster, on EMBER 1063852+72214 40%.
// Exactness: overlap is decided by exact comparisons of the box coordinates (closed boxes:
// touching counts). Cell indices come from floor((x - origin) / h_l) clamped to the grid,
// evaluated in floating point; every step is monotone in x, so the minimum corner of the
// intersection of two boxes, which lies in both boxes, falls in a level-j cell that both
// boxes meet at level j.
// Cost: O(n L + S + T) for n boxes on L levels, S <= 8 n cell entries and T pair tests
// (at most 40 n log2 n, else the grid declines). Memory: 4 bytes per entry and per cell,
// 64 per entry above level 0, 25 per box; level 0 has at most 8 n + 64 cells, each further
// level about 8 times fewer.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <span>
#include <vector>

namespace tritri::detail::box_pairs {

// One level of the hierarchy: a dense grid of dim[0] x dim[1] x dim[2] cells of size h.
struct GridLevel {
  int dim[3] = {1, 1, 1};
  double inv_h = 0;
  std::vector<std::uint32_t> first;  // cell c holds entries first[c] .. first[c + 1] of its level

  std::size_t cells() const { return static_cast<std::size_t>(dim[0]) * dim[1] * dim[2]; }
  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * dim[1] + static_cast<std::size_t>(y)) * dim[0] + static_cast<std::size_t>(x);
  }
};

// Whether keys a and b share a value (without branches: most pairs of a clean mesh share one).
inline bool share_key(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  bool shared = false;
  for (int u : a) shared |= (u == b[0]) | (u == b[1]) | (u == b[2]);
  return shared;
}

template <class Box, class Visit>
bool visit_pairs_in_grid(const std::vector<Box>& boxes, const Visit& visit,
                         std::span<const std::array<int, 3>> keys = {}) {
  const std::size_t n = boxes.size();
  if (n < 2) return true;
  if (n > (std::size_t{1} << 27)) return false;  // entries (at most 8 n) must fit 32 bits
  // Cell size: the median of the boxes' largest extents (robust to a few long ones).
  std::vector<double> extent(n);
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = boxes[0].min_coord(k);
    hi[k] = boxes[0].max_coord(k);
  }
  for (std::size_t i = 0; i < n; ++i) {
    double e = 0;
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], boxes[i].min_coord(k));
      hi[k] = std::max(hi[k], boxes[i].max_coord(k));
      e = std::max(e, boxes[i].max_coord(k) - boxes[i].min_coord(k));
    }
    extent[i] = e;
  }
  std::nth_element(extent.begin(), extent.begin() + static_cast<std::ptrdiff_t>(n / 2), extent.end());
  double h = 2 * extent[n / 2];
  extent = {};
  const double span = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  if (!(span > 0) || !std::isfinite(span)) return false;
  if (!(h > 0)) h = span;
  // At most about 8 cells per box on level 0: grow h until the dense grid is that small.
  const double max_cells = 8.0 * static_cast<double>(n) + 64;
  for (;;) {
    double cells = 1;
    for (int k = 0; k < 3; ++k) cells *= std::min(std::floor((hi[k] - lo[k]) / h) + 1, 1e6);
    if (cells <= max_cells) break;
    h *= std::cbrt(cells / max_cells) * 1.01;
  }
  std::vector<GridLevel> levels;
  bool capped = false;  // a level's cells per axis capped (1e6): then the levels do not nest
  auto add_level = [&] {
    const double hl = std::ldexp(h, static_cast<int>(levels.size()));
    GridLevel& g = levels.emplace_back();
    for (int k = 0; k < 3; ++k) {
      const double cells = std::floor((hi[k] - lo[k]) / hl) + 1;
      capped |= cells > 1e6;
      g.dim[k] = static_cast<int>(std::min(cells, 1e6));
    }
    g.inv_h = 1 / hl;
  };
  // Monotone in x: a subtraction, a product by a positive constant, a clamp.
  auto cell = [&](const GridLevel& g, double x, int k) {
    const double t = (x - lo[k]) * g.inv_h;
    if (!(t > 0)) return 0;
    if (t >= g.dim[k] - 1) return g.dim[k] - 1;
    return static_cast<int>(t);
  };
  auto range = [&](const GridLevel& g, const Box& b) {
    std::array<int, 6> r;
    for (int k = 0; k < 3; ++k) {
      r[k] = cell(g, b.min_coord(k), k);
      r[3 + k] = cell(g, b.max_coord(k), k);
    }
    return r;
  };
  auto count = [](const std::array<int, 6>& r) {
    return static_cast<std::size_t>(r[3] - r[0] + 1) * static_cast<std::size_t>(r[4] - r[1] + 1) *
           static_cast<std::size_t>(r[5] - r[2] + 1);
  };
  auto for_cells = [](const GridLevel& g, const std::array<int, 6>& r, auto&& f) {
    for (int z = r[2]; z <= r[5]; ++z)
      for (int y = r[1]; y <= r[4]; ++y)
        for (int x = r[0]; x <= r[3]; ++x) f(g.index(x, y, z));
  };
  // Each box on the first level where it meets at most 8 cells; the levels go up to one
  // of at most 2 cells per axis, where every box qualifies. Its level and cell range there
  // are found once. In parallel: the counts with relaxed atomic increments (the order of
  // boxes within a cell does not matter).
  add_level();
  while (levels.back().dim[0] > 2 || levels.back().dim[1] > 2 || levels.back().dim[2] > 2) add_level();
  std::vector<std::uint8_t> level_of(n);
  std::vector<std::array<int, 6>> range_of(n);
  for (GridLevel& g : levels) g.first.assign(g.cells() + 1, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i) {
      std::size_t l = 0;
      std::array<int, 6> cells = range(levels[0], boxes[i]);
      while (count(cells) > 8) cells = range(levels[++l], boxes[i]);
      level_of[i] = static_cast<std::uint8_t>(l);
      range_of[i] = cells;
      GridLevel& g = levels[l];
      for_cells(g, cells, [&](std::size_t c) {
        std::atomic_ref<std::uint32_t>(g.first[c + 1]).fetch_add(1, std::memory_order_relaxed);
      });
    }
  });
  // Prefix sums, and the pairwise tests within cells they imply.
  double tests = 0;
  for (GridLevel& g : levels)
    for (std::size_t c = 0; c < g.cells(); ++c) {
      const double k = g.first[c + 1];
      tests += k * k / 2;
      g.first[c + 1] += g.first[c];
    }
  std::vector<char> occupied(levels.size(), 0);
  std::size_t top = 0;  // the highest level with boxes
  for (std::size_t l = 0; l < levels.size(); ++l)
    if (levels[l].first.back() > 0) {
      occupied[l] = 1;
      top = l;
    }
  // Decline when the pairwise tests would cost more than the segment tree: boxes crowding
  // the cells of one level, or small boxes under many large ones. A test is a few
  // comparisons on contiguous data; measured on the EMBER pairs, 40 n log2 n of them still
  // take less time than CGAL's segment tree on the same boxes.
  const double budget = 40 * static_cast<double>(n) * std::log2(static_cast<double>(n));
  // The tests across levels, per level l: at most the boxes below it times 8 cells times l's
  // fullest cell (a box meets at most 8 cells on every level above its own: the levels'
  // cells nest, h_l being h 2^l exactly, so a run of a cells along an axis becomes at most
  // a / 2 + 1 one level up). Where the bounds do not fit the budget, the levels are counted
  // exactly, largest bound first, until they fit (a count visits every box below the level).
  // The levels nest when no axis was capped and each level's 1 / h is exactly half the one
  // below (a normal double: no overflow or underflow at extreme scales); else no bound.
  bool nested = !capped;
  for (std::size_t l = 1; l < levels.size(); ++l)
    nested &= std::isnormal(levels[l].inv_h) && levels[l].inv_h * 2 == levels[l - 1].inv_h;
  constexpr double kUnknown = std::numeric_limits<double>::infinity();
  std::vector<double> cross(top + 1, 0);  // per level: a bound or the exact count
  std::vector<double> below(levels.size() + 1, 0);  // below[l]: boxes on levels < l
  for (std::size_t i = 0; i < n; ++i) ++below[level_of[i] + 1u];
  for (std::size_t l = 1; l <= levels.size(); ++l) below[l] += below[l - 1];
  for (std::size_t l = 1; l <= top; ++l) {
    if (!occupied[l]) continue;
    if (!nested) {
      cross[l] = kUnknown;
      continue;
    }
    std::uint32_t fullest = 0;
    for (std::size_t c = 0; c < levels[l].cells(); ++c)
      fullest = std::max(fullest, levels[l].first[c + 1] - levels[l].first[c]);
    cross[l] = below[l] * 8 * fullest;
  }
  auto total = [&] { return std::accumulate(cross.begin(), cross.end(), tests); };
  auto count_exactly = [&](std::size_t l) {
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, n, 4096), 0.0,
        [&](const tbb::blocked_range<std::size_t>& r, double sum) {
          for (std::size_t i = r.begin(); i < r.end(); ++i)
            if (level_of[i] < l)
              for_cells(levels[l], range(levels[l], boxes[i]),
                        [&](std::size_t c) { sum += levels[l].first[c + 1] - levels[l].first[c]; });
          return sum;
        },
        std::plus<double>());
  };
  std::vector<char> counted(top + 1, 0);
  if (tests <= budget)
    while (total() > budget) {
      std::size_t pick = 0;  // the uncounted level of largest bound
      for (std::size_t l = 1; l <= top; ++l)
        if (!counted[l] && cross[l] > 0 && (pick == 0 || cross[l] > cross[pick])) pick = l;
      if (pick == 0) break;  // all exact, over budget
      cross[pick] = count_exactly(pick);
      counted[pick] = 1;
    }
  tests = total();
  if (tests > budget) return false;
  // Each cell's boxes by index; on the coarser levels also as contiguous copies of their
  // coordinates, which the finer boxes beneath them read in order (level 0, most of the
  // entries, is gathered one cell at a time below).
  struct Entry {
    double lo[3], hi[3];
    int info;
    std::array<int, 3> key;
  };
  const bool keyed = !keys.empty();
  auto entry_of = [&](std::size_t i) {
    Entry e;
    for (int k = 0; k < 3; ++k) {
      e.lo[k] = boxes[i].min_coord(k);
      e.hi[k] = boxes[i].max_coord(k);
    }
    e.info = boxes[i].info();
    e.key = keyed ? keys[static_cast<std::size_t>(e.info)] : std::array<int, 3>{};
    return e;
  };
  std::vector<std::vector<std::uint32_t>> member(levels.size());
  std::vector<std::vector<Entry>> entries(levels.size());
  {
    std::vector<std::vector<std::uint32_t>> fill(levels.size());
    for (std::size_t l = 0; l < levels.size(); ++l) {
      member[l].resize(levels[l].first.back());
      if (l > 0) entries[l].resize(levels[l].first.back());
      fill[l].assign(levels[l].first.begin(), levels[l].first.end() - 1);
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t i = r.begin(); i < r.end(); ++i) {
        const std::size_t l = level_of[i];
        std::vector<std::uint32_t>& f = fill[l];
        for_cells(levels[l], range_of[i], [&](std::size_t c) {
          const std::uint32_t slot = std::atomic_ref<std::uint32_t>(f[c]).fetch_add(1, std::memory_order_relaxed);
          member[l][slot] = static_cast<std::uint32_t>(i);
          if (l > 0) entries[l][slot] = entry_of(i);
        });
      }
    });
  }
  range_of = {};
  // Reports the pair of triangles i and j, whose boxes overlap with their intersection's
  // minimum corner at (x, y, z), when that corner lies in cell c of level g.
  auto report = [&](const GridLevel& g, std::size_t c, double x, double y, double z, int i, int j) {
    if (i != j && g.index(cell(g, x, 0), cell(g, y, 1), cell(g, z, 2)) == c) visit(std::min(i, j), std::max(i, j));
  };
  auto overlap = [](const Entry& a, const Entry& b) {
    return a.lo[0] <= b.hi[0] && b.lo[0] <= a.hi[0] && a.lo[1] <= b.hi[1] && b.lo[1] <= a.hi[1] &&
           a.lo[2] <= b.hi[2] && b.lo[2] <= a.hi[2];
  };
  // Pairs on one level, a cell at a time: its boxes gathered into one array per coordinate,
  // each box tested against the later ones without branches, the overlapping ones listed.
  struct CellBoxes {
    std::vector<double> lo[3], hi[3];
    std::vector<int> info;
    std::vector<std::array<int, 3>> key;
    std::vector<std::uint32_t> hit;
  };
  for (std::size_t l = 0; l < levels.size(); ++l) {
    const GridLevel& g = levels[l];
    if (g.first.back() < 2) continue;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, g.cells(), 256), [&](const tbb::blocked_range<std::size_t>& r) {
      CellBoxes cb;
      for (std::size_t c = r.begin(); c < r.end(); ++c) {
        const std::uint32_t* m = member[l].data() + g.first[c];
        const std::size_t k = g.first[c + 1] - g.first[c];
        if (k < 2) continue;
        if (cb.hit.size() < k) {
          for (int d = 0; d < 3; ++d) {
            cb.lo[d].resize(k);
            cb.hi[d].resize(k);
          }
          cb.info.resize(k);
          if (keyed) cb.key.resize(k);
          cb.hit.resize(k);
        }
        for (std::size_t t = 0; t < k; ++t) {
          const Box& b = boxes[m[t]];
          for (int d = 0; d < 3; ++d) {
            cb.lo[d][t] = b.min_coord(d);
            cb.hi[d][t] = b.max_coord(d);
          }
          cb.info[t] = b.info();
          if (keyed) cb.key[t] = keys[static_cast<std::size_t>(b.info())];
        }
        const double *lo0 = cb.lo[0].data(), *lo1 = cb.lo[1].data(), *lo2 = cb.lo[2].data();
        const double *hi0 = cb.hi[0].data(), *hi1 = cb.hi[1].data(), *hi2 = cb.hi[2].data();
        std::uint32_t* hit = cb.hit.data();
        for (std::size_t p = 0; p + 1 < k; ++p) {
          const double a0 = lo0[p], a1 = lo1[p], a2 = lo2[p], b0 = hi0[p], b1 = hi1[p], b2 = hi2[p];
          std::size_t hits = 0;
          for (std::size_t q = p + 1; q < k; ++q) {
            const bool meet = (a0 <= hi0[q]) & (lo0[q] <= b0) & (a1 <= hi1[q]) & (lo1[q] <= b1) & (a2 <= hi2[q]) &
                              (lo2[q] <= b2);
            hit[hits] = static_cast<std::uint32_t>(q);
            hits += meet;
          }
          for (std::size_t h = 0; h < hits; ++h) {
            const std::size_t q = hit[h];
            if (keyed && share_key(cb.key[p], cb.key[q])) continue;
            report(g, c, std::max(a0, lo0[q]), std::max(a1, lo1[q]), std::max(a2, lo2[q]), cb.info[p], cb.info[q]);
          }
        }
      }
    });
  }
  // Pairs across levels: each box against the boxes of every higher level in its cells there.
  if (top > 0)
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t i = r.begin(); i < r.end(); ++i) {
        if (level_of[i] >= top) continue;
        const Entry a = entry_of(i);
        for (std::size_t l = level_of[i] + 1u; l <= top; ++l) {
          if (!occupied[l]) continue;
          const GridLevel& g = levels[l];
          const std::vector<Entry>& e = entries[l];
          for_cells(g, range(g, boxes[i]), [&](std::size_t c) {
            for (std::uint32_t p = g.first[c]; p < g.first[c + 1]; ++p)
              if (overlap(a, e[p]) && !(keyed && share_key(a.key, e[p].key)))
                report(g, c, std::max(a.lo[0], e[p].lo[0]), std::max(a.lo[1], e[p].lo[1]),
                       std::max(a.lo[2], e[p].lo[2]), a.info, e[p].info);
          });
        }
      }
    });
  return true;
}

}  // namespace tritri::detail::box_pairs
