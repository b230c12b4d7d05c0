// tritri/classify.h
//
// classify: the exact classification of the intersection of two triangles.
//
// Inputs:  a0, a1, a2  vertices of triangle A;  b0, b1, b2  vertices of triangle B
//          (K::Point), optionally a kernel instance k (for stateful kernels).
// Output:  tritri::Result (result.h): every corner of A ∩ B as (type, id0, id1), the
//          segments between them, and the coplanar / degenerate flags.
//
// Preconditions: both triangles non-degenerate (three distinct, non-collinear vertices).
//   If one is degenerate and not strictly on one side of the other's plane, the result
//   has degenerate == true and no points; a degenerate triangle strictly on one side of
//   the other's plane may give an empty (correct) result without the flag.
// Exactness: every decision is a kernel predicate (orient3d, orient2d, and orient3d_each
//   where the kernel has it); no constructions, no tolerances. The answer is exact
//   whenever the kernel's predicates are, and identical for every exact kernel.
// Complexity: O(1). 3 orient3d (one orient3d_each) to reject or detect coplanarity, 6
//   (two) for other pairs;
//   at most 4 more in general position and at most 12 more (plus at most 12 orient2d)
//   when vertices lie in the other triangle's plane. Coplanar pairs: at most 22 orient2d.
//   Nothing is evaluated that the signs already known rule out.
//
// Algorithm (docs/ARCHITECTURE.md, "The classification algorithm"): the signs of B's
// vertices against A's plane and of A's vertices against B's plane reject separated
// pairs and detect coplanarity. Otherwise A ∩ plane(B) is a segment SA whose endpoints
// are vertices of A or crossings of A's edges, likewise SB, and A ∩ B = SA ∩ SB on the
// line plane(A) ∩ plane(B). In general position the four crossings are ordered along
// that line with one orient3d each; when vertices lie in the other plane each endpoint
// is located in the other triangle. Coplanar pairs use the 18 orient2d signs of every
// vertex against every edge line.
#pragma once

#include <utility>

#include "tritri/kernel_concept.h"
#include "tritri/location.h"
#include "tritri/projection.h"
#include "tritri/result.h"
#include "tritri/sign.h"

namespace tritri {

namespace detail {

inline constexpr int next(int i) noexcept { return i == 2 ? 0 : i + 1; }
inline constexpr int prev(int i) noexcept { return i == 0 ? 2 : i - 1; }

inline bool strictly_one_side(const int (&s)[3]) noexcept {
  return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
}
inline bool all_zero(const int (&s)[3]) noexcept { return s[0] == 0 && s[1] == 0 && s[2] == 0; }

// A point's closed edges of A and of B as bit masks, for the coplanar segment rule.
inline void edge_masks(const IntersectionPoint& p, int& ma, int& mb) noexcept {
  const int i = p.id0, j = p.id1;
  auto vertex_edges = [](int v) { return closed_edges(Location::vertex(v)); };
  switch (p.type) {
    case Type::VA_ON_VB:
      ma = vertex_edges(i);
      mb = vertex_edges(j);
      break;
    case Type::VA_ON_EB:
      ma = vertex_edges(i);
      mb = 1 << j;
      break;
    case Type::VB_ON_EA:
      ma = 1 << j;
      mb = vertex_edges(i);
      break;
    case Type::VA_ON_TB:
      ma = vertex_edges(i);
      mb = 0;
      break;
    case Type::VB_ON_TA:
      ma = 0;
      mb = vertex_edges(i);
      break;
    case Type::EA_CROSS_EB:
      ma = 1 << i;
      mb = 1 << j;
      break;
    default:
      ma = 0;
      mb = 0;
      break;  // edge-face crossings do not occur in coplanar pairs
  }
}

// One classification; A and B are arrays of pointers to the six input points.
template <class K>
class Classifier {
 public:
  using P = typename K::Point;

  // Writes into r, which the caller constructs in its return slot (named return value
  // optimisation, which compilers do here): copying a Result out of the classifier would
  // reread, as whole words, bytes just written one by one.
  Classifier(const K& k, const P* const (&a)[3], const P* const (&b)[3], Result& r) : k_(k), a_(a), b_(b), r_(r) {}

