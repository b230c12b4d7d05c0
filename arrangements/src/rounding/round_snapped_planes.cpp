// snap_near_coplanar_faces (round_snapped_planes.h): near-coplanar layers of the input made
// coplanar, the input kept otherwise.
#include "rounding/round_snapped_planes.h"

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

#include <tritri/box_pairs.h>

#include "arrangements/as_input.h"
#include "rounding/rounding_grid.h"

namespace arrangements {
namespace {

using Q = CGAL::Gmpq;
using QVec = std::array<Q, 3>;

int find(std::vector<int>& parent, int v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

QVec minus(const QVec& a, const QVec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
QVec cross(const QVec& a, const QVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Q dot(const QVec& a, const QVec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

using I = CGAL::Interval_nt<false>;
using IVec = std::array<I, 3>;

// The normal (b - a) x (c - a) of a triangle, in intervals (rounding set upwards by the caller).
IVec interval_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
  const IVec u{I(b[0]) - a[0], I(b[1]) - a[1], I(b[2]) - a[2]};
  const IVec v{I(c[0]) - a[0], I(c[1]) - a[1], I(c[2]) - a[2]};
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

// Whether p lies within delta of the plane of (a, b, c), a proper triangle with interval
// normal n: an interval filter, then exact rationals when the intervals cannot tell.
bool within_plane(const Vec3& a, const Vec3& b, const Vec3& c, const IVec& n, const Vec3& p, double delta) {
  {
    CGAL::Protect_FPU_rounding<true> rounding_up;
    const I h = n[0] * (I(p[0]) - a[0]) + n[1] * (I(p[1]) - a[1]) + n[2] * (I(p[2]) - a[2]);
    const I bound = I(delta) * delta * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const CGAL::Uncertain<bool> near = CGAL::square(h) <= bound;
    if (CGAL::is_certain(near)) return CGAL::get_certain(near);
  }
  const QVec qa = to_exact(a);
  const QVec qn = cross(minus(to_exact(b), qa), minus(to_exact(c), qa));
  const Q h = dot(qn, minus(to_exact(p), qa));
  return h * h <= Q(delta) * Q(delta) * dot(qn, qn);
}

struct Plane {
  QVec n;
  Q d;  // n . x = d
};

// The point of the planes (one, two or three) nearest to p: p projected onto the plane, onto
// the line of two, or the point of three; nullopt when two or three are parallel.
std::optional<QVec> onto_planes(const std::vector<const Plane*>& planes, const QVec& p) {
  if (planes.size() == 1) {
    const Plane& e = *planes[0];
    const Q s = (dot(e.n, p) - e.d) / dot(e.n, e.n);
    return QVec{p[0] - s * e.n[0], p[1] - s * e.n[1], p[2] - s * e.n[2]};
  }
  if (planes.size() == 2) {
    const Plane &e = *planes[0], &f = *planes[1];
    const QVec u = cross(e.n, f.n);
    const Q uu = dot(u, u);
    if (uu == 0) return std::nullopt;
    // x0 = ((d_e n_f - d_f n_e) x u) / |u|^2 lies on both planes; then along u to nearest p.
    const QVec w{e.d * f.n[0] - f.d * e.n[0], e.d * f.n[1] - f.d * e.n[1], e.d * f.n[2] - f.d * e.n[2]};
    const QVec wu = cross(w, u);
    const QVec x0{wu[0] / uu, wu[1] / uu, wu[2] / uu};
    const Q t = dot(u, minus(p, x0)) / uu;
    return QVec{x0[0] + t * u[0], x0[1] + t * u[1], x0[2] + t * u[2]};
  }
  const Plane &e = *planes[0], &f = *planes[1], &g = *planes[2];
  const QVec fg = cross(f.n, g.n), ge = cross(g.n, e.n), ef = cross(e.n, f.n);
  const Q det = dot(e.n, fg);
  if (det == 0) return std::nullopt;
  QVec x;
  for (int k = 0; k < 3; ++k) x[k] = (e.d * fg[k] + f.d * ge[k] + g.d * ef[k]) / det;
  return x;
}

// Groups that lie on the plane of a neighbouring layered group join it. Links need each
// triangle within delta of the other's plane, and the plane of a small triangle tilts with
// its rounding errors: a layer linked to a large face only through small triangles, or a
// small layered group beside a large one, stays a group of its own with a plane of its own.
// Two such planes nearly parallel put a vertex of both on a line far off (it stays), or a
// vertex of one off the other, and the layers cross again. So a group r takes a group g
// whose boxes overlap one of its own (a candidate pair) when every corner of every triangle
// of g lies within delta of r's plane (the plane of r's anchor, the larger one when both are
// layered); the joined group keeps r's anchor and is layered. Repeated until nothing joins:
// each join leaves one group fewer.
void join_groups_on_planes(const std::vector<Vec3>& V, const std::vector<Tri>& F,
                           const std::vector<std::pair<int, int>>& pairs, const std::vector<IVec>& normal,
                           double delta, std::vector<int>& parent, std::vector<char>& layered,
                           std::vector<int>& anchor, std::vector<double>& size) {
  auto on_plane_of = [&](int a, int t) {
    for (int k = 0; k < 3; ++k)
      if (!within_plane(V[F[a][0]], V[F[a][1]], V[F[a][2]], normal[a], V[F[t][k]], delta)) return false;
    return true;
  };
  std::vector<std::vector<int>> members(F.size());
  for (int t = 0; t < static_cast<int>(F.size()); ++t) members[find(parent, t)].push_back(t);
  for (bool joined = true; joined;) {
    joined = false;
    for (const auto& [s, t] : pairs) {
      int r = find(parent, s), g = find(parent, t);
      if (r == g || (!layered[r] && !layered[g])) continue;
      if (!layered[r] || (layered[g] && size[g] > size[r])) std::swap(r, g);
      if (!std::all_of(members[g].begin(), members[g].end(), [&](int u) { return on_plane_of(anchor[r], u); }))
        continue;
      const int root = std::min(r, g), other = std::max(r, g);
      parent[other] = root;
      layered[root] = 1;
      anchor[root] = anchor[r];
      size[root] = size[r];
      anchor[other] = -1;
      std::vector<int>& into = members[root];
      std::vector<int>& from = members[other];
      into.insert(into.end(), from.begin(), from.end());
      std::vector<int>().swap(from);
      joined = true;
    }
  }
}

}  // namespace

SnappedPlanes snap_near_coplanar_faces(const TriangleSoup& input, double delta, int threads, bool contacts) {
  const std::vector<Vec3>& V = input.vertices;
  const std::vector<Tri>& F = input.triangles;
  const int nf = static_cast<int>(F.size());
  SnappedPlanes out;
  out.soup = to_exact(input);
  out.soup.polygon.clear();

  // Candidates: triangles whose boxes, widened by delta (rounded outwards), overlap.
  std::vector<Vec3> lo(V.size()), hi(V.size());
  for (std::size_t v = 0; v < V.size(); ++v)
    for (int k = 0; k < 3; ++k) {
      lo[v][k] = std::nextafter(V[v][k] - delta, -std::numeric_limits<double>::infinity());
      hi[v][k] = std::nextafter(V[v][k] + delta, std::numeric_limits<double>::infinity());
    }
  const std::vector<std::pair<int, int>> pairs = tritri::overlapping_triangle_pairs(lo, hi, F, threads);
  // Each triangle's interval normal, computed once for all its tests; a triangle is proper
  // when its exact normal is not zero (decided by the intervals when they exclude zero).
  std::vector<IVec> normal(F.size());
  std::vector<char> is_proper(F.size());
  tbb::parallel_for(0, nf, [&](int t) {
    {
      CGAL::Protect_FPU_rounding<true> rounding_up;
      normal[t] = interval_normal(V[F[t][0]], V[F[t][1]], V[F[t][2]]);
    }
    const IVec& m = normal[t];
    if (!m[0].do_overlap(0) || !m[1].do_overlap(0) || !m[2].do_overlap(0)) {
      is_proper[t] = 1;
      return;
    }
    const QVec a = to_exact(V[F[t][0]]);
    const QVec n = cross(minus(to_exact(V[F[t][1]]), a), minus(to_exact(V[F[t][2]]), a));
    is_proper[t] = n[0] != 0 || n[1] != 0 || n[2] != 0;
  });
  // 0: no link; 1: near-coplanar neighbours (a shared corner); 2: near-coplanar layers.
  std::vector<char> link(pairs.size(), 0);
  // With contacts: bit k (k < 3) when corner k of the first triangle touches the second's
  // plane, bit 3 + k when corner k of the second touches the first's.
  std::vector<unsigned char> touch(pairs.size(), 0);
  auto in_box = [&](const Tri& t, const Vec3& p) {
    for (int k = 0; k < 3; ++k) {
      const double l = std::min({lo[t[0]][k], lo[t[1]][k], lo[t[2]][k]});
      const double h = std::max({hi[t[0]][k], hi[t[1]][k], hi[t[2]][k]});
      if (p[k] < l || p[k] > h) return false;
    }
    return true;
  };
  tbb::parallel_for(std::size_t{0}, pairs.size(), [&](std::size_t i) {
    const auto [s, t] = pairs[i];
    if (!is_proper[s] || !is_proper[t]) return;
    const Tri &a = F[s], &b = F[t];
    // near[0][k]: corner k of a within delta of b's plane; near[1][k]: of b, of a's plane.
    std::array<std::array<bool, 3>, 2> near{};
    bool all = true;
    for (int k = 0; k < 3 && (all || contacts); ++k) {
      near[0][k] = within_plane(V[b[0]], V[b[1]], V[b[2]], normal[t], V[a[k]], delta);
      near[1][k] = within_plane(V[a[0]], V[a[1]], V[a[2]], normal[s], V[b[k]], delta);
      all = all && near[0][k] && near[1][k];
    }
    if (all) {
      bool shared = false;
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) shared = shared || a[j] == b[k];
      link[i] = shared ? 1 : 2;
      return;
    }
    if (!contacts) return;
    // A corner touches the other triangle when it lies within delta of its plane and either
    // inside its box or on an edge whose other end lies within delta of the plane too.
    for (int side = 0; side < 2; ++side) {
      const Tri &mine = side == 0 ? a : b, &other = side == 0 ? b : a;
      const int near_corners = near[side][0] + near[side][1] + near[side][2];
      for (int k = 0; k < 3; ++k) {
        const int v = mine[k];
        // A corner at the position of one of the other's corners touches it there only: the
        // arrangement merges the two, and neither plane needs to move.
        if (!near[side][k] || v == other[0] || v == other[1] || v == other[2] || V[v] == V[other[0]] ||
            V[v] == V[other[1]] || V[v] == V[other[2]])
          continue;
        if (near_corners >= 2 || in_box(other, V[v])) touch[i] |= static_cast<unsigned char>(1u << (3 * side + k));
      }
    }
  });
  std::vector<int> parent(F.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t i = 0; i < pairs.size(); ++i)
    if (link[i]) {
      const int r = find(parent, pairs[i].first), s = find(parent, pairs[i].second);
      if (r != s) parent[std::max(r, s)] = std::min(r, s);
    }
  // Per group root: holds a link between layers, or is touched by a corner of another
  // triangle; such groups are made flat.
  std::vector<char> layered(F.size(), 0);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (link[i] == 2) layered[find(parent, pairs[i].first)] = 1;
    if (touch[i] & 7u) layered[find(parent, pairs[i].second)] = 1;
    if (touch[i] >> 3) layered[find(parent, pairs[i].first)] = 1;
  }

  // Each layered group's plane: that of its largest triangle (by the double norm of its
  // normal; ties to the smaller index). Any member's plane would do: they all lie within delta.
  std::vector<double> size(F.size(), 0.0);
  std::vector<int> anchor(F.size(), -1);
  for (int t = 0; t < nf; ++t) {
    const int r = find(parent, t);
    if (!layered[r]) continue;
    const Vec3 &a = V[F[t][0]], &b = V[F[t][1]], &c = V[F[t][2]];
    const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n2 = std::hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
    if (anchor[r] < 0 || n2 > size[r]) {
      anchor[r] = t;
      size[r] = n2;
    }
  }
  join_groups_on_planes(V, F, pairs, normal, delta, parent, layered, anchor, size);
  std::vector<int> plane_of(F.size(), -1);
  std::vector<Plane> planes;
  for (int r = 0; r < nf; ++r)
    if (anchor[r] >= 0) {
      plane_of[r] = static_cast<int>(planes.size());
      const QVec a = out.soup.vertices[F[anchor[r]][0]];
      const QVec n = cross(minus(out.soup.vertices[F[anchor[r]][1]], a), minus(out.soup.vertices[F[anchor[r]][2]], a));
      planes.push_back({n, dot(n, a)});
    }
  out.groups = planes.size();
  // The planes of each vertex's groups, then its move onto them.
  std::vector<std::vector<int>> vertex_planes(V.size());
  auto add_plane = [&](int v, int t) {
    const int p = plane_of[find(parent, t)];
    std::vector<int>& list = vertex_planes[v];
    if (p >= 0 && std::find(list.begin(), list.end(), p) == list.end()) list.push_back(p);
  };
  for (int t = 0; t < nf; ++t)
    for (int v : F[t]) add_plane(v, t);
  for (std::size_t i = 0; i < pairs.size(); ++i)
    for (int k = 0; k < 6; ++k)
      if (touch[i] >> k & 1u) {
        const auto [s, t] = pairs[i];
        if (k < 3) add_plane(F[s][k], t);
        else add_plane(F[t][k - 3], s);
      }
  const Q limit = Q(64 * delta) * Q(64 * delta);
  for (std::size_t v = 0; v < V.size(); ++v) {
    const std::vector<int>& list = vertex_planes[v];
    if (list.empty() || list.size() > 3) continue;
    std::vector<const Plane*> on;
    for (int p : list) on.push_back(&planes[p]);
    const std::optional<QVec> x = onto_planes(on, out.soup.vertices[v]);
    if (!x) continue;
    const QVec d = minus(*x, out.soup.vertices[v]);
    const Q d2 = dot(d, d);
    if (d2 == 0 || d2 > limit) continue;
    out.soup.vertices[v] = *x;
    ++out.moved;
    out.max_move = std::max(out.max_move, distance_bound(*x, V[v]));
  }
  return out;
}

}  // namespace arrangements
