// tritri/detail/incidence.h
//
// Incidences known by construction, which decide exact zeros of the implicit predicates
// without evaluating them:
//   on_common_plane(points)   every point lies on one plane some operand was built from
//                             (orient3d of them is 0);
//   on_common_line(points)    every point lies on one line some operand was built from
//                             (orient2d of them, in any projection, is 0);
//   known_coordinate(p, k)    p's k-th coordinate as a double when p is explicit or lies
//                             on a line or plane that is constant in k;
//   same_point_by_construction(p, q)   LPIs of one line and plane, TPIs of one set of planes;
//   orient3d_known_zero(points), orient2d_known_zero(points, plane)   the predicates' zeros
//                             that follow from the above: a repeated point, a common plane
//                             (in 2D: one the projection flattens to a line), a common line,
//                             a coordinate every point shares.
// What a point lies on: an explicit point on every plane and line it is a defining corner
// of; an LPI (p, q, r, s, t) on its line pq and its plane rst, on every plane that has
// p and q as corners and on that plane's meet with rst; a TPI on its three planes and on
// the lines where two of them meet.
//
// Why: after the filters, the exact stage is reached mostly by such zeros (points on one
// input edge, sub-triangles of one input triangle, points on one axis-aligned face), and
// its cost grows with the spread of the inputs' exponents: with subnormal coordinates
// beside O(1) ones, one Mpzf evaluation multiplies numbers of thousands of bits (issue 36).
// A false / empty answer only means "not known": the caller then evaluates exactly.
//
// Exactness: planes and lines are compared through their defining doubles, by ==. A
// defining plane is never degenerate and the planes of a TPI are independent (W != 0,
// ImplicitPoint::make), so equal corners mean the same plane and two planes of one TPI
// meet in a line. Cost: a few dozen double comparisons, paid only where the filters failed.
#pragma once

#include <array>
#include <initializer_list>
#include <optional>

#include "tritri/double_predicates.h"
#include "tritri/implicit_point.h"

