#include "stages/4_share_coplanar.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>

#include <tritri/location.h>

#include "models/double_model.h"
#include "models/exact_model.h"
#include "stages/3_pair_intersection.h"
#include "support/bounding_box.h"
#include "support/sort_unique.h"

namespace arrangements {
namespace {

// Where point x (in t's plane) lies in closed triangle t, which has orientation
// `orientation` != 0 in `plane`. A vertex of t is recognised by its id; a point at a
// vertex's position with another id cannot occur (points are deduplicated) and is
// reported Outside. The three edge signs are first asked of a filter on `box`, x's
// certified box (M::box; M::side_bounded: a few flops, decides unless x is near the edge's line);
// only the undecided ones go to M::side_of_line.
template <class M>
Location locate(const std::vector<typename M::Vertex>& V, const std::vector<typename M::Point>& P, const Tri& t,
                tritri::Plane plane, int orientation, int x, const typename M::Box& box) {
  for (int k = 0; k < 3; ++k)
    if (t[k] == x) return Location::vertex(k);
  int s[3];
  for (int k = 0; k < 3; ++k) {
    s[k] = M::side_bounded(V[t[k]], V[t[(k + 1) % 3]], box, plane);
    if (s[k] != tritri::kUndecided && s[k] * orientation < 0) return Location::outside();
  }
  for (int k = 0; k < 3; ++k) {
    if (s[k] == tritri::kUndecided)
      s[k] = M::side_of_line(P[t[k]], P[t[(k + 1) % 3]], P[x], plane, &P[t[(k + 2) % 3]]);
    s[k] *= orientation;
    if (s[k] < 0) return Location::outside();
  }
  const Location l = tritri::location_from_edge_signs(s);
  return l.kind == Location::Vertex ? Location::outside() : l;
}

struct Additions {
  std::vector<int> inside;
  std::vector<std::array<int, 2>> on_edge;  // (edge id, point)
  std::vector<std::array<int, 2>> segments;
};

// Edges with more points than this are searched for their run inside a triangle; shorter
// ones are visited whole (cheaper than the 6 exact signs at their ends).
constexpr std::size_t kSearchFrom = 16;

// along[e]: the points of edge e in their order from its first vertex g.edges[e][0] to its
// second (M::compare is an exact order, monotone along any line), for the edges of
// triangles that have coplanar partners with more than kSearchFrom points (empty for the
// others).
template <class M>
std::vector<std::vector<int>> points_along_edges(const std::vector<Tri>& F,
                                                 const BasicIntersectionGraph<typename M::Point>& g) {
  std::vector<char> wanted(g.edges.size(), 0);
  for (std::size_t t = 0; t < F.size(); ++t)
    if (!g.coplanar_partners[t].empty())
      for (int k = 0; k < 3; ++k) wanted[g.triangle_edges[t][k]] = 1;
  std::vector<std::vector<int>> along(g.edges.size());
  tbb::parallel_for(std::size_t{0}, g.edges.size(), [&](std::size_t e) {
    if (!wanted[e] || g.edge_points[e].size() <= kSearchFrom) return;
    std::vector<std::pair<typename M::Key, int>> keyed;
    keyed.reserve(g.edge_points[e].size());
    for (int x : g.edge_points[e]) keyed.emplace_back(M::key(g.points[x]), x);
    std::sort(keyed.begin(), keyed.end(), [&](const auto& x, const auto& y) {
      const int c = M::compare(g.points[x.second], x.first, g.points[y.second], y.first);
      return c != 0 ? c < 0 : x.second < y.second;
    });
    std::vector<int>& out = along[e];
    out.reserve(keyed.size());
    for (const auto& k : keyed) out.push_back(k.second);
    const auto& from = g.points[g.edges[e][0]];
    const auto& to = g.points[g.edges[e][1]];
    if (M::compare(from, M::key(from), to, M::key(to)) > 0) std::reverse(out.begin(), out.end());
  });
  return along;
}

}  // namespace

template <class M>
void share_coplanar(const std::vector<typename M::Vertex>& V, const std::vector<Tri>& F,
                    BasicIntersectionGraph<typename M::Point>& g) {
  std::vector<Additions> add(F.size());
  const std::vector<std::vector<int>> along = points_along_edges<M>(F, g);
  // Per thread, per point: the triangle that last listed it, and what was found there.
  struct Scratch {
    std::vector<int> seen;
    std::vector<char> is_point, inside_closed;
    std::vector<int> ids;
    std::vector<std::array<int, 2>> of_partner;  // (partner index, point) for the segment look-up
    void resize(std::size_t points) {
      seen.assign(points, -1);
      is_point.assign(points, 0);
      inside_closed.assign(points, 0);
    }
  };
  tbb::enumerable_thread_specific<Scratch> scratch;
  // Every point's certified box, once (a point is listed by every triangle whose partner
  // holds it).
  std::vector<typename M::Box> boxes(g.points.size());
  tbb::parallel_for(std::size_t{0}, g.points.size(), [&](std::size_t x) { boxes[x] = M::box(g.points[x]); });
  tbb::parallel_for(std::size_t{0}, F.size(), [&](std::size_t t) {
    const auto& partners = g.coplanar_partners[t];
    if (partners.empty()) return;
    const Tri& tri = F[t];
    // (Named variables, not a structured binding: the lambdas below capture them.)
    const std::pair<tritri::Plane, int> proj = M::projection(V[tri[0]], V[tri[1]], V[tri[2]]);
    const tritri::Plane plane = proj.first;
    const int orientation = proj.second;
    Additions& a = add[t];
    const BoundingBox tbox = triangle_bounds<M>(V, tri);
    const Vec3 &lo = tbox.lo, &hi = tbox.hi;
    Scratch& sc = scratch.local();
    if (sc.seen.empty()) sc.resize(g.points.size());
    sc.ids.clear();
    sc.of_partner.clear();
    // Each id once (stamped with t, no sort); whether it is one of a partner's points, or
    // only a corner (a segment end).
    auto visit = [&](int x, bool point, int q) {
      sc.of_partner.push_back({q, x});
      if (sc.seen[x] != static_cast<int>(t)) {
        sc.seen[x] = static_cast<int>(t);
        sc.is_point[x] = point;
        sc.ids.push_back(x);
      } else if (point) {
        sc.is_point[x] = 1;
      }
    };
    // The side of t's edge line k that x lies on, positive inside t.
    auto side = [&](int k, int x) {
      int s = M::side_bounded(V[tri[k]], V[tri[(k + 1) % 3]], boxes[x], plane);
      if (s == tritri::kUndecided)
        s = M::side_of_line(g.points[tri[k]], g.points[tri[(k + 1) % 3]], g.points[x], plane,
                            &g.points[tri[(k + 2) % 3]]);
      return s * orientation;
    };
    auto vertex_side = [&](int k, int v) {
      return orientation * tritri::to_int(M::orient2d(V[tri[k]], V[tri[(k + 1) % 3]], V[v], plane));
    };
    for (std::size_t q = 0; q < partners.size(); ++q) {
      const int u = partners[q];
      const int qi = static_cast<int>(q);
      for (int k = 0; k < 3; ++k) visit(F[u][k], false, qi);
      for (int x : g.triangle_points[u]) visit(x, true, qi);
      for (int k = 0; k < 3; ++k) {
        const int e = g.triangle_edges[u][k];
        const std::vector<int>& pts = g.edge_points[e].size() > kSearchFrom ? along[e] : g.edge_points[e];
        if (pts.empty()) continue;
        // (An edge two partners share is searched for both: the segment look-up below
        // goes by partner.)
        // The run of pts in closed t: for each edge line of t, the side is a linear
        // function along the edge, so its sign changes at most once between the edge's
        // ends; a binary search finds where.
        std::size_t first = 0, last = pts.size();
        // A short list is simply visited whole (its points outside t are located as such).
        for (int l = 0; l < 3 && first < last && pts.size() > kSearchFrom; ++l) {
          const int s0 = vertex_side(l, g.edges[e][0]), s1 = vertex_side(l, g.edges[e][1]);
          if (s0 >= 0 && s1 >= 0) continue;
          if (s0 < 0 && s1 < 0) {
            first = last;
            break;
          }
          if (s0 >= 0) {  // inside up to the first point strictly outside
            std::size_t lo_i = first, hi_i = last;
            while (lo_i < hi_i) {
              const std::size_t mid = lo_i + (hi_i - lo_i) / 2;
              if (side(l, pts[mid]) < 0)
                hi_i = mid;
              else
                lo_i = mid + 1;
            }
            last = lo_i;
          } else {  // inside from the first point not strictly outside
            std::size_t lo_i = first, hi_i = last;
            while (lo_i < hi_i) {
              const std::size_t mid = lo_i + (hi_i - lo_i) / 2;
              if (side(l, pts[mid]) >= 0)
                hi_i = mid;
              else
                lo_i = mid + 1;
            }
            first = lo_i;
          }
        }
        for (std::size_t i = first; i < last; ++i) visit(pts[i], true, qi);
      }
    }
    for (int x : sc.ids) {
      // A box around the point disjoint from t's box: outside, with no predicate.
      const typename M::Box& b = boxes[x];
      bool apart = false;
      for (int c = 0; c < 3; ++c) apart = apart || b[c].hi < lo[c] || b[c].lo > hi[c];
      const Location where = apart ? Location::outside() : locate<M>(V, g.points, tri, plane, orientation, x, b);
      sc.inside_closed[x] = where.kind != Location::Outside;
      if (!sc.is_point[x]) continue;
      if (where.kind == Location::Interior)
        a.inside.push_back(x);
      else if (where.kind == Location::Edge)
        a.on_edge.push_back({g.triangle_edges[t][where.id], x});
    }
    // u's segments with both ends in closed t: from each end found, the segments it starts
    // (each segment is listed by its smaller id first, and sorted).
    for (const auto& [q, x] : sc.of_partner) {
      if (!sc.inside_closed[x]) continue;
      const auto& segs = g.triangle_segments[partners[static_cast<std::size_t>(q)]];
      auto it = std::lower_bound(segs.begin(), segs.end(), std::array<int, 2>{x, -1});
      for (; it != segs.end() && (*it)[0] == x; ++it) {
        const int y = (*it)[1];
        if (sc.seen[y] == static_cast<int>(t) && sc.inside_closed[y]) a.segments.push_back(*it);
      }
    }
  });
  std::vector<int> edges;
  for (std::size_t t = 0; t < F.size(); ++t) {
    if (!add[t].inside.empty()) {
      g.triangle_points[t].insert(g.triangle_points[t].end(), add[t].inside.begin(), add[t].inside.end());
      sort_unique(g.triangle_points[t]);
    }
    for (const auto& e : add[t].on_edge) {
      g.edge_points[e[0]].push_back(e[1]);
      edges.push_back(e[0]);
    }
    if (!add[t].segments.empty()) {
      g.triangle_segments[t].insert(g.triangle_segments[t].end(), add[t].segments.begin(), add[t].segments.end());
      sort_unique(g.triangle_segments[t]);
    }
  }
  sort_unique(edges);
  for (int e : edges) sort_unique(g.edge_points[e]);
}

template void share_coplanar<DoubleModel>(const std::vector<Vec3>&, const std::vector<Tri>&, IntersectionGraph&);
template void share_coplanar<ExactModel>(const std::vector<ExactModel::Vertex>&, const std::vector<Tri>&,
                                         BasicIntersectionGraph<ExactModel::Point>&);

}  // namespace arrangements
