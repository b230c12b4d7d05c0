// Polygon faces -> triangles (see triangulate_polygon.h): one algorithm on double or exact
// rational coordinates; only the exact predicates and the CDT's kernel differ.
#include "io/triangulate_polygon.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cmath>
#include <cstddef>
#include <deque>
#include <utility>

#include <tritri/double_predicates.h>

namespace arrangements {
namespace {

// Exact predicates are all the triangulation needs: constraints that meet anywhere but at a
// shared end throw instead of being split at a constructed point. Doubles: CGAL's filtered
// kernel; rationals: plain rational arithmetic (every predicate exact).
template <class Coordinates>
struct CdtKernel;
template <>
struct CdtKernel<Vec3> {
  using type = CGAL::Exact_predicates_inexact_constructions_kernel;
};
template <>
struct CdtKernel<ExactVec3> {
  using type = CGAL::Simple_cartesian<CGAL::Gmpq>;
};

template <class K>
using CdtOf = CGAL::Constrained_Delaunay_triangulation_2<
    K,
    CGAL::Triangulation_data_structure_2<
        CGAL::Triangulation_vertex_base_with_info_2<int, K>,  // corner position in the face
        CGAL::Constrained_triangulation_face_base_2<K, CGAL::Triangulation_face_base_with_info_2<int, K>>>,
    CGAL::No_constraint_intersection_tag>;

tritri::Sign orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  return tritri::orient2d(ax, ay, bx, by, cx, cy);
}
tritri::Sign orient2d(const CGAL::Gmpq& ax, const CGAL::Gmpq& ay, const CGAL::Gmpq& bx, const CGAL::Gmpq& by,
                      const CGAL::Gmpq& cx, const CGAL::Gmpq& cy) {
  const CGAL::Gmpq det = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  return det > 0 ? tritri::Sign::Positive : det < 0 ? tritri::Sign::Negative : tritri::Sign::Zero;
}

void fan(std::span<const int> corners, std::vector<Tri>& out) {
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) out.push_back({corners[0], corners[i], corners[i + 1]});
}

// The orientation of the projected triangle (corners i, j, k), exactly.
template <class Coordinates>
tritri::Sign orientation(const std::vector<Coordinates>& V, std::span<const int> c, int axis, std::size_t i,
                         std::size_t j, std::size_t k) {
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  return orient2d(V[c[i]][a], V[c[i]][b], V[c[j]][a], V[c[j]][b], V[c[k]][a], V[c[k]][b]);
}

// True when every triangle of the fan from corner `apex` has orientation `sign` (!= Zero).
// For a simple polygon of that orientation the fan then tiles it: the signed areas add up
// to the polygon's, each point inside is covered with multiplicity 1, and all are positive.
template <class Coordinates>
bool fan_is_valid(const std::vector<Coordinates>& V, std::span<const int> c, int axis, std::size_t apex,
                  tritri::Sign sign) {
  const std::size_t n = c.size();
  for (std::size_t i = 1; i + 1 < n; ++i)
    if (orientation(V, c, axis, apex, (apex + i) % n, (apex + i + 1) % n) != sign) return false;
  return sign != tritri::Sign::Zero;
}

// The axis along which the polygon's Newell normal is largest (its projection is the most
// faithful); -1 if the normal vanishes (or, for doubles, overflows). Only a choice: the
// result is checked. Doubles: in long double; rationals: exactly.
int largest_axis(const auto(&n)[3]) {
  int axis = -1;
  for (int k = 0; k < 3; ++k)
    if (n[k] != 0 && (axis < 0 || (n[k] < 0 ? -n[k] : n[k]) > (n[axis] < 0 ? -n[axis] : n[axis]))) axis = k;
  return axis;
}

int projection_axis(const std::vector<Vec3>& V, std::span<const int> corners) {
  long double n[3] = {0, 0, 0};
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec3& p = V[corners[i]];
    const Vec3& q = V[corners[(i + 1) % corners.size()]];
    for (int k = 0; k < 3; ++k) {
      const int a = (k + 1) % 3, b = (k + 2) % 3;
      n[k] += (static_cast<long double>(p[a]) - q[a]) * (static_cast<long double>(p[b]) + q[b]);
    }
  }
  for (long double& c : n)
    if (!std::isfinite(c)) c = 0;  // an overflowing component is never chosen
  return largest_axis(n);
}

int projection_axis(const std::vector<ExactVec3>& V, std::span<const int> corners) {
  CGAL::Gmpq n[3];
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const ExactVec3& p = V[corners[i]];
    const ExactVec3& q = V[corners[(i + 1) % corners.size()]];
    for (int k = 0; k < 3; ++k) {
      const int a = (k + 1) % 3, b = (k + 2) % 3;
      n[k] += (p[a] - q[a]) * (p[b] + q[b]);
    }
  }
  return largest_axis(n);
}

