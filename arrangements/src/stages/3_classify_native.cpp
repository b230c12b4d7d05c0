#include "stages/3_classify_native.h"

#include <tritri/counting_kernel.h>
#include <tritri/double_kernel.h>
#include <tritri/plane_filter.h>
#include <tritri/location.h>
#include <tritri/projection.h>

#include <tuple>

#include "models/exact_model.h"

namespace arrangements {
namespace {

using tritri::Plane;

int next(int i) { return i == 2 ? 0 : i + 1; }
int prev(int i) { return i == 0 ? 2 : i - 1; }

// One triangle of the pair.
template <class P>
struct Side {
  int tri;
  int id[3];
  const P* v[3];
  Plane plane = Plane::XY;  // a projection in which the triangle is not degenerate
  int orientation = 0;      // its orientation there (0 until computed)
};

// Every predicate goes through the kernel K (whose Point is the vertices' type P).
template <class K>
class NativePair {
  using P = typename K::Point;
  using Side = arrangements::Side<P>;

 public:
  NativePair(const K& kernel, const std::vector<P>& V, const std::vector<Tri>& F, int ta, int tb,
             PairIntersection& out)
      : k_(kernel), out_(out) {
    for (int k = 0; k < 2; ++k) {
      const int t = k == 0 ? ta : tb;
      s_[k].tri = t;
      for (int i = 0; i < 3; ++i) {
        s_[k].id[i] = F[t][i];
        s_[k].v[i] = &V[F[t][i]];
      }
    }
    out_ = PairIntersection{};
    out_.tri[0] = ta;
    out_.tri[1] = tb;
  }

  bool run() {
    int sb[3], sa[3];
    for (int j = 0; j < 3; ++j) sb[j] = o3d(*s_[0].v[0], *s_[0].v[1], *s_[0].v[2], *s_[1].v[j]);
    if (one_side(sb)) return false;
    if (sb[0] == 0 && sb[1] == 0 && sb[2] == 0) {
      coplanar();
    } else {
      for (int i = 0; i < 3; ++i) sa[i] = o3d(*s_[1].v[0], *s_[1].v[1], *s_[1].v[2], *s_[0].v[i]);
      if (one_side(sa)) return false;
      if (!side_against_plane(1, sb)) side_against_plane(0, sa);
      if (out_.points.size() == 2) out_.segments.push_back({0, 1});
    }
    // Only what the triangles share in the mesh (common vertices, hence a common edge)?
    for (const PairPoint& p : out_.points)
      if (p.in[0].kind != Location::Vertex || p.in[1].kind != Location::Vertex) return true;
    return false;
  }

 private:
  static bool one_side(const int (&s)[3]) {
    return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
  }

  // Tests side k's simplices against the other triangle's plane signs s; returns true
  // when the pair is done (two points in the non-coplanar case).
  bool side_against_plane(int k, const int (&s)[3]) {
    const int zeros = (s[0] == 0) + (s[1] == 0) + (s[2] == 0);
    if (zeros == 2) {
      const int lone = s[0] != 0 ? 0 : (s[1] != 0 ? 1 : 2);
      const int e = next(lone);  // the edge between the two vertices in the plane
      vertex_in_plane(k, e);
      vertex_in_plane(k, next(e));
      segment_in_plane(k, e);
    } else if (zeros == 1) {
      const int z = s[0] == 0 ? 0 : (s[1] == 0 ? 1 : 2);
      vertex_in_plane(k, z);
      if (!done() && s[next(z)] * s[prev(z)] < 0) segment_crossing_plane(k, next(z));
    } else {
      const int lonely = s[0] == s[1] ? 2 : (s[0] == s[2] ? 1 : 0);
      segment_crossing_plane(k, lonely);
      if (!done()) segment_crossing_plane(k, prev(lonely));
    }
    return done();
  }

  bool done() const { return !out_.coplanar && out_.points.size() >= 2; }

