// tritri/shared_vertices.h
//
// meet_only_in_shared(k, a, ia, b, ib): a cheap exact test for two triangles of one mesh
// that share vertices (by index). Returns true when the triangles are certain to meet in
// exactly what they share (the common vertex, or the common edge), so that
// tritri::classify would report only VA_ON_VB points at the shared vertices; false when
// they share nothing, share all three vertices, or may meet anywhere else (then classify
// them in full). Most candidate pairs of a mesh are such neighbours.
//
//   a, b    the triangles' corners (K::Point); ia, ib their vertex indices in the mesh
// Preconditions: equal indices name equal points. Nothing else: degenerate triangles, or
// equal points under different indices, only make the answer false more often.
//
// Why it is exact. One shared vertex u, A = (u, a1, a2), B = (u, b1, b2): if b1 and b2 lie
// strictly on the same side of A's plane, every point of B but u (a convex combination
// with positive weight on b1 or b2) lies strictly on that side, so A and B meet only in
// u; the same with the roles swapped. A shared edge uv, A = (u, v, a), B = (u, v, b): if b
// is not in A's plane, B meets that plane only in the segment uv, which lies in A: the
// triangles meet exactly in the edge. (Coplanar neighbours are left to classify.)
// Cost: 1 orient3d for a shared edge, 2 to 4 for a shared vertex. Exact when K is.
//
// meet_only_in_shared_by_sides and separated_by_plane (below) are the same tests over
// plane signs the caller supplies, e.g. from cached planes (tritri/plane_filter.h); the
// arrangement pipeline's detection stage settles most candidate pairs with them.
#pragma once

#include <array>

#include "tritri/kernel_concept.h"
#include "tritri/projection.h"

