// tests/support/classify_oracle.h
//
// An independent exact check of one tritri::Result against its input pair:
//
//   1. form: points strictly sorted by (type, id0, id1), ids in range; segments sorted,
//      p0 < p1, indices in range;
//   2. degenerate input (collinear or repeated vertices, exact test): no points, no segments,
//      and `degenerate` set whenever a degenerate triangle is not strictly on one side of
//      the other's plane (or the other has no plane);
//   3. each point lies in the claimed open simplex of BOTH triangles: a vertex equals the
//      vertex, lies strictly inside the open edge, or strictly inside the open face; two
//      open edges cross at one point; an open edge crosses the open face at one point;
//   4. the points, built exactly from their types (a vertex; two edge lines meeting; an edge
//      line meeting a plane), are pairwise distinct and are exactly the corners of
//      CGAL::intersection(Triangle_3, Triangle_3) (duplicates and points strictly between
//      two others removed);
//   5. segments: non-coplanar, (0,1) iff two points; coplanar, the edges of the convex
//      overlap polygon ((0,1) for two points);
//   6. `coplanar` is the exact coplanarity of the six vertices.
//
// Tests on input vertices use InputKernel (CGAL::Epick: exact predicates on doubles, fast
// exact fallback); constructed points and CGAL's intersection use ExactKernel (CGAL::Epeck:
// exact rationals behind an interval filter); both from exact_oracle.h. Nothing here
// calls tritri.
//
// check_classification() returns "" when everything holds, else the first violation;
// locate() gives the exact point of a classified intersection point (also used by the
// intersection-graph reference).
#pragma once

#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <tritri/result.h>

#include "exact_oracle.h"
#include "pair_generators.h"

