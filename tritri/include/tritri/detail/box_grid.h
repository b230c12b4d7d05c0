// tritri/detail/box_grid.h
//
// visit_pairs_in_grid(boxes, visit): every pair of overlapping closed boxes, found with a
// uniform grid instead of a segment tree, for inputs where that is cheap: meshes whose
// triangles are about the same size (scans, CAD with few long faces). Returns false, having
// visited nothing, when the boxes would cover too many cells (long or very uneven
// triangles); the caller then uses CGAL's box_intersection_d (box_pairs.h).
//
//   boxes  3D boxes with min_coord / max_coord / info() (the triangle index), finite
//   visit  visit(i, j), i < j triangle indices; called once per overlapping pair, from
//          several threads at once (oneTBB, the caller's arena)
//
// Method: cell size h twice the median box extent, grown until the grid has at most ~8
// cells per box; each box is listed in every cell its box meets (counting sort into one
// array); each cell tests its boxes pairwise, in parallel over cells. Declines when the
// boxes cover more than 16 n cells, or the pairwise tests would exceed 12 n log2 n. A pair is reported
// only by the cell that holds the minimum corner of the two boxes' intersection, so each
// pair once, with no global list or sort.
// Exactness: overlap is decided by exact comparisons of the box coordinates (closed boxes:
// touching counts). Cell indices come from floor((x - origin) / h) clamped to the grid,
// evaluated in floating point; every step is monotone in x, so the minimum corner of the
// intersection of two boxes, which lies in both boxes, falls in a cell both are listed in.
// Cost: O(n + S + sum over cells of k^2) for n boxes, S cell entries (at most 16 n, else
// the grid declines), k boxes per cell (sum of k^2 / 2 at most 12 n log2 n). Memory: 4 bytes per entry plus 4 per cell.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tritri::detail::box_pairs {

template <class Box, class Visit>
bool visit_pairs_in_grid(const std::vector<Box>& boxes, const Visit& visit) {
  const std::size_t n = boxes.size();
  if (n < 2) return true;
  if (n > (std::size_t{1} << 27)) return false;  // entries (at most 16 n) must fit 32 bits
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
  const double span = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  if (!(span > 0) || !std::isfinite(span)) return false;
  if (!(h > 0)) h = span;
  // At most about 8 cells per box: grow h until the dense grid is that small.
  const double max_cells = 8.0 * static_cast<double>(n) + 64;
  int dim[3];
  for (;;) {
    double cells = 1;
    for (int k = 0; k < 3; ++k) cells *= std::min(std::floor((hi[k] - lo[k]) / h) + 1, 1e6);
    if (cells <= max_cells) break;
    h *= std::cbrt(cells / max_cells) * 1.01;
  }
  for (int k = 0; k < 3; ++k) dim[k] = static_cast<int>(std::min(std::floor((hi[k] - lo[k]) / h) + 1, 1e6));
  const double inv_h = 1 / h;
  // Monotone in x: a subtraction, a product by a positive constant, a clamp.
  auto cell = [&](double x, int k) {
    const double t = (x - lo[k]) * inv_h;
    if (!(t > 0)) return 0;
    if (t >= dim[k] - 1) return dim[k] - 1;
    return static_cast<int>(t);
  };
  // Counting sort of (cell, box) entries; decline when the boxes cover too many cells.
  const std::size_t cells = static_cast<std::size_t>(dim[0]) * dim[1] * dim[2];
  std::vector<std::uint32_t> first(cells + 1, 0);
  std::size_t entries = 0;
  std::vector<std::array<int, 6>> range(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t count = 1;
    for (int k = 0; k < 3; ++k) {
      range[i][k] = cell(boxes[i].min_coord(k), k);
      range[i][3 + k] = cell(boxes[i].max_coord(k), k);
      count *= static_cast<std::size_t>(range[i][3 + k] - range[i][k] + 1);
    }
    entries += count;
    if (entries > 16 * n) return false;
  }
  auto index = [&](int x, int y, int z) {
    return (static_cast<std::size_t>(z) * dim[1] + static_cast<std::size_t>(y)) * dim[0] + static_cast<std::size_t>(x);
  };
  auto for_cells = [&](const std::array<int, 6>& r, auto&& f) {
    for (int z = r[2]; z <= r[5]; ++z)
      for (int y = r[1]; y <= r[4]; ++y)
        for (int x = r[0]; x <= r[3]; ++x) f(index(x, y, z));
  };
  for (std::size_t i = 0; i < n; ++i) for_cells(range[i], [&](std::size_t c) { ++first[c + 1]; });
  for (std::size_t c = 0; c < cells; ++c) first[c + 1] += first[c];
  // Decline when the cells are crowded (long or uneven triangles): their pairwise tests
  // would cost more than the segment tree, about n log^2 n.
  double tests = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    const double k = first[c + 1] - first[c];
    tests += k * k / 2;
  }
  if (tests > 12 * static_cast<double>(n) * std::log2(static_cast<double>(n))) return false;
  std::vector<std::uint32_t> member(entries);
  {
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
      for_cells(range[i], [&](std::size_t c) { member[fill[c]++] = static_cast<std::uint32_t>(i); });
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells, 256), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t c = r.begin(); c < r.end(); ++c) {
      for (std::uint32_t p = first[c]; p < first[c + 1]; ++p) {
        const Box& a = boxes[member[p]];
        for (std::uint32_t q = p + 1; q < first[c + 1]; ++q) {
          const Box& b = boxes[member[q]];
          double corner[3];
          bool overlap = true;
          for (int k = 0; k < 3 && overlap; ++k) {
            overlap = a.min_coord(k) <= b.max_coord(k) && b.min_coord(k) <= a.max_coord(k);
            corner[k] = std::max(a.min_coord(k), b.min_coord(k));
          }
          if (!overlap || index(cell(corner[0], 0), cell(corner[1], 1), cell(corner[2], 2)) != c) continue;
          const int i = a.info(), j = b.info();
          if (i != j) visit(std::min(i, j), std::max(i, j));
        }
      }
    }
  });
  return true;
}

}  // namespace tritri::detail::box_pairs