  Side& ensure_projection(int k) {
    Side& t = s_[k];
    if (t.orientation == 0) std::tie(t.plane, t.orientation) = tritri::projection(k_, *t.v[0], *t.v[1], *t.v[2]);
    return t;
  }

  // Where a point of triangle o's plane lies in the closed triangle o (Outside: not in it).
  Location locate_in_triangle(int o, const P& p) {
    const Side& t = ensure_projection(o);
    int s[3];
    for (int i = 0; i < 3; ++i) {
      s[i] = o2d(*t.v[i], *t.v[next(i)], p, t.plane) * t.orientation;
      if (s[i] < 0) return Location::outside();
    }
    return tritri::location_from_edge_signs(s);
  }

  // Vertex v of side k lies in the other plane: is it in the other triangle?
  void vertex_in_plane(int k, int v) {
    if (done()) return;
    const Location loc = locate_in_triangle(1 - k, *s_[k].v[v]);
    if (loc.kind != Location::Outside) add(k, Location::vertex(v), loc);
  }

  // Edge e of side k has its endpoints strictly on both sides of the other plane: where
  // does it cross the other triangle? The edge's line passes on one side of all three
  // edge lines of the other triangle iff it meets it; a zero is a touched edge line.
  void segment_crossing_plane(int k, int e) {
    const Side& self = s_[k];
    const Side& other = s_[1 - k];
    int sign[3], ref = 0;
    for (int i = 0; i < 3; ++i) {
      sign[i] = o3d(*self.v[e], *self.v[next(e)], *other.v[i], *other.v[next(i)]);
      if (sign[i] != 0) {
        if (ref == 0) ref = sign[i];
        if (sign[i] != ref) return;
      }
    }
    for (int& x : sign) x *= ref;  // +1: the side of each edge line where the other triangle is
    add(k, Location::edge(e), tritri::location_from_edge_signs(sign));
  }

  // Edge e of side k lies in the other triangle's plane: crossings with the other's edges
  // and the other's vertices on it (its own endpoints are tested as vertices).
  void segment_in_plane(int k, int e) {
    const Side& self = s_[k];
    const Side& other = ensure_projection(1 - k);
    const P& p = *self.v[e];
    const P& q = *self.v[next(e)];
    int side_of_other[3];
    for (int i = 0; i < 3; ++i) side_of_other[i] = o2d(p, q, *other.v[i], other.plane);
    for (int i = 0; i < 3 && !done(); ++i) {
      // The other's vertex i strictly inside segment pq.
      if (side_of_other[i] == 0 && strictly_between(p, q, *other.v[i], other.plane))
        add(k, Location::edge(e), Location::vertex(i));
    }
    for (int i = 0; i < 3 && !done(); ++i) {
      // Proper crossing of pq with the other's edge i.
      if (side_of_other[i] * side_of_other[next(i)] >= 0) continue;
      const int sp = o2d(*other.v[i], *other.v[next(i)], p, other.plane);
      const int sq = o2d(*other.v[i], *other.v[next(i)], q, other.plane);
      if (sp * sq < 0) add(k, Location::edge(e), Location::edge(i), /*self_edge_in_other_plane=*/true);
    }
  }

  // x collinear with p, q (in the projection): strictly between them?
  static bool strictly_between(const P& p, const P& q, const P& x, Plane plane) {
    const int a = plane == Plane::XY ? 0 : (plane == Plane::YZ ? 1 : 2), b = (a + 1) % 3;
    for (int c : {a, b}) {
      if (p[c] < x[c] && x[c] < q[c]) return true;
      if (q[c] < x[c] && x[c] < p[c]) return true;
    }
    return false;
  }