namespace tritri_test {

// ---------------------------------------------------------------------------------------
// Exact predicates on the input vertices (Epick: exact for double input).

using IPoint = InputKernel::Point_3;
using ITriangle = std::array<IPoint, 3>;

inline IPoint to_input(const Point& p) { return to_cgal<InputKernel>(p); }
inline ITriangle to_input(const Triangle& t) { return {to_input(t[0]), to_input(t[1]), to_input(t[2])}; }

inline bool is_degenerate(const ITriangle& t) { return CGAL::collinear(t[0], t[1], t[2]); }

inline CGAL::Orientation side(const ITriangle& t, const IPoint& x) { return CGAL::orientation(t[0], t[1], t[2], x); }

// All three vertices of t strictly on one side of the plane of the non-degenerate `other`.
inline bool strictly_one_side(const ITriangle& t, const ITriangle& other) {
  const auto s0 = side(other, t[0]);
  return s0 != CGAL::COPLANAR && side(other, t[1]) == s0 && side(other, t[2]) == s0;
}

// The open segments (p, q) and (r, s) cross at exactly one point, inside both.
inline bool open_segments_cross(const IPoint& p, const IPoint& q, const IPoint& r, const IPoint& s) {
  if (CGAL::orientation(p, q, r, s) != CGAL::COPLANAR) return false;
  // 2D orientations in the common plane, coherent for any triple in it (collinear: 0).
  auto o = [](const IPoint& a, const IPoint& b, const IPoint& c) { return int(CGAL::coplanar_orientation(a, b, c)); };
  return o(p, q, r) * o(p, q, s) < 0 && o(r, s, p) * o(r, s, q) < 0;
}

// The open segment (p, q) crosses the open face of the non-degenerate t at one point.
inline bool open_segment_crosses_open_face(const IPoint& p, const IPoint& q, const ITriangle& t) {
  if (int(side(t, p)) * int(side(t, q)) >= 0) return false;  // q and p strictly apart
  const auto s = CGAL::orientation(p, q, t[0], t[1]);
  return s != CGAL::COPLANAR && CGAL::orientation(p, q, t[1], t[2]) == s && CGAL::orientation(p, q, t[2], t[0]) == s;
}

// ---------------------------------------------------------------------------------------
// Claims made by an intersection type.

enum class Simplex { Vertex, Edge, Face };

// The simplices of A and of B that an intersection type names.
struct Claim {
  Simplex in_a;
  int id_a;
  Simplex in_b;
  int id_b;
};

inline Claim claim_of(const tritri::IntersectionPoint& p) {
  using tritri::Type;
  switch (p.type) {
    case Type::VA_ON_VB:
      return {Simplex::Vertex, p.id0, Simplex::Vertex, p.id1};
    case Type::VA_ON_EB:
      return {Simplex::Vertex, p.id0, Simplex::Edge, p.id1};
    case Type::VB_ON_EA:
      return {Simplex::Edge, p.id1, Simplex::Vertex, p.id0};
    case Type::VA_ON_TB:
      return {Simplex::Vertex, p.id0, Simplex::Face, -1};
    case Type::VB_ON_TA:
      return {Simplex::Face, -1, Simplex::Vertex, p.id0};
    case Type::EA_CROSS_EB:
      return {Simplex::Edge, p.id0, Simplex::Edge, p.id1};
    case Type::EA_CROSS_TB:
      return {Simplex::Edge, p.id0, Simplex::Face, -1};
    default:
      return {Simplex::Face, -1, Simplex::Edge, p.id0};  // EB_CROSS_TA
  }
}

// Vertex v of one triangle lies in simplex (s, id) of the other triangle t.
inline bool vertex_in_open_simplex(const IPoint& v, const ITriangle& t, Simplex s, int id) {
  switch (s) {
    case Simplex::Vertex:
      return v == t[id];
    case Simplex::Edge:
      return in_open_segment(v, t[id], t[(id + 1) % 3]);
    default:
      return in_open_face(v, t);
  }
}

// "" if the point named p exists where its type says (item 3 above), else why not.
inline std::string check_claim(const tritri::IntersectionPoint& p, const ITriangle& a, const ITriangle& b) {
  const Claim c = claim_of(p);
  if (c.in_a == Simplex::Vertex && !vertex_in_open_simplex(a[c.id_a], b, c.in_b, c.id_b))
    return "vertex of A is not where the type says in B";
  if (c.in_b == Simplex::Vertex && !vertex_in_open_simplex(b[c.id_b], a, c.in_a, c.id_a))
    return "vertex of B is not where the type says in A";
  auto edge = [](const ITriangle& t, int e) { return std::pair(t[e], t[(e + 1) % 3]); };
  if (c.in_a == Simplex::Edge && c.in_b == Simplex::Edge) {
    const auto [p0, p1] = edge(a, c.id_a);
    const auto [q0, q1] = edge(b, c.id_b);
    if (!open_segments_cross(p0, p1, q0, q1)) return "the open edges do not cross at a single point";
  }
  if (c.in_a == Simplex::Edge && c.in_b == Simplex::Face) {
    const auto [p0, p1] = edge(a, c.id_a);
    if (!open_segment_crosses_open_face(p0, p1, b)) return "the open edge of A does not cross the open face of B";
  }
  if (c.in_a == Simplex::Face && c.in_b == Simplex::Edge) {
    const auto [q0, q1] = edge(b, c.id_b);
    if (!open_segment_crosses_open_face(q0, q1, a)) return "the open edge of B does not cross the open face of A";
  }
  return "";
}

// ---------------------------------------------------------------------------------------
// Exact points (Epeck) and CGAL's answer.

using OPoint = ExactKernel::Point_3;
using OTriangle = std::array<OPoint, 3>;

inline OPoint to_oracle(const Point& p) { return to_cgal<ExactKernel>(p); }
inline OTriangle to_oracle(const Triangle& t) { return {to_oracle(t[0]), to_oracle(t[1]), to_oracle(t[2])}; }

// The exact location of a point whose claim holds (check_claim): a vertex, or the meeting
// point of the two edge lines, or of the edge line and the other triangle's plane.
inline OPoint locate(const tritri::IntersectionPoint& p, const OTriangle& a, const OTriangle& b) {
  using tritri::Type;
  auto line = [](const OTriangle& t, int e) { return ExactKernel::Line_3(t[e], t[(e + 1) % 3]); };
  switch (p.type) {
    case Type::VA_ON_VB:
    case Type::VA_ON_EB:
    case Type::VA_ON_TB:
      return a[p.id0];
    case Type::VB_ON_EA:
    case Type::VB_ON_TA:
      return b[p.id0];
    case Type::EA_CROSS_EB: {
      const auto x = CGAL::intersection(line(a, p.id0), line(b, p.id1));
      return *boost::get<OPoint>(&*x);
    }
    default: {
      const bool a_edge = p.type == Type::EA_CROSS_TB;
      const OTriangle& e = a_edge ? a : b;
      const OTriangle& f = a_edge ? b : a;
      const auto x = CGAL::intersection(line(e, p.id0), ExactKernel::Plane_3(f[0], f[1], f[2]));
      return *boost::get<OPoint>(&*x);
    }
  }
}

// The corners of a finite set of points on the boundary of a convex set (a point, a segment
// or a convex polygon): duplicates and points strictly between two others removed.
inline std::vector<OPoint> corners(const std::vector<OPoint>& pts) {
  std::vector<OPoint> unique;
  for (const OPoint& p : pts)
    if (std::find(unique.begin(), unique.end(), p) == unique.end()) unique.push_back(p);
  std::vector<OPoint> out;
  for (std::size_t i = 0; i < unique.size(); ++i) {
    bool between = false;
    for (std::size_t j = 0; j < unique.size() && !between; ++j)
      for (std::size_t k = j + 1; k < unique.size() && !between; ++k)
        if (j != i && k != i)
          between = CGAL::collinear(unique[j], unique[k], unique[i]) &&
                    CGAL::collinear_are_strictly_ordered_along_line(unique[j], unique[i], unique[k]);
    if (!between) out.push_back(unique[i]);
  }
  return out;
}

// The corners of A ∩ B according to CGAL's exact intersection (non-degenerate triangles).
inline std::vector<OPoint> cgal_corners(const OTriangle& a, const OTriangle& b) {
  using K = ExactKernel;
  const auto x = CGAL::intersection(K::Triangle_3(a[0], a[1], a[2]), K::Triangle_3(b[0], b[1], b[2]));
  std::vector<OPoint> pts;
  if (!x) return pts;
  if (const auto* p = boost::get<OPoint>(&*x)) {
    pts.push_back(*p);
  } else if (const auto* s = boost::get<K::Segment_3>(&*x)) {
    pts = {s->source(), s->target()};
  } else if (const auto* t = boost::get<K::Triangle_3>(&*x)) {
    pts = {t->vertex(0), t->vertex(1), t->vertex(2)};
  } else if (const auto* v = boost::get<std::vector<OPoint>>(&*x)) {
    pts = *v;
  }
  return corners(pts);
}

// ---------------------------------------------------------------------------------------
// The check.

inline std::string point_string(const OPoint& p) { return to_string(exact(p)); }

inline std::string points_string(const std::vector<OPoint>& pts) {
  std::string s = "{";
  for (std::size_t i = 0; i < pts.size(); ++i) s += (i ? ", " : "") + point_string(pts[i]);
  return s + "}";
}

inline std::string result_string(const tritri::Result& r) {
  std::ostringstream os;
  os << r;
  return os.str();
}

inline std::string point_name(const tritri::IntersectionPoint& p) {
  return std::string(tritri::to_string(p.type)) + "(" + std::to_string(p.id0) + "," + std::to_string(p.id1) + ")";
}

// Form of the result: sorting, id ranges, segment indices.
inline std::string check_form(const tritri::Result& r) {
  using tritri::Type;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const auto& p = r.points[i];
    const int t = static_cast<int>(p.type);
    if (t < 0 || t > 7) return "point type out of range";
    const bool face = p.type == Type::VA_ON_TB || p.type == Type::VB_ON_TA || p.type == Type::EA_CROSS_TB ||
                      p.type == Type::EB_CROSS_TA;
    if (p.id0 < 0 || p.id0 > 2) return "id0 out of range";
    if (face ? p.id1 != -1 : (p.id1 < 0 || p.id1 > 2)) return "id1 out of range";
    if (i > 0 && !(r.points[i - 1] < p)) return "points not strictly sorted by (type, id0, id1)";
  }
  for (std::size_t i = 0; i < r.segments.size(); ++i) {
    const auto& s = r.segments[i];
    if (s.p0 < 0 || s.p0 >= s.p1 || static_cast<std::size_t>(s.p1) >= r.points.size())
      return "segment indices invalid (need 0 <= p0 < p1 < points.size())";
    if (i > 0) {
      const auto& q = r.segments[i - 1];
      if (!(q.p0 < s.p0 || (q.p0 == s.p0 && q.p1 < s.p1))) return "segments not strictly sorted";
    }
  }
  return "";
}

