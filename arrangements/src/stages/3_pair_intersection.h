// arrangements/src/stages/3_pair_intersection.h
//
// PairIntersection: what a classifier reports for one pair of triangles, in terms of
// input vertex ids, before points are deduplicated globally. Every classifier (the native
// one, the tritri adapter) fills this same record; build_intersection_graph consumes it.
//
// A point is either an existing vertex, or a new point defined as an LPI by vertex ids:
// the line through vertices (p, q) meets the plane through (r, s, t). A plane id below 0
// stands for auxiliary_point(-1 - id), the auxiliary point of that triangle (used by
// coplanar edge-edge crossings, whose plane passes through the other edge and a point off
// the triangles' common plane).
#pragma once

#include <array>
#include <cstdint>

#include <tritri/location.h>
#include <tritri/result.h>

namespace arrangements {

// Where a point lies in one triangle of the pair: tritri's Location (vertex k, edge k from
// vertex k to vertex (k+1)%3, Interior; never Outside in a record), with closed_edges.
using tritri::closed_edges;
using tritri::Location;

// An LPI by vertex ids: line (p, q), plane (r, s, t). Canonical form: p < q, r < s < t.
struct LpiKey {
  std::array<int, 5> v{};
  friend bool operator==(const LpiKey&, const LpiKey&) = default;
  friend auto operator<=>(const LpiKey&, const LpiKey&) = default;
};

inline LpiKey make_lpi_key(int p, int q, int r, int s, int t) {
  if (p > q) std::swap(p, q);
  if (r > s) std::swap(r, s);
  if (s > t) std::swap(s, t);
  if (r > s) std::swap(r, s);
  return {{p, q, r, s, t}};
}

struct PairPoint {
  int vertex = -1;  // an existing vertex id, or -1 for a new point given by `lpi`
  LpiKey lpi;
  Location in[2];  // location in the pair's first and second triangle
};

struct PairIntersection {
  int tri[2] = {-1, -1};
  bool coplanar = false;
  tritri::StaticVector<PairPoint, 6> points;
  tritri::StaticVector<tritri::Segment, 6> segments;  // indices into points
};

}  // namespace arrangements