// Triangulates the projection of a simple polygon; false (and nothing appended) if the
// projection is not simple.
template <class Coordinates>
bool triangulate_simple_projection(const std::vector<Coordinates>& V, std::span<const int> corners, int axis,
                                   std::vector<Tri>& out) {
  using K = typename CdtKernel<Coordinates>::type;
  using Cdt = CdtOf<K>;
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  const std::size_t n = corners.size();
  using Point = typename K::Point_2;
  std::vector<std::pair<Point, int>> points(n);
  for (std::size_t i = 0; i < n; ++i) points[i] = {Point(V[corners[i]][a], V[corners[i]][b]), static_cast<int>(i)};
  Cdt cdt;
  cdt.insert(points.begin(), points.end());
  if (cdt.number_of_vertices() != n) return false;  // a repeated position
  std::vector<typename Cdt::Vertex_handle> handle(n);
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) handle[v->info()] = v;
  try {
    for (std::size_t i = 0; i < n; ++i) cdt.insert_constraint(handle[i], handle[(i + 1) % n]);
  } catch (const typename Cdt::Intersection_of_constraints_exception&) {
    return false;  // two boundary edges meet
  }
  // A corner on another boundary edge (or collinear overlap) splits that edge.
  typename Cdt::Face_handle f;
  int e = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (!cdt.is_edge(handle[i], handle[(i + 1) % n], f, e)) return false;

  // The polygon's orientation in the projection, exactly: at its lexicographically
  // smallest corner the boundary turns convexly (simple polygons only).
  std::size_t m = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (points[i].first < points[m].first) m = i;
  const tritri::Sign orient = orientation(V, corners, axis, (m + n - 1) % n, m, (m + 1) % n);
  if (fan_is_valid(V, corners, axis, 0, orient)) {  // the fan upstream and older files use
    fan(corners, out);
    return true;
  }

  // Inside: faces reached from the infinite face by crossing an odd number of constraints.
  for (auto fh = cdt.all_faces_begin(); fh != cdt.all_faces_end(); ++fh) fh->info() = -1;
  std::deque<std::pair<typename Cdt::Face_handle, int>> todo = {{cdt.infinite_face(), 0}};
  while (!todo.empty()) {
    auto [fh, depth] = todo.front();
    todo.pop_front();
    if (fh->info() >= 0) continue;
    fh->info() = depth;
    for (int i = 0; i < 3; ++i) {
      const typename Cdt::Face_handle g = fh->neighbor(i);
      if (g->info() >= 0) continue;
      if (cdt.is_constrained({fh, i}))
        todo.emplace_back(g, depth + 1);
      else
        todo.emplace_front(g, depth);
    }
  }
  std::vector<Tri> inside;
  inside.reserve(n - 2);
  for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh) {
    if (fh->info() % 2 == 0) continue;
    Tri t = {corners[fh->vertex(0)->info()], corners[fh->vertex(1)->info()], corners[fh->vertex(2)->info()]};
    if (orient == tritri::Sign::Negative) std::swap(t[1], t[2]);  // CGAL's faces are counterclockwise
    inside.push_back(t);
  }
  if (inside.size() != n - 2) return false;  // cannot happen for a simple boundary
  out.insert(out.end(), inside.begin(), inside.end());
  return true;
}

template <class Coordinates>
bool triangulate(const std::vector<Coordinates>& V, std::span<const int> corners, std::vector<Tri>& out) {
  if (corners.size() == 3) {
    out.push_back({corners[0], corners[1], corners[2]});
    return true;
  }
  const int axis = projection_axis(V, corners);
  if (axis >= 0 && corners.size() == 4) {
    // A quad is simple, and split without overlap, iff its two triangles on one diagonal
    // have the same orientation (the other two corners lie on opposite sides of it).
    for (std::size_t apex : {0, 1}) {
      const tritri::Sign s = orientation(V, corners, axis, apex, apex + 1, apex + 2);
      if (s != tritri::Sign::Zero && fan_is_valid(V, corners, axis, apex, s)) {
        for (std::size_t i = 1; i + 1 < 4; ++i)
          out.push_back({corners[apex], corners[(apex + i) % 4], corners[(apex + i + 1) % 4]});
        return true;
      }
    }
  } else if (axis >= 0 && triangulate_simple_projection(V, corners, axis, out)) {
    return true;
  }
  fan(corners, out);
  return false;
}

}  // namespace

bool triangulate_polygon(const std::vector<Vec3>& V, std::span<const int> corners, std::vector<Tri>& out) {
  return triangulate(V, corners, out);
}

bool triangulate_polygon(const std::vector<ExactVec3>& V, std::span<const int> corners, std::vector<Tri>& out) {
  return triangulate(V, corners, out);
}

}  // namespace arrangements