// The expected segments for the exact corners x (in the result's order): (0,1) for two
// points; for a coplanar polygon, the pairs (i, j) with every other corner strictly on one
// side of line ij (n: the common plane's normal).
inline std::vector<tritri::Segment> expected_segments(const std::vector<OPoint>& x, bool coplanar,
                                                      const ExactKernel::Vector_3& n) {
  std::vector<tritri::Segment> segs;
  if (x.size() == 2) segs.push_back({0, 1});
  if (!coplanar || x.size() < 3) return segs;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = i + 1; j < x.size(); ++j) {
      const OPoint above = x[i] + n;  // with x[i], x[j]: a plane through line ij, across ours
      CGAL::Orientation first = CGAL::COPLANAR;
      bool edge = true;
      for (std::size_t k = 0; k < x.size() && edge; ++k) {
        if (k == i || k == j) continue;
        const auto s = CGAL::orientation(x[i], x[j], above, x[k]);
        if (s == CGAL::COPLANAR || (first != CGAL::COPLANAR && s != first)) edge = false;
        first = s;
      }
      if (edge) segs.push_back({static_cast<std::int8_t>(i), static_cast<std::int8_t>(j)});
    }
  return segs;
}

// "" if r is the correct classification of pair p, else the first violation found.
inline std::string check_classification(const Pair& pair, const tritri::Result& r) {
  const std::string form = check_form(r);
  if (!form.empty()) return form;

  const ITriangle a = to_input(pair.a), b = to_input(pair.b);
  const bool deg_a = is_degenerate(a), deg_b = is_degenerate(b);
  if (deg_a || deg_b) {
    if (!r.points.empty() || !r.segments.empty()) return "degenerate input but points reported";
    if (r.coplanar) return "degenerate input but coplanar set";
    const bool must_flag =
        (deg_a && (deg_b || !strictly_one_side(a, b))) || (deg_b && (deg_a || !strictly_one_side(b, a)));
    if (must_flag && !r.degenerate)
      return "degenerate triangle not strictly on one side of the other's plane, but degenerate == false";
    return "";
  }
  if (r.degenerate) return "non-degenerate input but degenerate == true";

  const bool coplanar =
      side(a, b[0]) == CGAL::COPLANAR && side(a, b[1]) == CGAL::COPLANAR && side(a, b[2]) == CGAL::COPLANAR;
  if (r.coplanar != coplanar)
    return std::string("coplanar flag is ") + (r.coplanar ? "true" : "false") + ", exact coplanarity is " +
           (coplanar ? "true" : "false");

  for (const auto& p : r.points) {
    const std::string why = check_claim(p, a, b);
    if (!why.empty()) return point_name(p) + ": " + why;
  }

  const OTriangle ea = to_oracle(pair.a), eb = to_oracle(pair.b);
  std::vector<OPoint> x;
  for (const auto& p : r.points) {
    const OPoint loc = locate(p, ea, eb);
    if (std::find(x.begin(), x.end(), loc) != x.end())
      return point_name(p) + " at " + point_string(loc) + " duplicates another point";
    x.push_back(loc);
  }

  const std::vector<OPoint> expected = cgal_corners(ea, eb);
  bool same = expected.size() == x.size();
  for (const OPoint& p : x) same = same && std::find(expected.begin(), expected.end(), p) != expected.end();
  if (!same) return "points " + points_string(x) + " differ from CGAL's corners " + points_string(expected);

  if (!coplanar && x.size() > 2) return "more than two points for a non-coplanar pair";
  const auto segs = expected_segments(x, coplanar, CGAL::normal(ea[0], ea[1], ea[2]));
  bool same_segs = segs.size() == r.segments.size();
  for (std::size_t i = 0; same_segs && i < segs.size(); ++i) same_segs = segs[i] == r.segments[i];
  if (!same_segs) {
    std::string s = "segments differ; expected [";
    for (const auto& sg : segs) s += "(" + std::to_string(sg.p0) + "," + std::to_string(sg.p1) + ")";
    return s + "]";
  }
  return "";
}

}  // namespace tritri_test