  void run() {
    Sign sb[3];
    tritri::orient3d_each(k_, *a_[0], *a_[1], *a_[2], *b_[0], *b_[1], *b_[2], sb);
    for (int j = 0; j < 3; ++j) ob_[j] = to_int(sb[j]);
    if (strictly_one_side(ob_)) return;
    if (all_zero(ob_)) {
      // B lies in plane(A), or A is degenerate. If both are proper triangles the planes
      // coincide, so A's signs against plane(B) are all zero and need no evaluation;
      // coplanar() checks both for degeneracy.
      coplanar();
      finish();
      return;
    }
    Sign sa[3];
    tritri::orient3d_each(k_, *b_[0], *b_[1], *b_[2], *a_[0], *a_[1], *a_[2], sa);
    for (int i = 0; i < 3; ++i) oa_[i] = to_int(sa[i]);
    if (strictly_one_side(oa_)) return;
    if (all_zero(oa_)) {
      r_.degenerate = true;  // A spans a plane that B's vertices are not all in: B is degenerate
    } else if (oa_[0] * oa_[1] * oa_[2] != 0 && ob_[0] * ob_[1] * ob_[2] != 0) {
      crossing_general_position();
    } else {
      crossing_with_vertices_in_planes();
    }
    finish();
  }

 private:
  // --- non-coplanar, no vertex in the other plane --------------------------------------

  // Index of the vertex whose sign differs from the other two (no zeros).
  static int lonely(const int (&s)[3]) noexcept { return s[0] == s[1] ? 2 : (s[0] == s[2] ? 1 : 0); }

  // Order along L = plane(A) ∩ plane(B), oriented by nA x nB, of the crossing of A's edge
  // ea with plane(B) and the crossing of B's edge eb with plane(A): the sign of
  // u(X) - u(Y). orient3d of the two edges tells on which side of each other the lines
  // pass; the vertex signs fix the direction of each edge.
  int compare_on_line(int ea, int eb) const {
    const int o = to_int(k_.orient3d(*a_[ea], *a_[next(ea)], *b_[eb], *b_[next(eb)]));
    return -oa_[ea] * ob_[eb] * o;
  }

  void crossing_general_position() {
    // SA runs between the crossings of the two edges at A's lonely vertex; which end is
    // higher along L depends on the side of plane(B) the lonely vertex is on (and the
    // same for B, whose view of L is reversed).
    const int la = lonely(oa_), lb = lonely(ob_);
    const int hi_a = oa_[la] > 0 ? la : prev(la), lo_a = oa_[la] > 0 ? prev(la) : la;
    const int lo_b = ob_[lb] > 0 ? lb : prev(lb), hi_b = ob_[lb] > 0 ? prev(lb) : lb;

    const int c1 = compare_on_line(lo_a, hi_b);
    if (c1 > 0) return;
    if (c1 == 0) return add({Type::EA_CROSS_EB, int8(lo_a), int8(hi_b)});
    const int c2 = compare_on_line(hi_a, lo_b);
    if (c2 < 0) return;
    if (c2 == 0) return add({Type::EA_CROSS_EB, int8(hi_a), int8(lo_b)});
    // The intervals overlap properly: [max(lo_a, lo_b), min(hi_a, hi_b)].
    const int c3 = compare_on_line(lo_a, lo_b);
    add(c3 > 0   ? IntersectionPoint{Type::EA_CROSS_TB, int8(lo_a), -1}
        : c3 < 0 ? IntersectionPoint{Type::EB_CROSS_TA, int8(lo_b), -1}
                 : IntersectionPoint{Type::EA_CROSS_EB, int8(lo_a), int8(lo_b)});
    const int c4 = compare_on_line(hi_a, hi_b);
    add(c4 < 0   ? IntersectionPoint{Type::EA_CROSS_TB, int8(hi_a), -1}
        : c4 > 0 ? IntersectionPoint{Type::EB_CROSS_TA, int8(hi_b), -1}
                 : IntersectionPoint{Type::EA_CROSS_EB, int8(hi_a), int8(hi_b)});
  }

  // --- non-coplanar, some vertex in the other plane ------------------------------------

  // An endpoint of SA (or SB): a vertex in the other plane or an edge crossing it.
  struct Feature {
    bool is_vertex;
    int id;
  };

  // The endpoints of T ∩ plane(other) from T's vertex signs (not all equal, not all zero).
  static int plane_section(const int (&s)[3], Feature (&f)[2]) noexcept {
    const int zeros = (s[0] == 0) + (s[1] == 0) + (s[2] == 0);
    if (zeros == 2) {
      int n = 0;
      for (int i = 0; i < 3; ++i)
        if (s[i] == 0) f[n++] = {true, i};
      return 2;
    }
    if (zeros == 1) {
      const int i = s[0] == 0 ? 0 : (s[1] == 0 ? 1 : 2);
      f[0] = {true, i};
      if (s[next(i)] * s[prev(i)] < 0) {  // the opposite edge crosses the plane
        f[1] = {false, next(i)};
        return 2;
      }
      return 1;
    }
    const int l = lonely(s);
    f[0] = {false, l};
    f[1] = {false, prev(l)};
    return 2;
  }