namespace tritri {

namespace detail {
// A triangle that repeats a vertex index (degenerate): the early-outs answer false.
inline bool repeats_an_index(const std::array<int, 3>& t) noexcept {
  return t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
}
// For each corner of a, its position in b (-1: not shared); returns how many are shared.
inline int shared_corners(const std::array<int, 3>& ia, const std::array<int, 3>& ib, int (&in_b)[3]) noexcept {
  int shared = 0;
  for (int i = 0; i < 3; ++i) {
    in_b[i] = -1;
    for (int j = 0; j < 3; ++j)
      if (ia[i] == ib[j]) {
        in_b[i] = j;
        ++shared;
      }
  }
  return shared;
}
}  // namespace detail

// The same tests for callers that know the plane signs another way (a cached plane,
// tritri/plane_filter.h). side(t, k) must return the exact sign of corner k of the other
// triangle against the plane of triangle t: side(0, k) = orient3d(a[0], a[1], a[2], b[k]),
// side(1, k) = orient3d(b[0], b[1], b[2], a[k]). Each side is asked at most once.
template <class Side>
bool meet_only_in_shared_by_sides(const std::array<int, 3>& ia, const std::array<int, 3>& ib, Side&& side) {
  if (detail::repeats_an_index(ia) || detail::repeats_an_index(ib)) return false;
  int in_b[3];  // for each corner of a, its position in b (-1: not shared)
  const int shared = detail::shared_corners(ia, ib, in_b);
  if (shared == 1) {
    // orient3d(u, a1, a2, .) with u = a[i] is a cyclic rotation of plane(a): same sign.
    const int i = in_b[0] >= 0 ? 0 : (in_b[1] >= 0 ? 1 : 2), j = in_b[i];
    const Sign s1 = side(0, (j + 1) % 3);
    if (s1 != Sign::Zero && side(0, (j + 2) % 3) == s1) return true;
    const Sign t1 = side(1, (i + 1) % 3);
    return t1 != Sign::Zero && side(1, (i + 2) % 3) == t1;
  }
  if (shared == 2) {
    const int w = in_b[0] < 0 ? 0 : (in_b[1] < 0 ? 1 : 2);    // a's corner not in b
    const int x = 3 - in_b[(w + 1) % 3] - in_b[(w + 2) % 3];  // b's corner not in a
    return side(0, x) != Sign::Zero;
  }
  return false;
}

template <Kernel K>
bool meet_only_in_shared(const K& k, const std::array<typename K::Point, 3>& a, const std::array<int, 3>& ia,
                         const std::array<typename K::Point, 3>& b, const std::array<int, 3>& ib) {
  return meet_only_in_shared_by_sides(ia, ib, [&](int t, int corner) {
    return t == 0 ? k.orient3d(a[0], a[1], a[2], b[corner]) : k.orient3d(b[0], b[1], b[2], a[corner]);
  });
}

// separated_by_plane(side): true when the three corners of one triangle lie strictly on
// one side of the other's plane, so that the two cannot meet (the first test of
// tritri::classify, which would return an empty result). side as above. Asks each side at
// most once, stopping at the first decision: 2 to 6 signs.
template <class Side>
bool separated_by_plane(Side&& side) {
  for (int t = 0; t < 2; ++t) {
    const Sign s0 = side(t, 0);
    if (s0 == Sign::Zero) continue;
    if (side(t, 1) == s0 && side(t, 2) == s0) return true;
  }
  return false;
}

// Tests in a projection, for what meet_only_in_shared leaves open: coplanar pairs, and
// pairs that straddle each other's planes. Preconditions: a and b proper triangles, equal
// indices name equal points. All tests run in a projection where a is not degenerate
// (tritri::projection); it maps a one to one, so when the projections of a and b meet only
// in the projection of a set S of a's points, a and b meet only in S (a common point
// projects into both projections; a has one point over each point of its projection).
//
// meet_in_shared_in_projection(k, a, ia, b, ib): true when the two meet exactly in what
// they share. Shared edge uv: the apexes lie strictly on opposite sides of line uv; the
// projections then meet only in segment uv. Shared vertex u: one of the four edge lines at
// u has the other triangle's two free corners strictly on the far side (the side without
// the third corner of its own triangle); that triangle's projection then meets the line
// only in u, and the owner's lies in the closed near side. For coplanar pairs this is the
// usual 2D argument; for others it is sufficient too (by the projection argument above).
// Sufficient, not necessary: false means "classify".
// Cost: 2 orient2d (edge), up to 9 (vertex), plus the projection (1 to 3).
template <Kernel K>
bool meet_in_shared_in_projection(const K& k, const std::array<typename K::Point, 3>& a, const std::array<int, 3>& ia,
                                   const std::array<typename K::Point, 3>& b, const std::array<int, 3>& ib) {
  if (detail::repeats_an_index(ia) || detail::repeats_an_index(ib)) return false;
  int in_b[3];
  const int shared = detail::shared_corners(ia, ib, in_b);
  const auto [plane, orientation] = projection(k, a[0], a[1], a[2], dominant_plane(a[0], a[1], a[2]));
  if (orientation == 0 || (shared != 1 && shared != 2)) return false;
  if (shared == 2) {
    const int w = in_b[0] < 0 ? 0 : (in_b[1] < 0 ? 1 : 2);  // a's corner not in b
    const int x = 3 - in_b[(w + 1) % 3] - in_b[(w + 2) % 3];
    const auto &u = a[(w + 1) % 3], &v = a[(w + 2) % 3];
    const Sign sa = k.orient2d(u, v, a[w], plane);
    const Sign sb = k.orient2d(u, v, b[x], plane);
    return sa != Sign::Zero && sb == -sa;
  }
  const int i = in_b[0] >= 0 ? 0 : (in_b[1] >= 0 ? 1 : 2), j = in_b[i];
  const auto& u = a[i];
  // Edge line (u, p) of one triangle, q its third corner, x and y the other's free corners.
  auto separates = [&](const auto& p, const auto& q, const auto& x, const auto& y) {
    const Sign s = k.orient2d(u, p, q, plane);
    if (s == Sign::Zero) return false;
    const Sign far = -s;
    return k.orient2d(u, p, x, plane) == far && k.orient2d(u, p, y, plane) == far;
  };
  const auto &a1 = a[(i + 1) % 3], &a2 = a[(i + 2) % 3], &b1 = b[(j + 1) % 3], &b2 = b[(j + 2) % 3];
  return separates(a1, a2, b1, b2) || separates(a2, a1, b1, b2) || separates(b1, b2, a1, a2) ||
         separates(b2, b1, a1, a2);
}

// separated_in_projection(k, a, b): true when the projections of triangles a and b onto
// the axis plane where a is best conditioned are disjoint: some edge line of one has all
// three corners of the other strictly on its far side (in that plane). Disjoint
// projections of closed triangles mean disjoint triangles, for any pair (a proper; no
// shared vertices needed, none possible when true). For two coplanar triangles the
// converse holds too (separating axis theorem for convex polygons: only touching or
// overlapping pairs are left); for others it is a cheap sufficient test, which settles
// most box pairs that straddle each other's planes without meeting.
// Cost: up to 3 + 2 * 3 * 4 orient2d, usually a few.
template <Kernel K>
bool separated_in_projection(const K& k, const std::array<typename K::Point, 3>& a,
                        const std::array<typename K::Point, 3>& b) {
  const auto [plane, orientation] = projection(k, a[0], a[1], a[2], dominant_plane(a[0], a[1], a[2]));
  if (orientation == 0) return false;
  const Sign ob = k.orient2d(b[0], b[1], b[2], plane);
  if (ob == Sign::Zero) return false;
  auto edge_separates = [&](const std::array<typename K::Point, 3>& t, Sign own,
                            const std::array<typename K::Point, 3>& o) {
    for (int e = 0; e < 3; ++e) {
      const Sign far = -own;
      const auto &p = t[e], &q = t[(e + 1) % 3];
      if (k.orient2d(p, q, o[0], plane) == far && k.orient2d(p, q, o[1], plane) == far &&
          k.orient2d(p, q, o[2], plane) == far)
        return true;
    }
    return false;
  };
  return edge_separates(a, static_cast<Sign>(orientation), b) || edge_separates(b, ob, a);
}

// touches_only_in_shared(k, a, ia, b, ib, sb): b touches plane(a) without crossing it,
// and the contact misses a except at shared vertices. sb[c] is the exact sign of b's corner
// c against plane(a) (orient3d(a[0], a[1], a[2], b[c])); precondition: a and b proper
// triangles, equal indices name equal points. Returns false unless sb has a zero, a
// nonzero and no two opposite signs. Then b meets plane(a) exactly in conv(Z), Z its zero
// corners (a point or a segment), so a and b meet inside conv(Z) and a. True when that is
// at most shared vertices: Z is one shared corner, or Z a shared edge; or, in a
// projection where a is proper, an edge line of a has conv(Z) strictly on its far side
// (the side without a's third corner), except for a shared endpoint of Z on that line.
// Sufficient, not necessary (false means "classify"). Cost: 1 to 3 orient2d for the
// projection, up to 6 more.
template <Kernel K>
bool touches_only_in_shared(const K& k, const std::array<typename K::Point, 3>& a, const std::array<int, 3>& ia,
                            const std::array<typename K::Point, 3>& b, const std::array<int, 3>& ib,
                            const Sign (&sb)[3]) {
  if (detail::repeats_an_index(ia) || detail::repeats_an_index(ib)) return false;
  int zero[3], nz = 0, pos = 0, neg = 0;
  for (int c = 0; c < 3; ++c) {
    if (sb[c] == Sign::Zero) zero[nz++] = c;
    pos += sb[c] == Sign::Positive;
    neg += sb[c] == Sign::Negative;
  }
  if (nz == 0 || nz == 3 || (pos > 0 && neg > 0)) return false;
  auto corner_of_a = [&](int c) {
    for (int i = 0; i < 3; ++i)
      if (ia[i] == ib[c]) return i;
    return -1;
  };
  const int s0 = corner_of_a(zero[0]), s1 = nz == 2 ? corner_of_a(zero[1]) : -1;
  if ((nz == 1 && s0 >= 0) || (nz == 2 && s0 >= 0 && s1 >= 0)) return true;  // a shared corner or edge
  const auto [plane, orientation] = projection(k, a[0], a[1], a[2], dominant_plane(a[0], a[1], a[2]));
  if (orientation == 0) return false;
  const Sign far = -static_cast<Sign>(orientation);
  // Every point of Z off a's corners strictly beyond the line of a's edge e (which then
  // holds any shared point of Z, as its line passes through that corner of a).
  auto beyond = [&](int e) {
    for (int q = 0; q < nz; ++q) {
      const int shared_at = q == 0 ? s0 : s1;
      if (shared_at >= 0) {
        if (shared_at != e && shared_at != (e + 1) % 3) return false;  // not on this edge's line
        continue;
      }
      if (k.orient2d(a[e], a[(e + 1) % 3], b[zero[q]], plane) != far) return false;
    }
    return true;
  };
  return beyond(0) || beyond(1) || beyond(2);
}

}  // namespace tritri
