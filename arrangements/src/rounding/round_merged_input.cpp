// merge_close_input_vertices (round_merged_input.h): vertices within delta merged, the
// input kept otherwise.
#include "rounding/round_merged_input.h"

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <numeric>
#include <utility>
#include <vector>

#include "support/cell_grid.h"
#include "rounding/rounding_grid.h"

namespace arrangements {
namespace {

int find(std::vector<int>& parent, int v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

}  // namespace

MergedInput merge_close_input_vertices(const TriangleSoup& input, double delta) {
  const std::size_t nv = input.vertices.size();
  // Cells of size delta: a vertex within delta of v lies in one of the 27 cells around v's.
  detail::CellGrid grid(delta);
  for (std::size_t v = 0; v < nv; ++v) grid.add(input.vertices[v], static_cast<int>(v));
  grid.finish();
  const CGAL::Gmpq limit = CGAL::Gmpq(delta) * CGAL::Gmpq(delta);
  auto close = [&](int a, int b) {
    CGAL::Gmpq d2 = 0;
    for (int k = 0; k < 3; ++k) {
      const CGAL::Gmpq d = CGAL::Gmpq(input.vertices[a][k]) - CGAL::Gmpq(input.vertices[b][k]);
      d2 += d * d;
    }
    return d2 <= limit;
  };
  std::vector<int> parent(nv);
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t i = 0; i < nv; ++i) {
    const int v = static_cast<int>(i);
    grid.for_each_near(input.vertices[i], [&](int w) {
      if (w <= v) return;
      const int a = find(parent, v), b = find(parent, w);
      if (a != b && close(v, w)) parent[std::max(a, b)] = std::min(a, b);  // the smallest index represents it
    });
  }

  MergedInput out;
  out.soup.vertices = input.vertices;
  out.soup.label_sets = input.label_sets;
  std::vector<int> representative(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    representative[v] = find(parent, static_cast<int>(v));
    const Vec3& p = input.vertices[v];
    // Exact duplicates merge too (as arranging does) but move nothing: not counted.
    if (representative[v] == static_cast<int>(v) || p == input.vertices[representative[v]]) continue;
    ++out.merged;
    out.max_move = std::max(out.max_move, distance_bound({CGAL::Gmpq(p[0]), CGAL::Gmpq(p[1]), CGAL::Gmpq(p[2])},
                                                         input.vertices[representative[v]]));
  }
  for (std::size_t t = 0; t < input.triangles.size(); ++t) {
    Tri f;
    for (int k = 0; k < 3; ++k) f[k] = representative[input.triangles[t][k]];
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) continue;
    out.soup.triangles.push_back(f);
    out.soup.label_set.push_back(input.label_set[t]);
    out.soup.source.push_back(input.source[t]);
  }
  return out;
}

}  // namespace arrangements
