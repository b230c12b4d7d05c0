// arrangements/src/support/side_of_line.h
//
// side_of_line(a, b, x, plane): the sign of orient2d(a, b, x) in `plane`, exactly, for
// explicit points a, b and a point x of the intersection graph or the triangulation.
//
// Why it is often cheap: every LPI the pipeline makes is an edge crossing (stage 3: an
// edge of one triangle meets the other's face or edge in the open edge), defined by the
// line through that edge's ends p, q (its first two defining points), and lies strictly
// inside segment pq. orient2d is affine in its last argument, so orient2d(a, b, x) =
// (1 - l) orient2d(a, b, p) + l orient2d(a, b, q) with 0 < l < 1: when the two signs agree,
// or one of them is zero, that is the sign, from two explicit predicates. Otherwise (the
// line ab separates p from q), and for explicit points and TPIs, tritri::orient2d decides.
// On the line by definition: with `third` given (a, b, third a proper triangle whose plane
// contains x), an LPI whose plane is defined by a, b and a point w strictly off that plane
// (an auxiliary point, or another triangle's corner; one explicit orient3d) meets that
// triangle's plane in line ab, so x is on it: 0, with no exact implicit arithmetic (an
// exact zero is the most expensive answer of the implicit predicate).
// Precondition: an LPI x lies strictly inside the segment of its first two defining
// points (true of every LPI of IntersectionGraph::points); with `third`, x lies in plane
// (a, b, third). Cost: two double orient2d when that decides, else one implicit
// orient2d more.
#pragma once

#include <tritri/double_predicates.h>
#include <tritri/implicit_predicates.h>

namespace arrangements {

inline int side_of_line(const tritri::ImplicitPoint& a, const tritri::ImplicitPoint& b, const tritri::ImplicitPoint& x,
                        tritri::Plane plane, const tritri::ImplicitPoint* third = nullptr) {
  if (x.kind() == tritri::ImplicitPoint::Kind::LPI && a.is_explicit() && b.is_explicit()) {
    if (third && third->is_explicit()) {
      int found = 0, w = -1;  // a and b among the plane points 2..4; w the other one
      for (int i = 2; i < 5; ++i) {
        if (x.input(i) == a.approx() || x.input(i) == b.approx())
          ++found;
        else
          w = i;
      }
      if (found == 2 && w >= 0 &&
          tritri::orient3d(a.approx(), b.approx(), third->approx(), x.input(w)) != tritri::Sign::Zero)
        return 0;
    }
    const int sp = tritri::to_int(tritri::orient2d(a.approx(), b.approx(), x.input(0), plane));
    const int sq = tritri::to_int(tritri::orient2d(a.approx(), b.approx(), x.input(1), plane));
    if (sp == sq || sq == 0) return sp;
    if (sp == 0) return sq;
  }
  return tritri::to_int(tritri::orient2d(a, b, x, plane));
}

}  // namespace arrangements
