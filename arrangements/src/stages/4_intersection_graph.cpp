#include "stages/4_intersection_graph.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdint>
#include <type_traits>

#include <tritri/implicit_point.h>
#include <tritri/location.h>

#include "models/double_model.h"
#include "models/exact_model.h"
#include "stages/4_share_coplanar.h"
#include "support/append_points.h"
#include "support/model_order.h"
#include "support/sort_unique.h"

namespace arrangements {
namespace {

// The vectors of `parts` one after the other in `out` (each part freed once copied).
template <class T>
void concatenate(std::vector<std::vector<T>>& parts, std::vector<T>& out) {
  std::size_t n = 0;
  for (const auto& p : parts) n += p.size();
  out.clear();
  out.reserve(n);
  for (auto& p : parts) {
    out.insert(out.end(), p.begin(), p.end());
    std::vector<T>().swap(p);
  }
}

// lists[k]: value(x) for every entry x with key x[0] == k among the entries of all parts,
// sorted and unique. A counting pass sizes each list once; the lists are then sorted in
// parallel (they are short: the points or segments of one triangle or edge).
template <class Entry, class List, class Value>
void group(std::vector<std::vector<Entry>>& parts, std::size_t keys, std::vector<List>& lists, Value value) {
  std::vector<std::uint32_t> count(keys, 0);
  for (const auto& part : parts)
    for (const Entry& x : part) ++count[x[0]];
  lists.assign(keys, {});
  tbb::parallel_for(std::size_t{0}, keys, [&](std::size_t k) {  // the allocations, in parallel
    if (count[k]) lists[k].reserve(count[k]);
  });
  // Filled by blocks of keys, one task each: every task reads all entries and appends
  // those of its keys (cheap sequential reads; the scattered appends, which cost, are
  // split). Each list gets its entries in part order, as one thread would.
  const std::size_t blocks = std::min<std::size_t>(keys, tbb::this_task_arena::max_concurrency());
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    const std::size_t first = b * keys / blocks, last = (b + 1) * keys / blocks;
    for (const auto& part : parts)
      for (const Entry& x : part)
        if (static_cast<std::size_t>(x[0]) - first < last - first) lists[x[0]].push_back(value(x));
  });
  for (auto& part : parts) std::vector<Entry>().swap(part);
  tbb::parallel_for(std::size_t{0}, keys, [&](std::size_t k) {
    if (count[k] > 1) sort_unique(lists[k]);
  });
}

// Unique edges, numbered in lexicographic order of (smaller id, larger id): a counting
// sort by the smaller vertex id, then each vertex's few half-edges sorted (linear time;
// the same order as sorting all (v0, v1, triangle * 3 + k) triples).
template <class G>
void build_edges(const std::vector<Tri>& F, G& g) {
  int nv = 0;
  for (const Tri& t : F) nv = std::max({nv, t[0] + 1, t[1] + 1, t[2] + 1});
  std::vector<int> first(static_cast<std::size_t>(nv) + 1, 0);
  for (const Tri& t : F)
    for (int k = 0; k < 3; ++k) ++first[std::min(t[k], t[(k + 1) % 3]) + 1];
  for (int v = 0; v < nv; ++v) first[v + 1] += first[v];
  std::vector<std::array<int, 2>> half(F.size() * 3);  // (v1, triangle * 3 + k), grouped by v0
  {
    std::vector<int> fill(first.begin(), first.end() - 1);
    for (std::size_t t = 0; t < F.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const int a = F[t][k], b = F[t][(k + 1) % 3];
        half[fill[std::min(a, b)]++] = {std::max(a, b), static_cast<int>(t * 3 + k)};
      }
  }
  g.triangle_edges.assign(F.size(), {-1, -1, -1});
  for (int v = 0; v < nv; ++v) {
    std::sort(half.begin() + first[v], half.begin() + first[v + 1]);
    for (int i = first[v]; i < first[v + 1]; ++i) {
      if (i == first[v] || half[i][0] != half[i - 1][0]) g.edges.push_back({v, half[i][0]});
      g.triangle_edges[half[i][1] / 3][half[i][1] % 3] = static_cast<int>(g.edges.size() - 1);
    }
  }
}

// A combinatorial name of a new point: (0, LPI ids) for an edge crossing a face,
// (1, edge, edge) for two crossing edges, edges as sorted vertex ids.
using PointName = std::array<int, 6>;

