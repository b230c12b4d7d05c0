#include "stages/5_triangulate.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>

#include "arrangements/memory_budget.h"
#include "models/double_model.h"
#include "models/exact_model.h"
#include "stages/5_triangulate_cluster.h"
#include "stages/5_triangulate_triangle.h"
#include "support/append_points.h"
#include "support/label_set_table.h"

namespace arrangements {

template <class M>
BasicOutputMesh<typename M::Point> triangulate(const BasicTriangleSoup<typename M::Vertex>& soup,
                                               const BasicIntersectionGraph<typename M::Point>& g, int scale_exponent,
                                               TriangulationInfo& info) {
  using Point = typename M::Point;
  const std::size_t nF = soup.triangles.size();
  std::vector<Piece<Point>> pieces(nF);
  std::vector<char> busy(nF, 0);
  for (std::size_t t = 0; t < nF; ++t) {
    busy[t] = !g.triangle_points[t].empty() || !g.triangle_segments[t].empty() || !g.coplanar_partners[t].empty();
    for (int k = 0; k < 3 && !busy[t]; ++k) busy[t] = !g.edge_points[g.triangle_edges[t][k]].empty();
  }
  // Coplanar clusters where per-triangle splitting would repeat most of the work are
  // triangulated whole (5_triangulate_cluster.h); the other triangles one by one.
  const std::vector<std::vector<int>> whole =
      info.per_triangle_only ? std::vector<std::vector<int>>{} : clusters_to_triangulate_whole(g);
  std::vector<char> done(nF, 0);
  std::atomic<std::size_t> whole_done{0};
  tbb::parallel_for(std::size_t{0}, whole.size(), [&](std::size_t c) {
    detail::memory_checkpoint();
    auto cluster_pieces = split_cluster_of<M>(soup, g, whole[c]);
    if (!cluster_pieces) return;  // no enclosing triangle: per triangle
    whole_done.fetch_add(1, std::memory_order_relaxed);
    for (std::size_t k = 0; k < whole[c].size(); ++k) {
      pieces[whole[c][k]] = std::move((*cluster_pieces)[k]);
      done[whole[c][k]] = 1;
    }
  });
  info.whole_clusters = whole_done.load();
  tbb::parallel_for(std::size_t{0}, nF, [&](std::size_t t) {
    detail::memory_checkpoint();
    if (busy[t] && !done[t]) pieces[t] = split_triangle_of<M>(soup, g, static_cast<int>(t));
  });

  // New TPIs, deduplicated exactly over all triangles (a crossing of two constraints is
  // also found by the triangles of those constraints); ids in exact lexicographic order.
  std::vector<Point> new_tpis;  // ids g.points.size() + k
  std::vector<std::size_t> tpi_offset(nF + 1, 0);
  for (std::size_t t = 0; t < nF; ++t) tpi_offset[t + 1] = tpi_offset[t] + pieces[t].tpis.size();
  std::vector<const Point*> tpi(tpi_offset[nF]);
  for (std::size_t t = 0; t < nF; ++t)
    for (std::size_t k = 0; k < pieces[t].tpis.size(); ++k) tpi[tpi_offset[t] + k] = &pieces[t].tpis[k];
  std::vector<int> order(tpi.size());
  std::iota(order.begin(), order.end(), 0);
  tbb::parallel_sort(order.begin(), order.end(), [&](int a, int b) {
    const int c = M::compare_xyz(*tpi[a], *tpi[b]);
    return c != 0 ? c < 0 : a < b;
  });
  // A crossing can also be a point that classification made (e.g. where an edge of one
  // constraint's triangle lies in t's plane and meets the other constraint's triangle):
  // look TPIs up among the graph's points, explicit vertices and LPIs sorted separately.
  std::vector<int> explicit_sorted;
  const std::vector<int>& lpi_sorted = g.new_points_sorted;  // sorted by stage 4
  if (!tpi.empty()) {
    explicit_sorted.resize(g.num_input_vertices);
    std::iota(explicit_sorted.begin(), explicit_sorted.end(), 0);
    tbb::parallel_sort(explicit_sorted.begin(), explicit_sorted.end(),
                       [&](int a, int b) { return M::vertex_less(soup.vertices[a], soup.vertices[b]); });
  }
  auto existing = [&](const Point& x) {
    // Input vertices in xyz order; new points in the graph's order (M::compare).
    auto it = std::lower_bound(explicit_sorted.begin(), explicit_sorted.end(), 0,
                               [&](int id, int) { return M::compare_xyz(g.points[id], x) < 0; });
    if (it != explicit_sorted.end() && M::compare_xyz(g.points[*it], x) == 0) return *it;
    const typename M::Key bx = M::key(x);
    auto along = [&](int id) { return M::compare(g.points[id], M::key(g.points[id]), x, bx); };
    const auto at =
        std::lower_bound(lpi_sorted.begin(), lpi_sorted.end(), 0, [&](int id, int) { return along(id) < 0; });
    if (at != lpi_sorted.end() && along(*at) == 0) return *at;
    return -1;
  };
  std::vector<int> tpi_id(tpi.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i == 0 || M::compare_xyz(*tpi[order[i - 1]], *tpi[order[i]]) != 0) {
      const int id = existing(*tpi[order[i]]);
      if (id >= 0) {
        tpi_id[order[i]] = id;
        continue;
      }
      new_tpis.push_back(*tpi[order[i]]);
    }
    tpi_id[order[i]] = i > 0 && M::compare_xyz(*tpi[order[i - 1]], *tpi[order[i]]) == 0
                           ? tpi_id[order[i - 1]]
                           : static_cast<int>(g.points.size() + new_tpis.size()) - 1;
  }
  info.new_tpi = new_tpis.size();

