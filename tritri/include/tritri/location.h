// tritri/location.h
//
// Location: where a point of a triangle's plane lies in the closed triangle: outside, in
// the open interior, on an open edge, or at a vertex. classify locates vertices and edge
// crossings with it; pipelines that record per-pair intersections (which simplex of each
// triangle a point lies on) can store it directly: it is two bytes.
//
// Numbering (the same as Result's, result.h): the triangle's vertices are 0, 1, 2; edge k
// is the open segment from vertex k to vertex (k+1)%3. So vertex k is the common end of
// edges k and (k+2)%3.
//
//   tritri::Location l = tritri::location_from_edge_signs(s);
//   if (l.kind == tritri::Location::Edge) { /* on open edge l.id */ }
//
// Exactness: only integers and signs; exact. Complexity: O(1) throughout.
#pragma once

#include <cstdint>

namespace tritri {

struct Location {
  enum Kind : std::int8_t { Outside, Interior, Edge, Vertex };
  Kind kind = Outside;
  std::int8_t id = -1;  // the vertex (Vertex) or edge (Edge) 0..2; -1 for Outside and Interior

  static constexpr Location outside() noexcept { return {}; }
  static constexpr Location interior() noexcept { return {Interior, -1}; }
  static constexpr Location edge(int k) noexcept { return {Edge, static_cast<std::int8_t>(k)}; }
  static constexpr Location vertex(int k) noexcept { return {Vertex, static_cast<std::int8_t>(k)}; }

  friend constexpr bool operator==(const Location&, const Location&) = default;
};

static_assert(sizeof(Location) == 2, "Location is stored in per-pair records: keep it two bytes");

// The closed edges of the triangle that a location lies on, as a bit mask (bit k: edge k):
// edge k -> {k}, vertex k -> {k, (k+2)%3}, interior and outside -> none. Two points lie on
// a common closed edge iff their masks intersect (how coplanar intersections get their
// segments). Precondition: id in 0..2 for Edge and Vertex.
constexpr int closed_edges(const Location& l) noexcept {
  if (l.kind == Location::Vertex) return (1 << l.id) | (1 << (l.id + 2) % 3);
  if (l.kind == Location::Edge) return 1 << l.id;
  return 0;
}

// The location of a point from its three signs against the triangle's edge lines:
// s[k] is the side of the line of edge k that the point is on, normalised so that +1 is
// the triangle's side (e.g. orient2d(v[k], v[k+1], x) times the triangle's orientation, or
// any other predicate with that meaning). Any negative: Outside; no zero: Interior; a zero
// for edge k only: Edge k; zeros for edges k and k+1 only: their common Vertex (k+1)%3.
// Precondition: not all three zero (that happens only for a degenerate triangle; the
// answer is then unspecified).
constexpr Location location_from_edge_signs(const int (&s)[3]) noexcept {
  if (s[0] < 0 || s[1] < 0 || s[2] < 0) return Location::outside();
  const int zeros = (s[0] == 0) + (s[1] == 0) + (s[2] == 0);
  if (zeros == 0) return Location::interior();
  if (zeros == 1) return Location::edge(s[0] == 0 ? 0 : (s[1] == 0 ? 1 : 2));
  // The edges other than the non-zero one, nz + 1 and nz + 2, meet at vertex nz + 2.
  const int nonzero = s[0] != 0 ? 0 : (s[1] != 0 ? 1 : 2);
  return Location::vertex(nonzero == 0 ? 2 : nonzero - 1);
}

}  // namespace tritri