PointName point_name(const std::vector<Tri>& F, const PairIntersection& p, const PairPoint& q) {
  if (q.in[0].kind == Location::Edge && q.in[1].kind == Location::Edge) {
    std::array<int, 2> e[2];
    for (int k = 0; k < 2; ++k) {
      const Tri& t = F[p.tri[k]];
      e[k] = {t[q.in[k].id], t[(q.in[k].id + 1) % 3]};
      if (e[k][0] > e[k][1]) std::swap(e[k][0], e[k][1]);
    }
    if (e[1] < e[0]) std::swap(e[0], e[1]);
    return {1, e[0][0], e[0][1], e[1][0], e[1][1], 0};
  }
  return {0, q.lpi.v[0], q.lpi.v[1], q.lpi.v[2], q.lpi.v[3], q.lpi.v[4]};
}

template <class M>
typename M::Point make_lpi(const std::vector<typename M::Vertex>& V, const std::vector<Tri>& F, const LpiKey& key) {
  auto at = [&](int id) {
    if (id >= 0) return V[id];
    const Tri& t = F[-1 - id];
    return M::auxiliary_point(V[t[0]], V[t[1]], V[t[2]]);
  };
  return M::lpi(at(key.v[0]), at(key.v[1]), at(key.v[2]), at(key.v[3]), at(key.v[4]));
}

// Two planes through the line of segment s of pair p (see SegmentSupport).
SegmentSupport segment_support(const std::vector<Tri>& F, const PairIntersection& p, const tritri::Segment& s, int a,
                               int b) {
  SegmentSupport sup;
  sup.ends = {a, b};
  sup.planes[0] = F[p.tri[0]];
  sup.planes[1] = F[p.tri[1]];
  if (!p.coplanar) return sup;
  // Coplanar pairs: the segment runs along an edge of one of the triangles.
  for (int k = 0; k < 2; ++k) {
    const int common = closed_edges(p.points[s.p0].in[k]) & closed_edges(p.points[s.p1].in[k]);
    for (int e = 0; e < 3; ++e)
      if (common & (1 << e)) {
        const Tri& t = F[p.tri[k]];
        sup.planes[1] = {t[e], t[(e + 1) % 3], -1 - p.tri[k]};
        return sup;
      }
  }
  sup.planes[1] = sup.planes[0];  // not along an edge: triangulation reports it
  return sup;
}

}  // namespace

