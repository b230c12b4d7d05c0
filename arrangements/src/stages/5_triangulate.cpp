#include "stages/5_triangulate.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "arrangements/memory_budget.h"
#include "models/double_model.h"
#include "models/exact_model.h"
#include "stages/5_triangulate_cluster.h"
#include "stages/5_triangulate_triangle.h"
#include "support/append_points.h"
#include "support/model_order.h"
#include "support/label_set_table.h"

namespace arrangements {

namespace {

// The TPIs of all pieces (a crossing of two constraints is also found by the triangles of
// those constraints; a crossing can also be a point that classification made, e.g. where
// an edge of one constraint's triangle lies in t's plane and meets the other constraint's
// triangle), deduplicated exactly and looked up among the graph's points: id[i] is tpi[i]'s
// graph point, or g.points.size() + k for fresh[k]. Everything in the model's order
// (M::compare with each point's key computed once: most comparisons settle on the keys),
// in which stage 4 already sorted the graph's new points; the lookups in parallel.
template <class Point>
struct TpiIds {
  std::vector<Point> fresh;
  std::vector<int> id;
};

template <class M>
TpiIds<typename M::Point> tpi_ids(const BasicIntersectionGraph<typename M::Point>& g,
                                  const std::vector<const typename M::Point*>& tpi) {
  using Key = typename M::Key;
  TpiIds<typename M::Point> out;
  out.id.resize(tpi.size());
  if (tpi.empty()) return out;
  std::vector<Key> key;
  const std::vector<int> order = ids_in_model_order<M>(
      tpi.size(), [&](std::size_t i) -> const typename M::Point& { return *tpi[i]; }, key);
  auto tpi_compare = [&](int a, int b) { return M::compare(*tpi[a], key[a], *tpi[b], key[b]); };
  std::vector<std::size_t> run;  // the first position in `order` of each distinct point
  for (std::size_t i = 0; i < order.size(); ++i)
    if (i == 0 || tpi_compare(order[i - 1], order[i]) != 0) run.push_back(i);
  run.push_back(order.size());

  // The graph's points in the same order: input vertices (sorted here) and new points.
  std::vector<Key> vertex_key;
  const std::vector<int> vertices = ids_in_model_order<M>(
      g.num_input_vertices, [&](std::size_t v) -> const typename M::Point& { return g.points[v]; }, vertex_key);
  const std::vector<int>& lpis = g.new_points_sorted;
  std::vector<Key> lpi_key(lpis.size());
  tbb::parallel_for(std::size_t{0}, lpis.size(), [&](std::size_t k) { lpi_key[k] = M::key(g.points[lpis[k]]); });
  std::vector<int> match(run.size() - 1, -1);
  tbb::parallel_for(std::size_t{0}, match.size(), [&](std::size_t r) {
    const int x = order[run[r]];
    auto find = [&](const std::vector<int>& sorted, auto&& key_at) {
      std::size_t lo = 0, hi = sorted.size();  // first position not before x
      while (lo < hi) {
        const std::size_t mid = (lo + hi) / 2;
        if (M::compare(g.points[sorted[mid]], key_at(mid), *tpi[x], key[x]) < 0) lo = mid + 1;
        else hi = mid;
      }
      return lo < sorted.size() && M::compare(g.points[sorted[lo]], key_at(lo), *tpi[x], key[x]) == 0 ? sorted[lo] : -1;
    };
    match[r] = find(vertices, [&](std::size_t i) -> const Key& { return vertex_key[vertices[i]]; });
    if (match[r] < 0) match[r] = find(lpis, [&](std::size_t k) -> const Key& { return lpi_key[k]; });
  });
  for (std::size_t r = 0; r + 1 < run.size(); ++r) {
    int id = match[r];
    if (id < 0) {
      id = static_cast<int>(g.points.size() + out.fresh.size());
      out.fresh.push_back(*tpi[order[run[r]]]);
    }
    for (std::size_t i = run[r]; i < run[r + 1]; ++i) out.id[order[i]] = id;
  }
  return out;
}

}  // namespace

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

  std::vector<std::size_t> tpi_offset(nF + 1, 0);
  for (std::size_t t = 0; t < nF; ++t) tpi_offset[t + 1] = tpi_offset[t] + pieces[t].tpis.size();
  std::vector<const Point*> tpi(tpi_offset[nF]);
  for (std::size_t t = 0; t < nF; ++t)
    for (std::size_t k = 0; k < pieces[t].tpis.size(); ++k) tpi[tpi_offset[t] + k] = &pieces[t].tpis[k];
  const TpiIds<Point> ids = tpi_ids<M>(g, tpi);
  const std::vector<int>& tpi_id = ids.id;
  const std::vector<Point>& new_tpis = ids.fresh;
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
