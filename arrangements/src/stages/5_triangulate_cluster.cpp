#include "stages/5_triangulate_cluster.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "models/double_model.h"
#include "models/exact_model.h"
#include "stages/5_local_triangulation.h"
#include "stages/5_insertion_order.h"
#include "stages/5_transverse_supports.h"
#include "support/union_find.h"

namespace arrangements {

template <class Point>
std::vector<std::vector<int>> clusters_to_triangulate_whole(const BasicIntersectionGraph<Point>& g) {
  const std::size_t n = g.coplanar_partners.size();
  UnionFind sets(n);
  bool any = false;
  for (std::size_t t = 0; t < n; ++t)
    for (const int u : g.coplanar_partners[t]) sets.unite(static_cast<int>(t), u), any = true;
  if (!any) return {};
  // The root of a set is its smallest triangle (UnionFind): clusters in that order.
  std::vector<int> index_of(n, -1);
  std::vector<std::vector<int>> clusters;
  for (std::size_t t = 0; t < n; ++t) {
    if (g.coplanar_partners[t].empty()) continue;
    const int root = sets.find(static_cast<int>(t));
    if (index_of[root] < 0) index_of[root] = static_cast<int>(clusters.size()), clusters.emplace_back();
    clusters[index_of[root]].push_back(static_cast<int>(t));
  }
  std::vector<std::vector<int>> whole;
  std::vector<int> points;
  std::vector<std::array<int, 2>> segments;
  std::vector<int> edges;
  for (auto& cluster : clusters) {
    std::size_t work = 0;
    points.clear(), segments.clear(), edges.clear();
    for (const int t : cluster) {
      work += 3 + g.triangle_points[t].size() + g.triangle_segments[t].size();
      points.insert(points.end(), g.triangle_points[t].begin(), g.triangle_points[t].end());
      segments.insert(segments.end(), g.triangle_segments[t].begin(), g.triangle_segments[t].end());
      for (const int e : g.triangle_edges[t]) {
        work += 2 * g.edge_points[e].size() + 1;  // each edge point is a point and a constraint
        edges.push_back(e);
      }
    }
    if (work < kWholeMinWork) continue;
    auto distinct = [](auto& v) {
      std::sort(v.begin(), v.end());
      return static_cast<std::size_t>(std::unique(v.begin(), v.end()) - v.begin());
    };
    std::size_t once = distinct(points) + distinct(segments);
    const std::size_t e = distinct(edges);
    for (std::size_t k = 0; k < e; ++k) once += 2 * g.edge_points[edges[k]].size() + 1;
    if (work >= kWholeFrom * once) whole.push_back(std::move(cluster));
  }
  return whole;
}

namespace {

template <class M>
typename M::Vertex vertex_at(const std::array<double, 3>& x) {
  if constexpr (std::is_same_v<typename M::Vertex, Vec3>)
    return Vec3{x[0], x[1], x[2]};
  else
    return typename M::Vertex(x[0], x[1], x[2]);
}

}  // namespace

template <class M>
std::optional<std::vector<Piece<typename M::Point>>> split_cluster_of(
    const BasicTriangleSoup<typename M::Vertex>& soup, const BasicIntersectionGraph<typename M::Point>& g,
    const std::vector<int>& cluster) {
  using Vertex = typename M::Vertex;
  using Point = typename M::Point;
  const std::vector<Vertex>& V = soup.vertices;
  const Tri& ref = soup.triangles[cluster.front()];
  const auto [plane, ref_sign] = M::projection(V[ref[0]], V[ref[1]], V[ref[2]]);
  if (ref_sign == 0) throw std::logic_error("triangulate: degenerate triangle");
  const auto [ai, aj] = tritri::plane_axes(plane);

  // The enclosing triangle: around the box of the cluster's corners in the projection, a
  // right triangle with legs 12 r from 4 r below and left of the box's centre (r: a power
  // of two at least the box's size), so the box lies well inside; checked exactly.
  constexpr double inf = std::numeric_limits<double>::infinity();
  Vec3 lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  for (const int t : cluster)
    for (const int c : soup.triangles[t]) {
      Vec3 l, h;
      M::bounds(V[c], l, h);
      for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], l[a]), hi[a] = std::max(hi[a], h[a]);
    }
  const double ci = 0.5 * lo[ai] + 0.5 * hi[ai], cj = 0.5 * lo[aj] + 0.5 * hi[aj];
  const double size = std::max(hi[ai] - lo[ai], hi[aj] - lo[aj]);
  if (!std::isfinite(ci) || !std::isfinite(cj) || !(size > 0) || !std::isfinite(size)) return std::nullopt;
  const double r = std::ldexp(1.0, std::ilogb(size) + 1);
  std::array<Vertex, 3> big;
  const double corner[3][2] = {{ci - 4 * r, cj - 4 * r}, {ci + 8 * r, cj - 4 * r}, {ci - 4 * r, cj + 8 * r}};
  for (int k = 0; k < 3; ++k) {
    std::array<double, 3> x{lo[0], lo[1], lo[2]};
    x[ai] = corner[k][0], x[aj] = corner[k][1];
    for (double c : x)
      if (!std::isfinite(c)) return std::nullopt;
    big[k] = vertex_at<M>(x);
  }
  const int big_sign = tritri::to_int(M::orient2d(big[0], big[1], big[2], plane));
  if (big_sign == 0) return std::nullopt;
  for (const int t : cluster)
    for (const int c : soup.triangles[t])
      for (int k = 0; k < 3; ++k)
        if (tritri::to_int(M::orient2d(big[k], big[(k + 1) % 3], V[c], plane)) != big_sign) return std::nullopt;

  local::LocalTriangulation<M> lt(plane, big_sign, V[ref[0]]);
  for (const Vertex& b : big) lt.add_vertex(M::explicit_point(b));
  lt.start(0, 1, 2);

  // Local vertices 3, 4, ...: the cluster's graph points in id order (ids), then new TPIs.
  std::vector<int> edges;  // the cluster's edges, sorted; an edge shared by two of its triangles once
  for (const int t : cluster) edges.insert(edges.end(), g.triangle_edges[t].begin(), g.triangle_edges[t].end());
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<int> ids;
  for (const int t : cluster) {
    const Tri& tri = soup.triangles[t];
    ids.insert(ids.end(), tri.begin(), tri.end());
    ids.insert(ids.end(), g.triangle_points[t].begin(), g.triangle_points[t].end());
  }
  for (const int e : edges) ids.insert(ids.end(), g.edge_points[e].begin(), g.edge_points[e].end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  auto local_of = [&](int id) {
    const auto it = std::lower_bound(ids.begin(), ids.end(), id);
    if (it == ids.end() || *it != id)
      throw std::logic_error("triangulate: a constraint's endpoint is not a point of its cluster");
    return 3 + static_cast<int>(it - ids.begin());
  };
  for (const int id : ids) lt.add_vertex(g.points[id]);

  // The cluster's edges each point lies on (a corner: the edges at it; an edge point: its
  // edge), as sorted (point id, edge id) pairs: what lies along an edge, known by
  // construction.
  std::vector<std::array<int, 2>> edges_at;  // (point id, edge id) for the cluster's edges
  for (const int e : edges) {
    edges_at.push_back({g.edges[e][0], e});
    edges_at.push_back({g.edges[e][1], e});
    for (const int p : g.edge_points[e]) edges_at.push_back({p, e});
  }
  std::sort(edges_at.begin(), edges_at.end());
  auto edges_of = [&](int id) {
    const auto lo = std::lower_bound(edges_at.begin(), edges_at.end(), std::array<int, 2>{id, INT_MIN});
    const auto hi = std::lower_bound(lo, edges_at.end(), std::array<int, 2>{id + 1, INT_MIN});
    return std::pair{lo, hi};
  };
  // Constraints: each soup triangle's edges between consecutive edge points (an edge shared
  // by two triangles of the cluster once), and the segments of the graph.
  struct Constraint {
    int a, b, line;
    std::array<Vertex, 3> support;
    int edge;  // the graph edge it runs along, -1 for a segment
  };
  std::vector<Constraint> constraints;
  TransverseSupports<M> supports(soup, g, ref);
  std::vector<char> edge_done(edges.size(), 0);
  for (const int t : cluster) {
    const Tri& tri = soup.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int e = g.triangle_edges[t][k];
      char& done = edge_done[std::lower_bound(edges.begin(), edges.end(), e) - edges.begin()];
      if (done) continue;
      done = 1;
      const auto s = supports.of_plane({tri[k], tri[(k + 1) % 3], -1 - t});
      if (!s) throw std::logic_error("triangulate: an edge's plane is not transverse to its cluster");
      std::vector<int> chain = points_along_edge<M>(g, tri[k], tri[(k + 1) % 3], e);
      chain.insert(chain.begin(), tri[k]);
      chain.push_back(tri[(k + 1) % 3]);
      for (std::size_t i = 0; i + 1 < chain.size(); ++i)
        constraints.push_back({local_of(chain[i]), local_of(chain[i + 1]), s->line, s->plane, e});
    }
  }
  {
    // A segment with both ends on one edge of the cluster runs along it (a coplanar
    // overlap's side): that edge's chain already holds it, split at every point on it.
    // Inserted again, each would walk its whole run of points: n wedges, O(n^3) steps.
    auto along_an_edge = [&](const std::array<int, 2>& seg) {
      const auto [a0, a1] = edges_of(seg[0]);
      const auto [b0, b1] = edges_of(seg[1]);
      for (auto i = a0, j = b0; i != a1 && j != b1;) {
        if ((*i)[1] == (*j)[1]) return true;
        (*i)[1] < (*j)[1] ? ++i : ++j;
      }
      return false;
    };
    std::vector<std::array<int, 2>> segments;
    for (const int t : cluster)
      segments.insert(segments.end(), g.triangle_segments[t].begin(), g.triangle_segments[t].end());
    std::sort(segments.begin(), segments.end());
    segments.erase(std::unique(segments.begin(), segments.end()), segments.end());
    for (const auto& seg : segments) {
      if (along_an_edge(seg)) continue;
      const auto s = supports.of_segment(seg);
      constraints.push_back({local_of(seg[0]), local_of(seg[1]), s.line, s.plane, -1});
    }
  }
  for (const Constraint& c : constraints) lt.add_line(c.a, c.line), lt.add_line(c.b, c.line);

  std::vector<Point> tpis;  // local vertex 3 + ids.size() + k
  // The edges a TPI lies on by construction (a crossing with an edge's chain: where stage 4
  // left no point, which it should not), so that the flood below never crosses them.
  std::vector<std::array<int, 2>> tpi_edges;
  auto crossing = [&](int c1, int c2) {
    const auto& A = constraints[c1].support;
    const auto& B = constraints[c2].support;
    tpis.push_back(M::tpi(V[ref[0]], V[ref[1]], V[ref[2]], A[0], A[1], A[2], B[0], B[1], B[2]));
    tpi_edges.push_back({constraints[c1].edge, constraints[c2].edge});
    const int v = lt.add_vertex(tpis.back());
    lt.add_line(v, constraints[c1].line);
    lt.add_line(v, constraints[c2].line);
    return v;
  };
  // Every point before any constraint: two constraints may cross at a point of the graph,
  // which must not become a new TPI. Constraints in a shuffled order (fixed seed).
  {
    std::vector<int> order(ids.size());
    std::iota(order.begin(), order.end(), 3);
    for (const int l : local::spatial_order(lt, std::move(order), plane)) lt.insert_point(l);
  }
  for (const int c : local::shuffled_order(constraints.size()))
    lt.insert_constraint(constraints[c].a, constraints[c].b, c, crossing, constraints[c].line);

  // Each soup triangle's local triangles: a flood from a triangle at its first corner
  // whose corners lie in it, across every local edge that does not run along one of its
  // edges (both ends on that edge, known by construction: no predicate). Its edges are
  // chains of constraints, so no local triangle straddles them and those inside are
  // connected.
  const std::size_t nv = lt.pts.size(), nt = lt.tris.size();
  const int first_tpi = 3 + static_cast<int>(ids.size());
  const local::TrianglesAround at = local::triangles_around(lt);
  const std::vector<int>&first = at.first, &around = at.around;
  std::vector<std::array<int, 2>> covered;  // (local triangle, index in cluster)
  std::vector<int> tested_for(nv, -1), visited_for(nt, -1), stack;
  std::vector<std::uint8_t> edge_mask(nv, 0);
  for (std::size_t q = 0; q < cluster.size(); ++q) {
    const int t = cluster[q];
    const Tri& tri = soup.triangles[t];
    const std::array<int, 3>& e = g.triangle_edges[t];
    const int c[3] = {local_of(tri[0]), local_of(tri[1]), local_of(tri[2])};
    auto mask = [&](int v) {  // bit k: v lies on t's edge k
      if (tested_for[v] != static_cast<int>(q)) {
        tested_for[v] = static_cast<int>(q);
        std::uint8_t m = 0;
        if (v >= 3 && v < first_tpi)
          for (auto [i, end] = edges_of(ids[v - 3]); i != end; ++i)
            for (int k = 0; k < 3; ++k) m |= static_cast<std::uint8_t>(((*i)[1] == e[k]) << k);
        if (v >= first_tpi)
          for (const int on : tpi_edges[v - first_tpi])
            for (int k = 0; k < 3; ++k) m |= static_cast<std::uint8_t>((on == e[k]) << k);
        edge_mask[v] = m;
      }
      return edge_mask[v];
    };
    // The seed: around corner c[0], a triangle whose other corners lie in t (exact sides).
    const int s = lt.orient(c[0], c[1], c[2]);
    auto in = [&](int v) {
      return v == c[0] || v == c[1] || v == c[2] ||
             (lt.orient(c[0], c[1], v) * s >= 0 && lt.orient(c[1], c[2], v) * s >= 0 &&
              lt.orient(c[2], c[0], v) * s >= 0);
    };
    int seed_triangle = -1;
    for (int i = first[c[0]]; i < first[c[0] + 1] && seed_triangle < 0; ++i) {
      const auto& T = lt.tris[around[i]];
      if (in(T.v[0]) && in(T.v[1]) && in(T.v[2])) seed_triangle = around[i];
    }
    if (seed_triangle < 0) throw std::logic_error("triangulate: no local triangle at a corner of its triangle");
    visited_for[seed_triangle] = static_cast<int>(q);
    stack.assign(1, seed_triangle);
    while (!stack.empty()) {
      const int T = stack.back();
      stack.pop_back();
      covered.push_back({T, static_cast<int>(q)});
      const auto& L = lt.tris[T];
      for (int k = 0; k < 3; ++k) {
        const int nb = L.n[k];
        if (nb < 0 || visited_for[nb] == static_cast<int>(q)) continue;
        if (mask(L.v[local::next3(k)]) & mask(L.v[local::prev3(k)])) continue;  // along t's edge
        visited_for[nb] = static_cast<int>(q);
        stack.push_back(nb);
      }
    }
  }
  std::sort(covered.begin(), covered.end());

  // The pieces: each local triangle by the smallest soup triangle covering it, in its
  // orientation; TPIs renumbered per piece.
  std::vector<Piece<Point>> pieces(cluster.size());
  std::vector<int> same_turn(cluster.size());
  for (std::size_t q = 0; q < cluster.size(); ++q) {
    const Tri& tri = soup.triangles[cluster[q]];
    same_turn[q] = tritri::to_int(M::orient2d(V[tri[0]], V[tri[1]], V[tri[2]], plane)) == big_sign;
  }
  std::vector<std::map<std::vector<int>, int>> cover_index(cluster.size());
  std::vector<std::vector<int>> tpi_in_piece(cluster.size());
  std::vector<int> cover;
  for (std::size_t i = 0; i < covered.size();) {
    const int T = covered[i][0];
    cover.clear();
    for (; i < covered.size() && covered[i][0] == T; ++i) cover.push_back(cluster[covered[i][1]]);
    const int q = covered[i - cover.size()][1];  // the smallest (cluster is sorted)
    Piece<Point>& piece = pieces[q];
    Tri out;
    for (int k = 0; k < 3; ++k) {
      const int l = lt.tris[T].v[k];
      if (l < 3) throw std::logic_error("triangulate: a covered triangle at the enclosing triangle");
      if (l < first_tpi) {
        out[k] = ids[l - 3];
        continue;
      }
      auto& in_piece = tpi_in_piece[q];
      if (in_piece.empty()) in_piece.assign(tpis.size(), 0);
      int& slot = in_piece[l - first_tpi];
      if (slot == 0) piece.tpis.push_back(tpis[l - first_tpi]), slot = static_cast<int>(piece.tpis.size());
      out[k] = -slot;  // -1 - (slot - 1)
    }
    if (!same_turn[q]) std::swap(out[1], out[2]);
    piece.triangles.push_back(out);
    if (cover.size() == 1) {
      piece.covered_by.push_back(-1);
    } else {
      auto [it, fresh] = cover_index[q].emplace(cover, static_cast<int>(piece.covers.size()));
      if (fresh) piece.covers.push_back(cover);
      piece.covered_by.push_back(it->second);
    }
  }
  return pieces;
}

template std::vector<std::vector<int>> clusters_to_triangulate_whole(const IntersectionGraph&);
template std::vector<std::vector<int>> clusters_to_triangulate_whole(const BasicIntersectionGraph<ExactModel::Point>&);
template std::optional<std::vector<Piece<tritri::ImplicitPoint>>> split_cluster_of<DoubleModel>(
    const TriangleSoup&, const IntersectionGraph&, const std::vector<int>&);
template std::optional<std::vector<Piece<ExactModel::Point>>> split_cluster_of<ExactModel>(
    const BasicTriangleSoup<ExactModel::Vertex>&, const BasicIntersectionGraph<ExactModel::Point>&,
    const std::vector<int>&);

}  // namespace arrangements
