// arrangements/src/io/triangulate_polygon.h
//
// bool triangulate_polygon(V, corners, out): append a triangulation of one polygon face.
//   V        the file's vertices: finite doubles (Vec3) or exact rationals (ExactVec3,
//            for load_mesh_files); the same rules for both, every predicate exact
//   corners  the face's corners c0 .. c(n-1), n >= 3, indices into V (valid)
//   out      receives exactly n - 2 triangles of corner indices (no new points), in a
//            deterministic order that depends only on the corners' coordinates and order
// returns true when the appended triangles meet only in shared corners and edges (always
// for n = 3; for a simple projection, below), false for the fan fallback
//
// Polygon faces are triangulated in the plane of the polygon: the corners are projected
// along the axis where the polygon's (Newell) normal is largest, and if that projection is
// a simple polygon (checked exactly: no two boundary edges meet except consecutive ones at
// their shared corner, no repeated positions), the result is the fan from the first corner
// if that fan is valid (every fan triangle oriented like the polygon: convex polygons, so
// meshes of convex faces keep the triangles every other tool makes), for a quad otherwise
// the fan from the second corner, and otherwise a constrained Delaunay triangulation of
// the projection (CGAL, exact predicates). In all three cases every triangle lies inside
// the polygon, the triangles meet only in shared corners
// and edges, and they keep the polygon's orientation. A planar polygon is thus split into
// triangles that do not overlap; a non-planar one whose projection is simple gets the
// lifting of that 2D triangulation (triangles may fold, never cross each other).
// Otherwise (the projection self-intersects, touches itself or repeats a corner), the
// documented fallback is the fan from the first corner, (c0, c_i, c_(i+1)) for
// i = 1 .. n-2. Triangles (n = 3) are appended as they are. The fan's triangles of a
// self-intersecting face overlap each other (a star of n corners: all of them), so
// arrange() arranges them as a coplanar cluster, and refuses one of more than its budget of
// overlapping triples (arrange.h; a star face of about 180 corners or more) with an
// InputError instead of running out of memory (issue 36).
//
// Exactness: the decision "simple or not" and every orientation used by the triangulation
// are exact predicates (no rounding decides anything): for doubles tritri::orient2d and
// CGAL's Epick, for rationals rational arithmetic (CGAL::Simple_cartesian<Gmpq>). The
// projection axis is chosen from the Newell normal, in long double for doubles (which only
// selects among valid triangulations) and exactly for rationals.
// Cost: O(n log n) expected predicates for a simple projection, O(n) for the fallback
// (rationals: each predicate costs rational arithmetic on the coordinates' sizes).
#pragma once

#include <span>
#include <vector>

#include "arrangements/triangle_soup.h"

namespace arrangements {

bool triangulate_polygon(const std::vector<Vec3>& V, std::span<const int> corners, std::vector<Tri>& out);
bool triangulate_polygon(const std::vector<ExactVec3>& V, std::span<const int> corners, std::vector<Tri>& out);

}  // namespace arrangements