template <class M>
BasicIntersectionGraph<typename M::Point> build_intersection_graph(const std::vector<typename M::Vertex>& V,
                                                                   const std::vector<Tri>& F,
                                                                   const PairRecords& pairs, bool share) {
  using Point = typename M::Point;
  using Key = typename M::Key;
  BasicIntersectionGraph<Point> g;
  g.num_input_vertices = static_cast<int>(V.size());
  build_edges(F, g);

  // 1. New points by definition. A crossing of two edges is named by the two edges (its
  // LPI may use the plane of either triangle on either side, so several pairs describe
  // it differently); an edge crossing a face by its LPI. Each name keeps its smallest LPI.
  const std::vector<PairRecordChunk>& chunks = pairs.chunks();
  std::vector<std::pair<PointName, LpiKey>> named;
  {
    std::vector<std::vector<std::pair<PointName, LpiKey>>> per_chunk(chunks.size());
    tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t c) {
      for (std::size_t i = 0; i < chunks[c].size(); ++i) {
        const PairIntersection p = chunks[c][i];
        for (const auto& q : p.points)
          if (q.vertex < 0) per_chunk[c].emplace_back(point_name(F, p, q), q.lpi);
      }
    });
    concatenate(per_chunk, named);
  }
  tbb::parallel_sort(named.begin(), named.end());
  std::vector<PointName> names;
  std::vector<LpiKey> keys;
  for (const auto& [name, lpi] : named)
    if (names.empty() || names.back() != name) {
      names.push_back(name);
      keys.push_back(lpi);
    }
  named = {};  // freed before the points are built (peak memory)
  std::vector<Point> lpis(keys.size());
  tbb::parallel_for(std::size_t{0}, keys.size(), [&](std::size_t i) { lpis[i] = make_lpi<M>(V, F, keys[i]); });

  // 2. Exact deduplication among new points: sort by an exact total order, along
  // M::compare (DoubleModel: along tritri::kSortDirection with ties by xyz; distinct points
  // of structured inputs rarely tie along it; certified intervals settle almost every
  // comparison); each run of equal points is represented by its smallest key index
  // (deterministic).
  std::vector<Key> db;
  const std::vector<int> order =
      ids_in_model_order<M>(keys.size(), [&](std::size_t i) -> const Point& { return lpis[i]; }, db);
  auto compare = [&](int a, int b) { return M::compare(lpis[a], db[a], lpis[b], db[b]); };
  // Runs of equal points from the comparisons of neighbours in the order (in parallel; an
  // exact total order makes equality transitive).
  std::vector<char> same_as_previous(order.size(), 0);
  tbb::parallel_for(std::size_t{1}, order.size(),
                    [&](std::size_t i) { same_as_previous[i] = compare(order[i - 1], order[i]) == 0; });
  // Each run handled by the task holding its first element (runs never overlap).
  std::vector<int> representative(keys.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, order.size()), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i) {
      if (same_as_previous[i]) continue;
      std::size_t j = i + 1;
      while (j < order.size() && same_as_previous[j]) ++j;
      int rep = order[i];
      for (std::size_t k = i; k < j; ++k) rep = std::min(rep, order[k]);
      for (std::size_t k = i; k < j; ++k) representative[order[k]] = rep;
    }
  });

  // 3. New points that coincide with an input vertex become that vertex: the vertices
  // sorted in the same exact order, each new point looked up (grids put many vertices at
  // exactly the x of a new point, where xyz order would need exact arithmetic).
  std::vector<int> final_id(keys.size(), -1);
  append_points(g.points, V.size(), [&](std::size_t v) { return M::explicit_point(V[v]); });
  std::vector<int> by_position;
  std::vector<Key> vb;
  if (!keys.empty())
    by_position =
        ids_in_model_order<M>(V.size(), [&](std::size_t v) -> const Point& { return g.points[v]; }, vb);
  // Both sequences in one order: a merge finds every match. In parallel, by pieces of
  // `order`, each merged from the first vertex not before its first point.
  std::vector<int> vertex_match(keys.size(), -1);
  auto vertex_before_point = [&](int vid, int k) { return M::compare(g.points[vid], vb[vid], lpis[k], db[k]) < 0; };
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, by_position.empty() ? 0 : order.size(), 4096),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      std::size_t v = static_cast<std::size_t>(
                          std::lower_bound(by_position.begin(), by_position.end(), order[r.begin()],
                                           vertex_before_point) -
                          by_position.begin());
                      for (std::size_t i = r.begin(); i < r.end() && v < by_position.size();) {
                        const int k = order[i], vid = by_position[v];
                        const int c = M::compare(g.points[vid], vb[vid], lpis[k], db[k]);
                        if (c < 0) {
                          ++v;
                        } else {
                          if (c == 0) vertex_match[k] = vid;
                          ++i;
                        }
                      }
                    });
  std::vector<int> fresh;  // the keys that become new points, in id order
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (representative[i] != static_cast<int>(i)) continue;
    if (vertex_match[i] >= 0) {
      final_id[i] = vertex_match[i];
    } else {
      final_id[i] = static_cast<int>(V.size() + fresh.size());
      fresh.push_back(static_cast<int>(i));
    }
  }
  g.new_points = fresh.size();
  append_points(g.points, fresh.size(), [&](std::size_t k) { return std::move(lpis[fresh[k]]); });
  for (std::size_t i = 0; i < keys.size(); ++i) final_id[i] = final_id[representative[i]];
  // The new points in the order of the sort (triangulation looks TPIs up in it, with
  // M::compare).
  for (const int k : order)
    if (representative[k] == k && vertex_match[k] < 0) g.new_points_sorted.push_back(final_id[k]);

  // 4. Record points, segments and coplanar partners per triangle and edge: each chunk of
  // records lists its entries (in parallel), which are then sorted and grouped.
  auto id_of = [&](const PairIntersection& p, const PairPoint& q) {
    if (q.vertex >= 0) return q.vertex;
    return final_id[std::lower_bound(names.begin(), names.end(), point_name(F, p, q)) - names.begin()];
  };
  struct Entries {
    std::vector<std::array<int, 2>> edge_point, triangle_point, partner;  // (edge or triangle, id)
    std::vector<std::array<int, 3>> triangle_segment;                      // (triangle, a, b)
    std::vector<SegmentSupport> supports;
  };
  std::vector<Entries> found(chunks.size());
  tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t c) {
    Entries& e = found[c];
    for (std::size_t r = 0; r < chunks[c].size(); ++r) {
      const PairIntersection p = chunks[c][r];
      int ids[6];
      for (std::size_t i = 0; i < p.points.size(); ++i) {
        ids[i] = id_of(p, p.points[i]);
        for (int k = 0; k < 2; ++k) {
          const Location& loc = p.points[i].in[k];
          if (loc.kind == Location::Edge) e.edge_point.push_back({g.triangle_edges[p.tri[k]][loc.id], ids[i]});
          if (loc.kind == Location::Interior) e.triangle_point.push_back({p.tri[k], ids[i]});
        }
      }
      for (const auto& s : p.segments) {
        int a = ids[s.p0], b = ids[s.p1];
        if (a == b) continue;
        if (a > b) std::swap(a, b);
        e.supports.push_back(segment_support(F, p, s, a, b));
        // A segment along a triangle's own edge is already that edge (its points are
        // recorded on the edge): it constrains only the triangles it crosses.
        for (int k = 0; k < 2; ++k)
          if (!(closed_edges(p.points[s.p0].in[k]) & closed_edges(p.points[s.p1].in[k])))
            e.triangle_segment.push_back({p.tri[k], a, b});
      }
      if (p.coplanar) e.partner.insert(e.partner.end(), {{p.tri[0], p.tri[1]}, {p.tri[1], p.tri[0]}});
    }
  });
  g.intersecting_pairs = pairs.size();
  auto parts = [&](auto member) {  // one member of every chunk's entries, moved out
    std::vector<std::decay_t<decltype(found[0].*member)>> all(found.size());
    for (std::size_t c = 0; c < found.size(); ++c) all[c] = std::move(found[c].*member);
    return all;
  };
  {
    auto partner = parts(&Entries::partner);
    for (const auto& part : partner) g.coplanar_pairs += part.size() / 2;  // each pair's record once
    group(partner, F.size(), g.coplanar_partners, [](const auto& x) { return x[1]; });
  }
  {
    auto edge_point = parts(&Entries::edge_point);
    group(edge_point, g.edges.size(), g.edge_points, [](const auto& x) { return x[1]; });
  }
  {
    auto triangle_point = parts(&Entries::triangle_point);
    group(triangle_point, F.size(), g.triangle_points, [](const auto& x) { return x[1]; });
  }
  {
    auto triangle_segment = parts(&Entries::triangle_segment);
    group(triangle_segment, F.size(), g.triangle_segments,
          [](const auto& x) { return std::array<int, 2>{x[1], x[2]}; });
  }
  {
    auto supports = parts(&Entries::supports);
    concatenate(supports, g.segment_supports);
  }
  tbb::parallel_sort(g.segment_supports.begin(), g.segment_supports.end());
  g.segment_supports.erase(std::unique(g.segment_supports.begin(), g.segment_supports.end()),
                           g.segment_supports.end());
  found = {};
  if (share && g.coplanar_pairs > 0) share_coplanar<M>(V, F, g);  // keeps the lists sorted and unique
  std::vector<std::array<int, 2>> all_segments;
  std::size_t listed = 0;
  for (const auto& v : g.triangle_segments) listed += v.size();
  all_segments.reserve(listed);
  for (const auto& v : g.triangle_segments) all_segments.insert(all_segments.end(), v.begin(), v.end());
  tbb::parallel_sort(all_segments.begin(), all_segments.end());
  g.segments = std::unique(all_segments.begin(), all_segments.end()) - all_segments.begin();
  return g;
}

template IntersectionGraph build_intersection_graph<DoubleModel>(const std::vector<Vec3>&, const std::vector<Tri>&,
                                                                 const PairRecords&, bool);
template BasicIntersectionGraph<ExactModel::Point> build_intersection_graph<ExactModel>(
    const std::vector<ExactModel::Vertex>&, const std::vector<Tri>&, const PairRecords&, bool);

}  // namespace arrangements