  // Location of vertex v of triangle `self` (in the other triangle's plane) in `other`,
  // with orient2d in a projection where `other` is non-degenerate.
  Location locate_vertex(const P* const (&self)[3], int v, const P* const (&other)[3],
                         std::pair<Plane, int>& proj) const {
    if (proj.second == 0) proj = tritri::projection(k_, *other[0], *other[1], *other[2]);
    int s[3];
    for (int j = 0; j < 3; ++j) {
      s[j] = proj.second * to_int(k_.orient2d(*other[j], *other[next(j)], *self[v], proj.first));
      if (s[j] < 0) return {};
    }
    return tritri::location_from_edge_signs(s);
  }

  // Location in `other` of the point where edge e of `self` crosses other's plane: the
  // line of the edge passes on one side of all three edge lines of `other` iff it meets
  // the closed triangle; a zero means it meets that edge line.
  Location locate_crossing(const P* const (&self)[3], int e, const P* const (&other)[3]) const {
    int s[3];
    int ref = 0;
    for (int j = 0; j < 3; ++j) {
      s[j] = to_int(k_.orient3d(*self[e], *self[next(e)], *other[j], *other[next(j)]));
      if (s[j] != 0) {
        if (ref == 0) ref = s[j];
        if (s[j] != ref) return {};
      }
    }
    for (int& x : s) x *= ref;
    return tritri::location_from_edge_signs(s);
  }

  void crossing_with_vertices_in_planes() {
    Feature fa[2], fb[2];
    const int na = plane_section(oa_, fa), nb = plane_section(ob_, fb);
    // SA ∩ SB has at most one point when either section is a single point.
    const std::size_t max_points = (na == 1 || nb == 1) ? 1 : 2;
    std::pair<Plane, int> proj_a{Plane::XY, 0}, proj_b{Plane::XY, 0};

    for (int n = 0; n < na && r_.points.size() < max_points; ++n) {
      const Feature f = fa[n];
      const Location loc = f.is_vertex ? locate_vertex(a_, f.id, b_, proj_b) : locate_crossing(a_, f.id, b_);
      if (loc.kind == Location::Outside) continue;
      if (f.is_vertex)
        add_unique(loc.kind == Location::Interior ? IntersectionPoint{Type::VA_ON_TB, int8(f.id), -1}
                   : loc.kind == Location::Edge   ? IntersectionPoint{Type::VA_ON_EB, int8(f.id), int8(loc.id)}
                                                  : IntersectionPoint{Type::VA_ON_VB, int8(f.id), int8(loc.id)});
      else
        add_unique(loc.kind == Location::Interior ? IntersectionPoint{Type::EA_CROSS_TB, int8(f.id), -1}
                   : loc.kind == Location::Edge   ? IntersectionPoint{Type::EA_CROSS_EB, int8(f.id), int8(loc.id)}
                                                  : IntersectionPoint{Type::VB_ON_EA, int8(loc.id), int8(f.id)});
    }
    for (int n = 0; n < nb && r_.points.size() < max_points; ++n) {
      const Feature f = fb[n];
      const Location loc = f.is_vertex ? locate_vertex(b_, f.id, a_, proj_a) : locate_crossing(b_, f.id, a_);
      if (loc.kind == Location::Outside) continue;
      if (f.is_vertex)
        add_unique(loc.kind == Location::Interior ? IntersectionPoint{Type::VB_ON_TA, int8(f.id), -1}
                   : loc.kind == Location::Edge   ? IntersectionPoint{Type::VB_ON_EA, int8(f.id), int8(loc.id)}
                                                  : IntersectionPoint{Type::VA_ON_VB, int8(loc.id), int8(f.id)});
      else
        add_unique(loc.kind == Location::Interior ? IntersectionPoint{Type::EB_CROSS_TA, int8(f.id), -1}
                   : loc.kind == Location::Edge   ? IntersectionPoint{Type::EA_CROSS_EB, int8(loc.id), int8(f.id)}
                                                  : IntersectionPoint{Type::VA_ON_EB, int8(loc.id), int8(f.id)});
    }
  }

  // --- coplanar -------------------------------------------------------------------------

