// arrangements/src/models/point_model.h
//
// PointModel: what the pipeline's stages (arrangements/src/stages/) ask of a number
// representation. Each stage is written once, as a template on a model M, and compiled
// for two models:
//   DoubleModel (double_model.h)  double input; new points are implicit (LPI, TPI) over the
//                                 input doubles, never rounded; filtered exact predicates
//                                 with certified bounds: the fast path
//   ExactModel  (exact_model.h)   rational input (any coordinate a rational, e.g. a vertex
//                                 of an exact arrangement); every point a CGAL::Epeck point
//                                 with rational coordinates, made when the point is made
// arrange(TriangleSoup) runs the first, arrange(ExactTriangleSoup) the second
// (arrangements/arrange.h); the file loader picks by the file's coordinates.
//
// A model M provides (all static; every predicate exact for any point the model makes):
//   Input, Vertex, Point       the public input coordinates; an input vertex in the
//                              stages; any point (vertex, LPI, TPI)
//   Kernel                     a tritri kernel (tritri/kernel_concept.h) on Vertex: stage 3
//                              classifies with it
//   vertex(Input) -> Vertex, hash(Vertex)      stage 1 (hash consistent with equality)
//   projection(a, b, c) -> (Plane, orientation) a projection where abc is not degenerate
//                              (orientation 0: degenerate in every projection)
//   bounds(Vertex, lo, hi)     a box that certainly holds the vertex (stage 2)
//   PlaneCache, plane_cache(a, b, c), side_of_plane(cache, a, b, c, d)
//                              orient3d(a, b, c, d) with a per-triangle cache (stage 2)
//   explicit_point(Vertex), lpi(p, q, r, s, t), tpi(9 vertices), auxiliary_point(a, b, c)
//                              constructions: line pq with plane rst, three planes, a
//                              point strictly off plane abc (each one non-degenerate by an
//                              exact test, or refused with std::logic_error)
//   Key, key(Point), compare(p, kp, q, kq)     a total order on points, exact, monotone
//                              along every line (edge points are sorted by it), with a
//                              per-point key that makes most comparisons cheap
//   compare_xyz(p, q), vertex_less(a, b)       exact lexicographic order
//   Box, box(Point), side_bounded(a, b, box, plane)   a certified box around a point and
//                              the sign of orient2d(a, b, x) for every x in it, or
//                              tritri::kUndecided
//   side_of_line(a, b, x, plane, third)        orient2d(a, b, x) (third: see
//                              support/side_of_line.h)
//   orient3d, orient2d on vertices; Local, local(Point, origin), orient2d_local
//                              the points of one triangle's local triangulation
//   unscaled(Point, k)         the point of a model scaled by 2^k in the unscaled frame
//   to_exact(Point), to_double(Point)          exact rationals; nearest doubles
//   kCanScale                  whether preprocessing may scale by 2^k (doubles only)
//   kProjectionFirst           stage 2 tries projections before plane signs (rationals:
//                              an exact zero costs far more than an interval orient2d)
#pragma once

#include <concepts>
#include <cstdint>
#include <utility>

#include <tritri/kernel_concept.h>

#include "arrangements/triangle_soup.h"

namespace arrangements {

template <class M>
concept PointModel = tritri::Kernel<typename M::Kernel> &&
    std::same_as<typename M::Kernel::Point, typename M::Vertex> &&
    requires(const typename M::Input& in, const typename M::Vertex& v, const typename M::Point& p,
             const typename M::Key& k, const typename M::Box& box, tritri::Plane plane, Vec3& d) {
  { M::vertex(in) } -> std::same_as<typename M::Vertex>;
  { M::hash(v) } -> std::same_as<std::uint64_t>;
  { M::projection(v, v, v) } -> std::same_as<std::pair<tritri::Plane, int>>;
  M::bounds(v, d, d);
  { M::side_of_plane(M::plane_cache(v, v, v), v, v, v, v) } -> std::same_as<tritri::Sign>;
  { M::explicit_point(v) } -> std::same_as<typename M::Point>;
  { M::lpi(v, v, v, v, v) } -> std::same_as<typename M::Point>;
  { M::tpi(v, v, v, v, v, v, v, v, v) } -> std::same_as<typename M::Point>;
  { M::auxiliary_point(v, v, v) } -> std::same_as<typename M::Vertex>;
  { M::key(p) } -> std::same_as<typename M::Key>;
  { M::compare(p, k, p, k) } -> std::same_as<int>;
  { M::compare_xyz(p, p) } -> std::same_as<int>;
  { M::vertex_less(v, v) } -> std::same_as<bool>;
  { M::box(p) } -> std::same_as<typename M::Box>;
  { M::side_bounded(v, v, box, plane) } -> std::same_as<int>;
  { M::side_of_line(p, p, p, plane, &p) } -> std::same_as<int>;
  { M::orient3d(v, v, v, v) } -> std::same_as<tritri::Sign>;
  { M::orient2d(v, v, v, plane) } -> std::same_as<tritri::Sign>;
  { M::orient2d_local(M::local(p, v), M::local(p, v), M::local(p, v), plane) } -> std::same_as<tritri::Sign>;
  { M::unscaled(p, 0) } -> std::same_as<typename M::Point>;
  { M::to_exact(p) } -> std::same_as<ExactVec3>;
  { M::to_double(p) } -> std::same_as<Vec3>;
  { M::kCanScale } -> std::convertible_to<bool>;
  { M::kProjectionFirst } -> std::convertible_to<bool>;
};

}  // namespace arrangements