  // Output in soup-triangle order; points renumbered in first-use order. Three passes, so
  // that only integer work is serial: (1) in order, each soup triangle's first output
  // triangle and its covers' label sets (the label table numbers new sets in order of
  // first use); (2) in parallel, the triangles over graph point ids, their sources, label
  // sets and covers; (3) in order, the first-use numbering of the points, then their
  // copies in parallel.
  BasicOutputMesh<Point> out;
  const std::size_t nP = g.points.size() + new_tpis.size();
  std::vector<std::size_t> first_out(nF + 1, 0);
  for (std::size_t t = 0; t < nF; ++t) first_out[t + 1] = first_out[t] + (busy[t] ? pieces[t].triangles.size() : 1);
  const std::size_t out_triangles = first_out[nF];
  out.label_sets = soup.label_sets;
  LabelSetTable label_table(out.label_sets);
  // Covers numbered over all soup triangles in order: first_cover[t] + c is cover c of t,
  // in cover_label and (keep_covers; info arrives fresh) in info.covers.
  std::vector<int> first_cover(nF, 0);
  std::vector<int> cover_label;  // each cover's label set
  for (std::size_t t = 0; t < nF; ++t) {
    first_cover[t] = static_cast<int>(cover_label.size());
    if (!busy[t]) continue;
    const Piece<Point>& p = pieces[t];
    if (info.keep_covers) info.covers.insert(info.covers.end(), p.covers.begin(), p.covers.end());
    for (std::size_t c = 0; c < p.covers.size(); ++c) {
      LabelSet merged;
      for (int u : p.covers[c]) {
        const LabelSet& l = soup.label_sets[soup.label_set[u]];
        merged.insert(merged.end(), l.begin(), l.end());
      }
      std::sort(merged.begin(), merged.end());
      merged.erase(std::unique(merged.begin(), merged.end()), merged.end());
      cover_label.push_back(label_table.index_of(std::move(merged)));
    }
  }
  out.triangles.resize(out_triangles);
  out.source.resize(out_triangles);
  out.label_set.resize(out_triangles);
  if (info.keep_covers) {
    info.emitted_by.assign(out_triangles, -1);
    info.cover_of.assign(out_triangles, -1);
  }
  tbb::parallel_for(std::size_t{0}, nF, [&](std::size_t t) {
    const int ti = static_cast<int>(t);
    std::size_t o = first_out[t];
    if (!busy[t]) {
      out.triangles[o] = soup.triangles[t];
      out.source[o] = soup.source[t];
      out.label_set[o] = soup.label_set[t];
      if (info.keep_covers) info.emitted_by[o] = ti;  // cover_of: -1 already
      return;
    }
    Piece<Point> p = std::move(pieces[t]);  // freed once emitted (peak memory)
    for (std::size_t k = 0; k < p.triangles.size(); ++k, ++o) {
      Tri tr = p.triangles[k];
      for (int& v : tr)
        if (v < 0) v = tpi_id[tpi_offset[t] + (-1 - v)];
      const int cover = p.covered_by[k];
      out.triangles[o] = tr;
      out.source[o] = soup.source[t];
      out.label_set[o] = cover < 0 ? soup.label_set[t] : cover_label[static_cast<std::size_t>(first_cover[t] + cover)];
      if (info.keep_covers) {
        info.emitted_by[o] = ti;
        info.cover_of[o] = cover < 0 ? -1 : first_cover[t] + cover;
      }
    }
  });
  info.output_vertex.assign(nP, -1);
  std::vector<int> point_of;  // output vertex -> graph point id (then TPI ids)
  point_of.reserve(nP);
  for (Tri& tr : out.triangles)
    for (int& v : tr) {
      int& id = info.output_vertex[v];
      if (id < 0) {
        id = static_cast<int>(point_of.size());
        point_of.push_back(v);
      }
      v = id;
    }
  auto point = [&](int v) -> const Point& {
    return v < static_cast<int>(g.points.size()) ? g.points[v] : new_tpis[v - g.points.size()];
  };
  append_points(out.vertices, point_of.size(), [&](std::size_t i) { return point(point_of[i]); });
  if (scale_exponent != 0)
    tbb::parallel_for(std::size_t{0}, out.vertices.size(),
                      [&](std::size_t i) { out.vertices[i] = M::unscaled(out.vertices[i], scale_exponent); });
  return out;
}

template OutputMesh triangulate<DoubleModel>(const TriangleSoup&, const IntersectionGraph&, int, TriangulationInfo&);
template BasicOutputMesh<ExactModel::Point> triangulate<ExactModel>(const BasicTriangleSoup<ExactModel::Vertex>&,
                                                                    const BasicIntersectionGraph<ExactModel::Point>&,
                                                                    int, TriangulationInfo&);

}  // namespace arrangements
