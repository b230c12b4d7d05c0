#include "stages/5_triangulate_triangle.h"

#include <algorithm>
#include <deque>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "models/double_model.h"
#include "models/exact_model.h"
#include "stages/5_local_triangulation.h"
#include "stages/5_insertion_order.h"
#include "stages/5_transverse_supports.h"
#include "support/bounding_box.h"

namespace arrangements {
namespace {

using local::LocalTriangle;

// The projection where triangle t is not degenerate, and t's orientation there: the
// dominant plane first (the best conditioned, so the filters decide most predicates),
// checked exactly, then the others in tritri's cyclic order.
template <class M>
std::pair<tritri::Plane, int> projection(const std::vector<typename M::Vertex>& V, const Tri& t) {
  const auto proj = M::projection(V[t[0]], V[t[1]], V[t[2]]);
  if (proj.second == 0) throw std::logic_error("triangulate: degenerate triangle");
  return proj;
}

// The coplanar partners covering each local triangle of t: (local triangle, index in
// g.coplanar_partners[t]) pairs, sorted. A triangle is covered by partner q when its three
// corners lie in q's closed triangle; q's edges inside t are constraints, so no local
// triangle straddles q's boundary, and the triangles in q form a connected set (they tile
// the convex q and t's intersection).
// So each partner is found from one seed triangle by a flood fill: a neighbour across an
// edge is in q when its third corner is. The seed is a triangle around a vertex in closed
// q and t, when their intersection has an area (any such vertex has one: the intersection
// is convex, so it fills a wedge of positive angle at the vertex): q's corners that are
// vertices of t, or the vertices of t's edges in closed q, which are a run along each edge
// found by binary search (each side of q's edge lines is a linear function along t's
// edge). An intersection with an area touches t's boundary or holds q's corners; where it
// meets t's edge, its ends are points of the pair's classification, vertices here.
// Cost: O(log k) predicates per partner and edge, plus the covered triangles and their
// neighbours, not one test per partner and triangle (two coplanar fans of n long thin
// triangles: O(n) partners and regions in every triangle, cubic in all).
constexpr std::size_t kSearchFrom = 16;  // longer edges are searched, shorter ones scanned
constexpr std::size_t kDirectUpTo = 256;  // (local triangles) x (partners) tested pair by pair
template <class M>
std::vector<std::array<int, 2>> partner_covers(const BasicTriangleSoup<typename M::Vertex>& soup,
                                               const BasicIntersectionGraph<typename M::Point>& g, int t,
                                               tritri::Plane plane, local::LocalTriangulation<M>& lt,
                                               const std::array<std::vector<int>, 3>& chain,
                                               const std::map<int, int>& local_of) {
  std::vector<std::array<int, 2>> covered;
  const auto& partners = g.coplanar_partners[t];
  if (partners.empty()) return covered;
  const auto& V = soup.vertices;
  const Tri& tri = soup.triangles[t];
  const std::size_t nv = lt.pts.size(), nt = lt.tris.size();
  // Few partners and triangles: each pair tested directly (no seeds, no flood).
  const bool direct = nt * partners.size() <= kDirectUpTo;
  // Triangles around each vertex (CSR), for the seeds.
  const local::TrianglesAround at = direct ? local::TrianglesAround{} : local::triangles_around(lt);
  const std::vector<int>&first = at.first, &around = at.around;
  std::vector<typename M::Box> box(nv);
  std::vector<char> has_box(nv, 0);
  auto box_of = [&](int v) -> const typename M::Box& {
    if (!has_box[v]) {
      box[v] = M::box(lt.pts[v]);
      has_box[v] = 1;
    }
    return box[v];
  };
  std::vector<int> tested_for(nv, -1), visited_for(direct ? 0 : nt, -1), stack;  // the flood's marks
  std::vector<char> inside(nv, 0);
  for (std::size_t qi = 0; qi < partners.size(); ++qi) {
    const int q = static_cast<int>(qi);
    const Tri& u = soup.triangles[partners[qi]];
    const int sign = tritri::to_int(M::orient2d(V[u[0]], V[u[1]], V[u[2]], plane));
    const BoundingBox ubox = triangle_bounds<M>(V, u);
    const Vec3 &lo = ubox.lo, &hi = ubox.hi;
    // The side of u's edge line e that local vertex v lies on, positive inside u.
    auto side = [&](int e, int v) {
      int s = M::side_bounded(V[u[e]], V[u[(e + 1) % 3]], box_of(v), plane);
      if (s == tritri::kUndecided)
        s = M::side_of_line(g.points[u[e]], g.points[u[(e + 1) % 3]], lt.pts[v], plane, &g.points[u[(e + 2) % 3]]);
      return sign * s;
    };
    auto in_partner = [&](int v) {  // v in u's closed triangle, once per (q, v)
      if (tested_for[v] == q) return inside[v] == 1;
      tested_for[v] = q;
      const typename M::Box& b = box_of(v);
      bool in = true;
      for (int c = 0; c < 3 && in; ++c) in = b[c].hi >= lo[c] && b[c].lo <= hi[c];  // boxes apart: outside
      for (int e = 0; e < 3 && in; ++e) in = side(e, v) >= 0;
      inside[v] = in;
      return in;
    };
    if (direct) {
      for (std::size_t T = 0; T < nt; ++T) {
        const LocalTriangle& L = lt.tris[T];
        if (in_partner(L.v[0]) && in_partner(L.v[1]) && in_partner(L.v[2])) covered.push_back({static_cast<int>(T), q});
      }
      continue;
    }
    // A vertex in closed u: one of u's corners, or a vertex of a run along t's edges.
    int seed_vertex = -1;
    for (int k = 0; k < 3 && seed_vertex < 0; ++k) {
      const auto it = local_of.find(u[k]);
      if (it != local_of.end()) seed_vertex = it->second;
    }
    for (int f = 0; f < 3 && seed_vertex < 0; ++f) {
      const std::vector<int>& c = chain[f];
      if (c.size() <= kSearchFrom) {  // a short edge: its vertices in turn
        for (std::size_t i = 0; i < c.size() && seed_vertex < 0; ++i)
          if (in_partner(c[i])) seed_vertex = c[i];
        continue;
      }
      std::size_t lo = 0, hi = c.size();
      for (int e = 0; e < 3 && lo < hi; ++e) {
        auto corner_side = [&](int k) {
          return sign * tritri::to_int(M::orient2d(V[u[e]], V[u[(e + 1) % 3]], V[tri[k]], plane));
        };
        const int s0 = corner_side(f), s1 = corner_side((f + 1) % 3);
        if (s0 >= 0 && s1 >= 0) continue;
        if (s0 < 0 && s1 < 0) {
          lo = hi;
          break;
        }
        std::size_t a = lo, b = hi;  // the first index where the sign turns
        while (a < b) {
          const std::size_t mid = a + (b - a) / 2;
          if ((side(e, c[mid]) >= 0) == (s0 < 0))
            b = mid;
          else
            a = mid + 1;
        }
        (s0 >= 0 ? hi : lo) = a;
      }
      if (lo < hi) seed_vertex = c[lo];
    }
    if (seed_vertex < 0) continue;
    int seed = -1;
    for (int i = first[seed_vertex]; i < first[seed_vertex + 1] && seed < 0; ++i) {
      const LocalTriangle& T = lt.tris[around[i]];
      if (in_partner(T.v[0]) && in_partner(T.v[1]) && in_partner(T.v[2])) seed = around[i];
    }
    if (seed < 0) continue;  // q and t meet in no area
    visited_for[seed] = q;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int T = stack.back();
      stack.pop_back();
      covered.push_back({T, q});
      const LocalTriangle& L = lt.tris[T];
      for (int k = 0; k < 3; ++k) {
        const int n = L.n[k];
        if (n < 0 || visited_for[n] == q) continue;
        visited_for[n] = q;
        const LocalTriangle& N = lt.tris[n];
        int w = -1;
        for (int j = 0; j < 3; ++j)
          if (N.v[j] != L.v[local::next3(k)] && N.v[j] != L.v[local::prev3(k)]) w = N.v[j];
        if (in_partner(w)) stack.push_back(n);
      }
    }
  }
  std::sort(covered.begin(), covered.end());
  return covered;
}

}  // namespace