namespace tritri::detail {

using Corner = ImplicitPoint::Coords;
using PlaneCorners = std::array<const Corner*, 3>;

// The defining planes of a point: an LPI's plane, a TPI's three; none if explicit.
inline int defining_planes(const ImplicitPoint& p, PlaneCorners out[3]) {
  if (p.is_explicit()) return 0;
  if (p.kind() == ImplicitPoint::Kind::LPI) {
    out[0] = {&p.input(2), &p.input(3), &p.input(4)};
    return 1;
  }
  for (int k = 0; k < 3; ++k) out[k] = {&p.input(3 * k), &p.input(3 * k + 1), &p.input(3 * k + 2)};
  return 3;
}

inline bool is_corner(const Corner& c, const PlaneCorners& plane) {
  return c == *plane[0] || c == *plane[1] || c == *plane[2];
}

// The same three corners, in any order (the corners of a defining plane are distinct).
inline bool same_plane(const PlaneCorners& a, const PlaneCorners& b) {
  return is_corner(*a[0], b) && is_corner(*a[1], b) && is_corner(*a[2], b);
}

inline bool lies_on_plane(const ImplicitPoint& p, const PlaneCorners& plane) {
  if (p.is_explicit()) return is_corner(p.approx(), plane);
  if (p.kind() == ImplicitPoint::Kind::LPI && is_corner(p.input(0), plane) && is_corner(p.input(1), plane))
    return true;
  PlaneCorners own[3];
  const int n = defining_planes(p, own);
  for (int k = 0; k < n; ++k)
    if (same_plane(own[k], plane)) return true;
  return false;
}

// A line by construction: two distinct corners, or two independent defining planes.
struct ConstructedLine {
  const Corner* a = nullptr;  // the two-corner form when set
  const Corner* b = nullptr;
  PlaneCorners p0{}, p1{};  // the two-plane form otherwise
};

inline bool lies_on_line(const ImplicitPoint& p, const ConstructedLine& line) {
  if (line.a) {
    if (p.is_explicit()) return p.approx() == *line.a || p.approx() == *line.b;
    if (p.kind() == ImplicitPoint::Kind::LPI)
      return (p.input(0) == *line.a && p.input(1) == *line.b) || (p.input(0) == *line.b && p.input(1) == *line.a);
    // A TPI lies on the line when two of its planes contain both corners.
    PlaneCorners own[3];
    defining_planes(p, own);
    int containing = 0;
    for (const PlaneCorners& plane : own) containing += is_corner(*line.a, plane) && is_corner(*line.b, plane);
    return containing >= 2;
  }
  return lies_on_plane(p, line.p0) && lies_on_plane(p, line.p1);
}

// The lines a point was built on: an LPI's line, the three meets of a TPI's planes.
inline int constructed_lines(const ImplicitPoint& p, ConstructedLine out[3]) {
  if (p.is_explicit()) return 0;
  if (p.kind() == ImplicitPoint::Kind::LPI) {
    out[0] = ConstructedLine{&p.input(0), &p.input(1), {}, {}};
    return 1;
  }
  PlaneCorners own[3];
  defining_planes(p, own);
  out[0] = ConstructedLine{nullptr, nullptr, own[0], own[1]};
  out[1] = ConstructedLine{nullptr, nullptr, own[0], own[2]};
  out[2] = ConstructedLine{nullptr, nullptr, own[1], own[2]};
  return 3;
}

// Three corners whose affine hull holds every point, when known: a defining plane of
// some operand that all the others lie on; else, when no operand is a TPI, the explicit
// points and the LPIs' line corners if they are at most three (repeated to fill three
// when fewer: then all lie on one line or are one point).
inline std::optional<PlaneCorners> common_plane(std::initializer_list<const ImplicitPoint*> points) {
  for (const ImplicitPoint* candidate : points) {
    PlaneCorners planes[3];
    const int n = defining_planes(*candidate, planes);
    for (int k = 0; k < n; ++k) {
      bool all = true;
      for (const ImplicitPoint* p : points) all = all && (p == candidate || lies_on_plane(*p, planes[k]));
      if (all) return planes[k];
    }
  }
  const Corner* corners[3] = {};
  int count = 0;
  auto add = [&](const Corner& c) {
    for (int i = 0; i < count; ++i)
      if (*corners[i] == c) return true;
    if (count == 3) return false;
    corners[count++] = &c;
    return true;
  };
  for (const ImplicitPoint* p : points) {
    if (p->is_explicit()) {
      if (!add(p->approx())) return std::nullopt;
    } else if (p->kind() != ImplicitPoint::Kind::LPI || !add(p->input(0)) || !add(p->input(1))) {
      return std::nullopt;
    }
  }
  if (count == 0) return std::nullopt;
  return PlaneCorners{corners[0], corners[count > 1 ? 1 : 0], corners[count > 2 ? 2 : count - 1]};
}

inline bool on_common_plane(std::initializer_list<const ImplicitPoint*> points) {
  return common_plane(points).has_value();
}

// The same point by construction: two LPIs of one line (two corners, in either order)
// and one plane, or two TPIs of the same three planes, in any order.
inline bool same_point_by_construction(const ImplicitPoint& p, const ImplicitPoint& q) {
  if (p.is_explicit() || q.is_explicit() || p.kind() != q.kind()) return false;
  PlaneCorners pp[3], qp[3];
  const int n = defining_planes(p, pp);
  defining_planes(q, qp);
  if (p.kind() == ImplicitPoint::Kind::LPI)
    return same_plane(pp[0], qp[0]) && ((p.input(0) == q.input(0) && p.input(1) == q.input(1)) ||
                                        (p.input(0) == q.input(1) && p.input(1) == q.input(0)));
  // Three independent planes (W != 0): as sets, each of p's is one of q's, all distinct.
  for (int i = 0; i < n; ++i)
    if (!same_plane(pp[i], qp[0]) && !same_plane(pp[i], qp[1]) && !same_plane(pp[i], qp[2])) return false;
  return true;
}

// p's coordinate k exactly, when p is explicit or lies on a defining plane (or an LPI on
// a line) whose corners all share that coordinate.
inline std::optional<double> known_coordinate(const ImplicitPoint& p, int k) {
  if (p.is_explicit()) return p.approx()[k];
  if (p.kind() == ImplicitPoint::Kind::LPI && p.input(0)[k] == p.input(1)[k]) return p.input(0)[k];
  PlaneCorners own[3];
  const int n = defining_planes(p, own);
  for (int i = 0; i < n; ++i)
    if ((*own[i][0])[k] == (*own[i][1])[k] && (*own[i][0])[k] == (*own[i][2])[k]) return (*own[i][0])[k];
  return std::nullopt;
}

// The value c when every point's coordinate k is known and equals c.
inline std::optional<double> common_known_coordinate(std::initializer_list<const ImplicitPoint*> points, int k) {
  std::optional<double> c;
  for (const ImplicitPoint* p : points) {
    const auto pk = known_coordinate(*p, k);
    if (!pk || (c && *c != *pk)) return std::nullopt;
    c = pk;
  }
  return c;
}

// On one axis-aligned plane {x_k = c}, and either on a second one or on a common defining
// plane that is not parallel to it (its corners differ in k): on their meet, a line.
inline bool on_common_axis_line(std::initializer_list<const ImplicitPoint*> points) {
  for (int k = 0; k < 3; ++k) {
    if (!common_known_coordinate(points, k)) continue;
    if (common_known_coordinate(points, (k + 1) % 3) || common_known_coordinate(points, (k + 2) % 3)) return true;
    for (const ImplicitPoint* candidate : points) {
      PlaneCorners planes[3];
      const int n = defining_planes(*candidate, planes);
      for (int i = 0; i < n; ++i) {
        const PlaneCorners& pl = planes[i];
        if ((*pl[0])[k] == (*pl[1])[k] && (*pl[0])[k] == (*pl[2])[k]) continue;  // parallel
        bool all = true;
        for (const ImplicitPoint* p : points) all = all && (p == candidate || lies_on_plane(*p, pl));
        if (all) return true;
      }
    }
    return false;  // a second common constant axis was looked for above
  }
  return false;
}

inline bool all_on_line(std::initializer_list<const ImplicitPoint*> points, const ConstructedLine& line) {
  for (const ImplicitPoint* p : points)
    if (!lies_on_line(*p, line)) return false;
  return true;
}

inline bool on_common_line(std::initializer_list<const ImplicitPoint*> points) {
  for (const ImplicitPoint* candidate : points) {
    ConstructedLine lines[3];
    const int n = constructed_lines(*candidate, lines);
    for (int k = 0; k < n; ++k)
      if (all_on_line(points, lines[k])) return true;
    // An LPI also lies on the meet of its plane with any plane through its line (another
    // point's defining plane with p and q as corners): a line, since pq is not parallel
    // to the LPI's plane. This is the segment where two input triangles cross.
    if (candidate->is_explicit() || candidate->kind() != ImplicitPoint::Kind::LPI) continue;
    const PlaneCorners own{&candidate->input(2), &candidate->input(3), &candidate->input(4)};
    for (const ImplicitPoint* other : points) {
      PlaneCorners planes[3];
      const int m = other == candidate ? 0 : defining_planes(*other, planes);
      for (int i = 0; i < m; ++i)
        if (is_corner(candidate->input(0), planes[i]) && is_corner(candidate->input(1), planes[i]) &&
            !same_plane(planes[i], own) && all_on_line(points, ConstructedLine{nullptr, nullptr, own, planes[i]}))
          return true;
    }
  }
  return on_common_axis_line(points);
}

// Two operands that are one point: the same object, equal explicit coordinates, or built
// twice from the same line and plane(s).
inline bool repeats_a_point(std::initializer_list<const ImplicitPoint*> points) {
  for (auto i = points.begin(); i != points.end(); ++i)
    for (auto j = i + 1; j != points.end(); ++j) {
      const ImplicitPoint& p = **i;
      const ImplicitPoint& q = **j;
      if (&p == &q || (p.is_explicit() && q.is_explicit() && p.approx() == q.approx()) ||
          same_point_by_construction(p, q))
        return true;
    }
  return false;
}

// orient3d of four points is 0 by construction: a repeated point, a common plane, or a
// coordinate all of them share (a common axis-aligned plane).
inline bool orient3d_known_zero(std::initializer_list<const ImplicitPoint*> points) {
  if (repeats_a_point(points) || on_common_plane(points)) return true;
  for (int k = 0; k < 3; ++k)
    if (common_known_coordinate(points, k)) return true;
  return false;
}

// orient2d of three points in the projection dropping one axis is 0 by construction: a
// repeated point, a common line, a common plane that the projection flattens to a line
// (its corners' orient2d there is 0, decided exactly on doubles), or a coordinate all of
// them share on one of the projection's axes.
inline bool orient2d_known_zero(std::initializer_list<const ImplicitPoint*> points, Plane plane) {
  if (repeats_a_point(points) || on_common_line(points)) return true;
  const auto axes = plane_axes(plane);
  if (common_known_coordinate(points, axes[0]) || common_known_coordinate(points, axes[1])) return true;
  const auto corners = common_plane(points);
  return corners && orient2d(*(*corners)[0], *(*corners)[1], *(*corners)[2], plane) == Sign::Zero;
}

}  // namespace tritri::detail