  void coplanar() {
    const auto [plane, sa] = tritri::projection(k_, *a_[0], *a_[1], *a_[2]);
    if (sa == 0) {
      r_.degenerate = true;
      return;
    }
    const int sb = to_int(k_.orient2d(*b_[0], *b_[1], *b_[2], plane));
    if (sb == 0) {
      r_.degenerate = true;
      return;
    }
    r_.coplanar = true;

    // side_b[i][j]: side of A's edge line i that B's vertex j is on (+1: A's side);
    // side_a[j][i]: side of B's edge line j that A's vertex i is on.
    int side_b[3][3], side_a[3][3];
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) side_b[i][j] = sa * to_int(k_.orient2d(*a_[i], *a_[next(i)], *b_[j], plane));
      if (side_b[i][0] < 0 && side_b[i][1] < 0 && side_b[i][2] < 0) return;  // separating line
    }
    for (int j = 0; j < 3; ++j) {
      for (int i = 0; i < 3; ++i) side_a[j][i] = sb * to_int(k_.orient2d(*b_[j], *b_[next(j)], *a_[i], plane));
      if (side_a[j][0] < 0 && side_a[j][1] < 0 && side_a[j][2] < 0) return;
    }

    for (int i = 0; i < 3; ++i) {
      const int s[3] = {side_a[0][i], side_a[1][i], side_a[2][i]};
      const Location loc = location_from_edge_signs(s);
      if (loc.kind == Location::Interior) add({Type::VA_ON_TB, int8(i), -1});
      if (loc.kind == Location::Edge) add({Type::VA_ON_EB, int8(i), int8(loc.id)});
      if (loc.kind == Location::Vertex) add({Type::VA_ON_VB, int8(i), int8(loc.id)});
    }
    for (int j = 0; j < 3; ++j) {
      const int s[3] = {side_b[0][j], side_b[1][j], side_b[2][j]};
      const Location loc = location_from_edge_signs(s);
      if (loc.kind == Location::Interior) add({Type::VB_ON_TA, int8(j), -1});
      if (loc.kind == Location::Edge) add({Type::VB_ON_EA, int8(j), int8(loc.id)});
      // Vertex-on-vertex was already found from A's side.
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (side_b[i][j] * side_b[i][next(j)] < 0 && side_a[j][i] * side_a[j][next(i)] < 0)
          add({Type::EA_CROSS_EB, int8(i), int8(j)});
  }

  // --- output ---------------------------------------------------------------------------

  static std::int8_t int8(int v) noexcept { return static_cast<std::int8_t>(v); }

  void add(const IntersectionPoint& p) noexcept { r_.points.push_back(p); }
  void add_unique(const IntersectionPoint& p) noexcept {
    for (const auto& q : r_.points)
      if (q == p) return;
    r_.points.push_back(p);
  }

  // Sort the points and derive the segments from them.
  void finish() noexcept {
    auto& pts = r_.points;
    for (std::size_t i = 1; i < pts.size(); ++i)
      for (std::size_t j = i; j > 0 && pts[j] < pts[j - 1]; --j) std::swap(pts[j], pts[j - 1]);
    if (!r_.coplanar) {
      if (pts.size() == 2) r_.segments.push_back({0, 1});
      return;
    }
    // Two corners of the overlap on a common closed edge of A or of B bound it.
    int ma[6], mb[6];
    for (std::size_t i = 0; i < pts.size(); ++i) edge_masks(pts[i], ma[i], mb[i]);
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (std::size_t j = i + 1; j < pts.size(); ++j)
        if ((ma[i] & ma[j]) || (mb[i] & mb[j])) r_.segments.push_back({int8(int(i)), int8(int(j))});
  }

  const K& k_;
  const P* const (&a_)[3];
  const P* const (&b_)[3];
  int oa_[3] = {0, 0, 0};  // A's vertices against plane(B)
  int ob_[3] = {0, 0, 0};  // B's vertices against plane(A)
  Result& r_;
};

}  // namespace detail

// Classifies the intersection of triangles A = (a0, a1, a2) and B = (b0, b1, b2) with
// the predicates of kernel instance k. See the top of this file.
template <Kernel K>
Result classify(const K& k, const typename K::Point& a0, const typename K::Point& a1, const typename K::Point& a2,
                const typename K::Point& b0, const typename K::Point& b1, const typename K::Point& b2) {
  using P = typename K::Point;
  const P* const a[3] = {&a0, &a1, &a2};
  const P* const b[3] = {&b0, &b1, &b2};
  Result r;
  detail::Classifier<K>(k, a, b, r).run();
  return r;
}

// The same with a default-constructed kernel: classify<tritri::DoubleKernel>(a0, ..., b2).
template <Kernel K>
Result classify(const typename K::Point& a0, const typename K::Point& a1, const typename K::Point& a2,
                const typename K::Point& b0, const typename K::Point& b1, const typename K::Point& b2) {
  return classify(K{}, a0, a1, a2, b0, b1, b2);
}

}  // namespace tritri