template <class M>
std::vector<int> points_along_edge(const BasicIntersectionGraph<typename M::Point>& g, int from, int to, int e) {
  std::vector<int> on_edge = g.edge_points[e];
  std::vector<std::pair<typename M::Key, int>> keyed(on_edge.size());
  for (std::size_t i = 0; i < on_edge.size(); ++i) keyed[i] = {M::key(g.points[on_edge[i]]), on_edge[i]};
  std::sort(keyed.begin(), keyed.end(), [&](const auto& x, const auto& y) {
    const int c = M::compare(g.points[x.second], x.first, g.points[y.second], y.first);
    return c != 0 ? c < 0 : x.second < y.second;
  });
  for (std::size_t i = 0; i < on_edge.size(); ++i) on_edge[i] = keyed[i].second;
  const auto &p = g.points[from], &q = g.points[to];
  if (!on_edge.empty() && M::compare(p, M::key(p), q, M::key(q)) > 0) std::reverse(on_edge.begin(), on_edge.end());
  return on_edge;
}

template <class M>
Piece<typename M::Point> split_triangle_of(const BasicTriangleSoup<typename M::Vertex>& soup,
                                           const BasicIntersectionGraph<typename M::Point>& g, int t) {
  using Vertex = typename M::Vertex;
  using Point = typename M::Point;
  const std::vector<Vertex>& V = soup.vertices;
  const Tri& tri = soup.triangles[t];
  const auto [plane, sign] = projection<M>(V, tri);
  // Doubles: one triangulation object per thread, reset for each triangle so that its memory
  // is reused (allocations were about a tenth of triangulation's time); one that grew large
  // is dropped at the end, so that no thread keeps much. The exact model builds its own:
  // CGAL's points are not kept in thread storage, destroyed at thread exit, possibly after
  // CGAL's own statics.
  using Triangulation = local::LocalTriangulation<M>;
  std::optional<Triangulation> own;
  Triangulation* reused = nullptr;
  if constexpr (std::is_same_v<M, DoubleModel>) {
    thread_local Triangulation kept(plane, sign, V[tri[0]]);
    kept.reset(plane, sign, V[tri[0]]);
    reused = &kept;
  } else {
    reused = &own.emplace(plane, sign, V[tri[0]]);
  }
  Triangulation& lt = *reused;

  // Local vertices: corners, edge points, interior points (graph ids in `global`).
  std::vector<int> global;
  std::map<int, int> local_of;
  auto add = [&](int id) {
    auto [it, fresh] = local_of.emplace(id, static_cast<int>(global.size()));
    if (fresh) {
      global.push_back(id);
      lt.add_vertex(g.points[id]);
    }
    return it->second;
  };
  const int c0 = add(tri[0]), c1 = add(tri[1]), c2 = add(tri[2]);
  lt.start(c0, c1, c2);
  // Edge points in order along each edge (points_along_edge); an edge point splits the
  // sub-edge between its inserted neighbours in that order (no predicate).
  // chain[k]: the local ids along edge k, corners included; rank_of[l]: (edge, rank) of
  // local id l on its edge, edge -1 for corners and interior points.
  std::array<std::vector<int>, 3> chain;
  std::vector<std::array<int, 2>> rank_of;
  for (int k = 0; k < 3; ++k) {
    const std::vector<int> on_edge = points_along_edge<M>(g, tri[k], tri[(k + 1) % 3], g.triangle_edges[t][k]);
    chain[k].push_back(local_of.at(tri[k]));
    for (int x : on_edge) {
      const int l = add(x);
      rank_of.resize(global.size(), {-1, 0});
      rank_of[l] = {k, static_cast<int>(chain[k].size())};
      chain[k].push_back(l);
    }
    chain[k].push_back(local_of.at(tri[(k + 1) % 3]));
  }
  for (int x : g.triangle_points[t]) add(x);
  rank_of.resize(global.size(), {-1, 0});
  const std::size_t points = global.size();

  // Constraints, each with a plane through its line that is transverse to t; line_of[s]
  // names the line (t's plane meets that plane in it), the same for segments that chose
  // the same plane.
  const auto& segs = g.triangle_segments[t];
  std::vector<std::array<Vertex, 3>> support(segs.size());
  std::vector<int> line_of(segs.size());
  TransverseSupports<M> supports(soup, g, tri);
  for (std::size_t s = 0; s < segs.size(); ++s) {
    const auto found = supports.of_segment(segs[s]);
    support[s] = found.plane;
    line_of[s] = found.line;
  }
  Piece<Point> piece;
  auto crossing = [&](int c1, int c2) {
    const auto& A = support[c1];
    const auto& B = support[c2];
    const Point x = M::tpi(V[tri[0]], V[tri[1]], V[tri[2]], A[0], A[1], A[2], B[0], B[1], B[2]);
    piece.tpis.push_back(x);
    global.push_back(-static_cast<int>(piece.tpis.size()));
    const int v = lt.add_vertex(x);
    lt.add_line(v, line_of[c1]);
    lt.add_line(v, line_of[c2]);
    return v;
  };
  // With few constraints: every edge point, along each edge, then the interior points in
  // local order, then the constraints in list order (the triangulation the rounding
  // ladder's tests were built on, round_mesh.h). With many (a triangle under a coplanar
  // fan, a large face crossed by a fine mesh), inserting every edge point first makes fans
  // from the corners that each constraint of a strip crosses whole, with quadratic flips
  // (TwoCylinders: 1.5 M flips, 26 M queue steps); instead the interior points, then the
  // constraints in a shuffled order (a fixed seed: deterministic), each right after its
  // endpoints, then the other edge points (0.1 M flips, 0.14 M steps). An edge point then
  // splits only the region between the constraints around it, so a constraint crosses few
  // edges (a randomized incremental construction). Interior points must come before the
  // constraints: two constraints may cross at one of them, which must not become a new
  // TPI; two constraints inside the closed triangle never cross on its boundary.
  constexpr std::size_t kIncrementalFrom = 32;
  auto endpoints = [&](std::size_t s) {
    auto a = local_of.find(segs[s][0]), b = local_of.find(segs[s][1]);
    if (a == local_of.end() || b == local_of.end())
      throw std::logic_error("triangulate: a constraint's endpoint is not a point of its triangle");
    return std::pair<int, int>{a->second, b->second};
  };
  for (std::size_t s = 0; s < segs.size(); ++s) {
    const auto [a, b] = endpoints(s);
    lt.add_line(a, line_of[s]);
    lt.add_line(b, line_of[s]);
  }
  if (segs.size() < kIncrementalFrom) {
    for (int k = 0; k < 3; ++k)
      for (std::size_t i = 1; i + 1 < chain[k].size(); ++i)
        lt.split_boundary_edge(chain[k][i - 1], chain[k].back(), chain[k][i]);
    for (std::size_t l = 0; l < points; ++l)
      if (rank_of[l][0] < 0 && l != static_cast<std::size_t>(c0) && l != static_cast<std::size_t>(c1) &&
          l != static_cast<std::size_t>(c2))
        lt.insert_point(static_cast<int>(l));
    for (std::size_t s = 0; s < segs.size(); ++s) {
      const auto [a, b] = endpoints(s);
      lt.insert_constraint(a, b, static_cast<int>(s), crossing, line_of[s]);
    }
  } else {
    std::array<std::set<int>, 3> inserted_ranks;  // per edge, the ranks inserted so far
    for (int k = 0; k < 3; ++k) inserted_ranks[k] = {0, static_cast<int>(chain[k].size()) - 1};
    std::vector<char> inserted(points, 0);
    inserted[c0] = inserted[c1] = inserted[c2] = 1;
    auto insert = [&](int l) {
      if (inserted[l]) return;
      inserted[l] = 1;
      const auto [k, r] = rank_of[l];
      if (k < 0) {
        lt.insert_point(l);
        return;
      }
      const auto next = inserted_ranks[k].upper_bound(r);
      lt.split_boundary_edge(chain[k][*std::prev(next)], chain[k][*next], l);
      inserted_ranks[k].insert(next, r);
    };
    std::vector<int> interior;  // corners excluded
    for (std::size_t l = 3; l < rank_of.size(); ++l)
      if (rank_of[l][0] < 0) interior.push_back(static_cast<int>(l));
    for (const int l : local::spatial_order(lt, std::move(interior), plane)) insert(l);
    for (const int s : local::shuffled_order(segs.size())) {
      const auto [a, b] = endpoints(static_cast<std::size_t>(s));
      insert(a);
      insert(b);
      lt.insert_constraint(a, b, s, crossing, line_of[static_cast<std::size_t>(s)]);
    }
    for (std::size_t l = 0; l < points; ++l) insert(static_cast<int>(l));
  }

  // Coplanar partners: which of them cover each local triangle (partner_covers), each
  // triangle emitted once, by the smallest triangle covering it.
  const auto& partners = g.coplanar_partners[t];
  const std::vector<std::array<int, 2>> covered = partner_covers<M>(soup, g, t, plane, lt, chain, local_of);
  std::map<std::vector<int>, int> cover_index;
  std::vector<int> cover;
  for (std::size_t T = 0, i = 0; T < lt.tris.size(); ++T) {
    cover.clear();
    for (; i < covered.size() && covered[i][0] == static_cast<int>(T); ++i) cover.push_back(partners[covered[i][1]]);
    if (!cover.empty() && cover.front() < t) continue;  // emitted by the smallest covering triangle
    const LocalTriangle& L = lt.tris[T];
    piece.triangles.push_back({global[L.v[0]], global[L.v[1]], global[L.v[2]]});
    if (cover.empty()) {
      piece.covered_by.push_back(-1);
    } else {
      cover.insert(cover.begin(), t);
      auto [it, fresh] = cover_index.emplace(cover, static_cast<int>(piece.covers.size()));
      if (fresh) piece.covers.push_back(cover);
      piece.covered_by.push_back(it->second);
    }
  }
  constexpr std::size_t kKeepTriangles = 1 << 14;
  if (lt.tris.capacity() > kKeepTriangles) lt = Triangulation(plane, sign, V[tri[0]]);
  return piece;
}

template std::vector<int> points_along_edge<DoubleModel>(const IntersectionGraph&, int, int, int);
template std::vector<int> points_along_edge<ExactModel>(const BasicIntersectionGraph<ExactModel::Point>&, int, int,
                                                        int);
template Piece<tritri::ImplicitPoint> split_triangle_of<DoubleModel>(const TriangleSoup&, const IntersectionGraph&,
                                                                     int);
template Piece<ExactModel::Point> split_triangle_of<ExactModel>(const BasicTriangleSoup<ExactModel::Vertex>&,
                                                                const BasicIntersectionGraph<ExactModel::Point>&, int);

}  // namespace arrangements
