// snap_near_coplanar_faces (round_snapped_planes.h): near-coplanar layers of the input made
// coplanar, the input kept otherwise.
#include "round_snapped_planes.h"

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
#include "support/rounding_grid.h"

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

}  // namespace

SnappedPlanes snap_near_coplanar_faces(const TriangleSoup& input, double delta, int threads) {
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
  tbb::parallel_for(std::size_t{0}, pairs.size(), [&](std::size_t i) {
    const auto [s, t] = pairs[i];
    if (!is_proper[s] || !is_proper[t]) return;
    const Tri &a = F[s], &b = F[t];
    for (int k = 0; k < 3; ++k)
      if (!within_plane(V[a[0]], V[a[1]], V[a[2]], normal[s], V[b[k]], delta) ||
          !within_plane(V[b[0]], V[b[1]], V[b[2]], normal[t], V[a[k]], delta))
        return;
    bool shared = false;
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) shared = shared || a[j] == b[k];
    link[i] = shared ? 1 : 2;
  });
  std::vector<int> parent(F.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t i = 0; i < pairs.size(); ++i)
    if (link[i]) {
      const int r = find(parent, pairs[i].first), s = find(parent, pairs[i].second);
      if (r != s) parent[std::max(r, s)] = std::min(r, s);
    }
  std::vector<char> layered(F.size(), 0);  // per group root: holds a link between layers
  for (std::size_t i = 0; i < pairs.size(); ++i)
    if (link[i] == 2) layered[find(parent, pairs[i].first)] = 1;

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
  for (int t = 0; t < nf; ++t) {
    const int r = find(parent, t);
    if (plane_of[r] < 0) continue;
    for (int v : F[t]) {
      std::vector<int>& list = vertex_planes[v];
      if (std::find(list.begin(), list.end(), plane_of[r]) == list.end()) list.push_back(plane_of[r]);
    }
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
