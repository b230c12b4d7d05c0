// arrangements/src/stages/5_triangulate_cluster.h (internal to stage 5)
//
// Coplanar clusters triangulated whole (issues 36 and 37). Stage 5 splits each soup
// triangle by its own points and constraints and those of its coplanar partners
// (split_triangle_of), so a point or crossing shared by k mutually overlapping coplanar
// triangles is inserted k times: n thin wedges through one region cost O(n^3) insertions
// (100 wedges: 71 s) for an output of O(n^2) triangles. A cluster (the triangles
// connected by coplanar partnership, all in one plane) where that repetition dominates is
// instead triangulated once, as one constrained triangulation of all its points and
// constraints, and each soup triangle of it keeps the pieces it covers.
//
// clusters_to_triangulate_whole(g): the clusters (each a sorted list of soup triangles,
//   the lists in order of their smallest triangle) for which one triangulation is
//   cheaper: the sum over their triangles of the points and constraints each would
//   insert is at least kWholeFrom times the distinct points and constraints of the
//   cluster, and at least kWholeMinWork. Other clusters, and ordinary input, are split per
//   triangle as before (the same output, byte for byte). Cost: linear in the lists.
// split_cluster_of<M>(soup, g, cluster): the pieces (5_triangulate_triangle.h) of the
//   cluster's triangles, in the cluster's order: the same contract as split_triangle_of
//   per triangle (each local triangle emitted once, by the smallest soup triangle covering
//   it, in that triangle's orientation; covers; new TPIs where two constraints cross).
//   Built inside an enclosing triangle of three explicit points around the cluster in the
//   projection (checked exactly to hold every corner of the cluster strictly inside; if
//   not, the cluster is split per triangle): all points in Morton order, then every
//   constraint (the soup triangles' edges between their edge points, and the graph's
//   segments) once, in a shuffled order; then each soup triangle's local triangles are
//   found by a flood from one of its corners, not crossing its edges.
// Exactness: every decision is the model's exact orient2d in a projection where the
//   cluster's plane is not degenerate, as in split_triangle_of; TPIs from exact planes.
// Cost: O(P log P)-ish expected for P distinct points and constraints of the cluster (no
//   Delaunay flips: a bad order can cost more, as per triangle), plus the covered local
//   triangles of each soup triangle (the output).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "arrangements/triangle_soup.h"
#include "stages/4_intersection_graph.h"
#include "stages/5_triangulate_triangle.h"

namespace arrangements {

inline constexpr std::size_t kWholeFrom = 4;        // repetition factor that makes a cluster whole
inline constexpr std::size_t kWholeMinWork = 4096;  // per-triangle insertions below which it never does

template <class Point>
std::vector<std::vector<int>> clusters_to_triangulate_whole(const BasicIntersectionGraph<Point>& g);

// std::nullopt when no enclosing triangle holds the cluster (then split it per triangle).
template <class M>
std::optional<std::vector<Piece<typename M::Point>>> split_cluster_of(
    const BasicTriangleSoup<typename M::Vertex>& soup, const BasicIntersectionGraph<typename M::Point>& g,
    const std::vector<int>& cluster);

}  // namespace arrangements