  void coplanar() {
    out_.coplanar = true;
    ensure_projection(0);
    ensure_projection(1);
    for (int v = 0; v < 3; ++v) vertex_in_plane(1, v);
    for (int e = 0; e < 3; ++e) segment_in_plane(1, e);
    for (int v = 0; v < 3; ++v) {  // A's vertices inside B (on B's boundary: found above)
      const Location loc = locate_in_triangle(1, *s_[0].v[v]);
      if (loc.kind == Location::Interior) add(0, Location::vertex(v), loc);
    }
    // Segments: two corners of the overlap on a common closed edge of A or of B.
    const auto& pts = out_.points;
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (std::size_t j = i + 1; j < pts.size(); ++j)
        if ((closed_edges(pts[i].in[0]) & closed_edges(pts[j].in[0])) ||
            (closed_edges(pts[i].in[1]) & closed_edges(pts[j].in[1])))
          out_.segments.push_back({static_cast<std::int8_t>(i), static_cast<std::int8_t>(j)});
  }

  // Records a point lying at `self` in side k and at `other` in the other triangle. A new
  // point is an LPI of an edge line with a plane that the edge crosses: never an edge
  // lying in that plane (self_edge_in_other_plane), which would leave it undefined.
  void add(int k, Location self, Location other, bool self_edge_in_other_plane = false) {
    PairPoint p;
    p.in[k] = self;
    p.in[1 - k] = other;
    for (const PairPoint& q : out_.points)
      if (q.in[0] == p.in[0] && q.in[1] == p.in[1]) return;
    const Side& a = s_[k];
    const Side& b = s_[1 - k];
    if (self.kind == Location::Vertex) {
      p.vertex = a.id[self.id];
    } else if (other.kind == Location::Vertex) {
      p.vertex = b.id[other.id];
    } else if (self.kind == Location::Edge && other.kind == Location::Edge && out_.coplanar) {
      // Coplanar edge crossing: the plane through the other edge and an auxiliary point.
      p.lpi = make_lpi_key(a.id[self.id], a.id[next(self.id)], b.id[other.id], b.id[next(other.id)], -1 - b.tri);
    } else if (self.kind == Location::Edge && !(other.kind == Location::Edge && self_edge_in_other_plane)) {
      p.lpi = make_lpi_key(a.id[self.id], a.id[next(self.id)], b.id[0], b.id[1], b.id[2]);
    } else {  // then the other side's location is an edge (a new point lies on at least one)
      const int e = other.id < 0 ? 0 : other.id;
      p.lpi = make_lpi_key(b.id[e], b.id[next(e)], a.id[0], a.id[1], a.id[2]);
    }
    out_.points.push_back(p);
  }

  int o3d(const P& a, const P& b, const P& c, const P& d) const {
    return tritri::to_int(k_.orient3d(a, b, c, d));
  }
  int o2d(const P& a, const P& b, const P& c, Plane p) const {
    return tritri::to_int(k_.orient2d(a, b, c, p));
  }

  K k_;
  Side s_[2];
  PairIntersection& out_;
};

}  // namespace

template <class K>
bool classify_pair_native(const K& k, const std::vector<typename K::Point>& V, const std::vector<Tri>& F, int ta,
                          int tb, PairIntersection& out) {
  return NativePair<K>(k, V, F, ta, tb, out).run();
}

template bool classify_pair_native(const tritri::DoubleKernel&, const std::vector<Vec3>&, const std::vector<Tri>&, int,
                                   int, PairIntersection&);
template bool classify_pair_native(const tritri::PlaneCachedKernel&, const std::vector<Vec3>&, const std::vector<Tri>&,
                                   int, int, PairIntersection&);
template bool classify_pair_native(const tritri::CountingKernel<tritri::DoubleKernel>&, const std::vector<Vec3>&,
                                   const std::vector<Tri>&, int, int, PairIntersection&);
template bool classify_pair_native(const ExactModel::Kernel&, const std::vector<ExactModel::Vertex>&,
                                   const std::vector<Tri>&, int, int, PairIntersection&);
template bool classify_pair_native(const tritri::CountingKernel<ExactModel::Kernel>&,
                                   const std::vector<ExactModel::Vertex>&, const std::vector<Tri>&, int, int,
                                   PairIntersection&);

}  // namespace arrangements
