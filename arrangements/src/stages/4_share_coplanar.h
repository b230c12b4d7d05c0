// arrangements/src/stages/4_share_coplanar.h
//
// share_coplanar: the last step of build_intersection_graph (4_intersection_graph.cpp),
// run when coplanar pairs exist. Coplanar partners share their points and segments (as in
// the 2020 pipeline): for every triangle t and each coplanar partner u, the points of u
// (inside u or on its edges) that lie in the closed triangle t are added to t (inside t,
// or on the edge of t they lie on), and u's segments whose endpoints both lie in t are
// added to t's segments. Without it, a constraint of u meeting u's edge inside t would
// cross t's copy of that edge at a point t does not know, and t's triangulation would
// construct it again. Additions are computed from the lists as they were before, so the
// result does not depend on processing order.
//
// Precondition: the graph's lists are sorted and unique (so are they after), and every
// end of a segment of u is a corner of u, a point of one of its edges or a point inside it
// (what triangulation needs of every constraint).
// Exactness: point location is orient2d on implicit points (a certified filter, then
// tritri's filtered exact predicates) in a projection where t is not degenerate.
// Cost: the points of u's edges are sorted along each edge once; the run of an edge's
// points inside t is found by binary search on the exact sides of t's edge lines (a
// linear function along the edge changes sign once), so a pair (t, u) costs O(log k)
// predicates per edge plus one location per point found, not one per point of u: two
// coplanar fans of long thin triangles (QuickCSG's TwoCylinders and finer) have O(n)
// partners per triangle, each with O(n) points on its edges, and listing them all was
// cubic. Edges with at most 16 points are visited whole instead (cheaper than the exact
// signs at their ends). u's segments are looked up from the points found (they are sorted
// by first end).
// Memory: the sorted copies of the partners' edge lists and per-thread stamps.
#pragma once

#include <vector>

#include "arrangements/triangle_soup.h"
#include "stages/4_intersection_graph.h"

namespace arrangements {

template <class M>
void share_coplanar(const std::vector<typename M::Vertex>& V, const std::vector<Tri>& F,
                    BasicIntersectionGraph<typename M::Point>& g);

}  // namespace arrangements
