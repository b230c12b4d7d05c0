// The exact path on rational input that no double soup can express (thirds, sevenths,
// 1/10^k), against an independent exact reference built here with CGAL::Epeck:
//   (a) every vertex of every pairwise intersection (CGAL::intersection of the two
//       Triangle_3: point, segment ends, triangle or polygon corners) is an output vertex;
//   (b) every output vertex is an input vertex, such a pairwise vertex, or the point where
//       the planes of three input triangles that contain it meet (a TPI, by
//       CGAL::intersection of the three Plane_3);
//   (c) check_arrangement(mesh).ok();
//   (d) every input triangle t (label t) is tiled by the output triangles whose label set
//       holds t: each lies in t's plane (CGAL::orientation) and their areas projected along
//       t's dominant axis (Gmpq) add up to t's; with no coplanar overlap in the scene, the
//       output triangles with source t add up to t's signed projected area (orientation kept);
//   (e) arranging the arrangement again finds no new point (no LPI, no TPI).
// Scenes: grids with steps 1/3, 2/7, 2/5 crossing; tilted planes through one rational point
// (four through it, three sharing a line); a triple point; stars of David and overlapping
// coplanar triangles with rational corners; a triangle 1/10^30 above or below another's
// plane; nearly parallel crossings (slopes 1/10^20, 1/10^25); slivers 1/10^20 thin; each
// also scaled by 10^20 and 10^-20. Then bad exact input (std::invalid_argument) and the
// `arrange` tool on exact files: refusals (exit 1, a message) and hand-derived counts.
#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "arrangements/arrange.h"
#include "arrangements/as_input.h"
#include "arrangements/check_arrangement.h"
#include "arrangements/load_triangle_soup.h"
#include "support/exact_soups.h"
#include "support/run_program.h"
#include "support/temp_dir.h"

namespace {

using namespace arrangements;
using CGAL::Gmpq;
using K = CGAL::Epeck;
using KP = K::Point_3;
using KT = K::Triangle_3;
using tritri_test::sorted_vertices;

// ---- rationals -----------------------------------------------------------------------

Gmpq q(long n, long d = 1) { return Gmpq(CGAL::Gmpz(n), CGAL::Gmpz(d)); }
Gmpq pow10(int k) {  // 10^k, k of any sign
  CGAL::Gmpz p(1);
  for (int i = 0; i < (k < 0 ? -k : k); ++i) p *= 10;
  return k < 0 ? Gmpq(CGAL::Gmpz(1), p) : Gmpq(p);
}
ExactVec3 add(const ExactVec3& a, const ExactVec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
ExactVec3 sub(const ExactVec3& a, const ExactVec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
ExactVec3 mul(const Gmpq& s, const ExactVec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
ExactVec3 cross(const ExactVec3& a, const ExactVec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
std::string str(const ExactVec3& v) {
  std::ostringstream o;
  o << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
  return o.str();
}

// ---- Epeck <-> Gmpq ------------------------------------------------------------------

// CGAL's exact type is GMP's mpq_class or CGAL::Gmpq, as CGAL was configured.
using ET = std::decay_t<decltype(std::declval<const K::FT&>().exact())>;
template <class To, class From>
To convert(const From& x) {
  if constexpr (std::is_same_v<To, From>) {
    return x;
  } else if constexpr (std::is_same_v<To, Gmpq>) {
    return Gmpq(x.get_mpq_t());
  } else {
    To e;
    mpq_set(e.get_mpq_t(), x.mpq());
    return e;
  }
}
ET et_of(const Gmpq& x) { return convert<ET>(x); }
Gmpq gmpq_of(const ET& e) { return convert<Gmpq>(e); }
KP kp(const ExactVec3& v) { return KP(K::FT(et_of(v[0])), K::FT(et_of(v[1])), K::FT(et_of(v[2]))); }
ExactVec3 ev(const KP& p) {
  const auto& e = p.exact();
  return {gmpq_of(e.x()), gmpq_of(e.y()), gmpq_of(e.z())};
}

// ---- scenes --------------------------------------------------------------------------

// A soup built triangle by triangle: triangle i has label i (label set {i}) and source i.
struct Scene {
  std::string name;
  ExactTriangleSoup soup;
  void tri(const ExactVec3& a, const ExactVec3& b, const ExactVec3& c) {
    const int base = static_cast<int>(soup.vertices.size()), t = static_cast<int>(soup.triangles.size());
    soup.vertices.insert(soup.vertices.end(), {a, b, c});
    soup.triangles.push_back({base, base + 1, base + 2});
    soup.label_set.push_back(t);
    soup.label_sets.push_back({static_cast<std::uint32_t>(t)});
    soup.source.push_back(t);
  }
  // n x n cells o + i u + j w, two triangles each.
  void grid(const ExactVec3& o, const ExactVec3& u, const ExactVec3& w, int n) {
    auto at = [&](int i, int j) { return add(o, add(mul(q(i), u), mul(q(j), w))); };
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        tri(at(i, j), at(i + 1, j), at(i + 1, j + 1));
        tri(at(i, j), at(i + 1, j + 1), at(i, j + 1));
      }
  }
  // A triangle in the plane through p with normal n, with centroid p (p in its interior).
  void around(const ExactVec3& p, const ExactVec3& n) {
    const ExactVec3 e = (n[1] == 0 && n[2] == 0) ? ExactVec3{q(0), q(1), q(0)} : ExactVec3{q(1), q(0), q(0)};
    const ExactVec3 u = cross(n, e), w = cross(n, u);
    tri(sub(p, add(u, w)), add(p, sub(mul(q(2), u), w)), add(p, sub(mul(q(2), w), u)));
  }
};

// A point (x, y) lifted onto the plane z = 1/3 + x/7 - y/5.
ExactVec3 lift(const Gmpq& x, const Gmpq& y) { return {x, y, q(1, 3) + x / 7 - y / 5}; }

std::vector<Scene> rational_scenes() {
  std::vector<Scene> out;
  {  // steps 1/3 (z = 1/5), 2/7 (vertical plane y = x/2 + 1/7), 2/5 (z = (x - y)/3 + 1/10)
    Scene s{"grids k/3, k/7, k/5", {}};
    s.grid({q(0), q(0), q(1, 5)}, {q(1, 3), q(0), q(0)}, {q(0), q(1, 3), q(0)}, 6);
    s.grid({q(0), q(1, 7), q(-1)}, {q(2, 7), q(1, 7), q(0)}, {q(0), q(0), q(2, 7)}, 7);
    s.grid({q(0), q(0), q(1, 10)}, {q(2, 5), q(0), q(2, 15)}, {q(0), q(2, 5), q(-2, 15)}, 5);
    out.push_back(s);
  }
  {  // four planes through P; the fifth's normal is the sum of the first two: a common line
    Scene s{"tilted planes through (1/3, 1/7, 1/11)", {}};
    const ExactVec3 p{q(1, 3), q(1, 7), q(1, 11)};
    for (const ExactVec3& n : {ExactVec3{q(1), q(2), q(3)}, ExactVec3{q(3), q(-1), q(2)}, ExactVec3{q(-2), q(1), q(5)},
                               ExactVec3{q(1), q(1), q(-1)}, ExactVec3{q(4), q(1), q(5)}})
      s.around(p, n);
    s.around({q(1, 2), q(-1, 3), q(2, 9)}, {q(1, 5), q(2, 3), q(-1, 7)});  // not through P
    out.push_back(s);
  }
  {
    Scene s{"three triangles, triple point (2/3, -1/7, 5/11)", {}};
    const ExactVec3 p{q(2, 3), q(-1, 7), q(5, 11)};
    for (const ExactVec3& n : {ExactVec3{q(7), q(1), q(2)}, ExactVec3{q(1), q(5), q(-1)}, ExactVec3{q(2), q(-1), q(9)}})
      s.around(p, n);
    out.push_back(s);
  }
  {  // coplanar: edges cross in six rational points; a seventh triangle crosses both
    Scene s{"star of David, rational corners, crossed", {}};
    s.tri(lift(q(0), q(0)), lift(q(3), q(0)), lift(q(3, 2), q(8, 3)));
    s.tri(lift(q(0), q(5, 3)), lift(q(3, 2), q(-1)), lift(q(3), q(5, 3)));
    s.tri({q(1) - q(2, 11), q(-2), q(-2)}, {q(1) + q(4, 11), q(4), q(-2)}, {q(1) + q(1, 11), q(1), q(3)});
    out.push_back(s);
  }
  {  // coplanar: overlapping, a collinear part of an edge from outside, one nested inside
    Scene s{"coplanar overlapping rational triangles", {}};
    auto flat = [](const Gmpq& x, const Gmpq& y) { return ExactVec3{x, y, q(1, 7) - x - y / 3}; };
    s.tri(flat(q(0), q(0)), flat(q(4, 3), q(0)), flat(q(0), q(4, 3)));
    s.tri(flat(q(1, 3), q(1, 7)), flat(q(5, 3), q(1, 7)), flat(q(1, 3), q(11, 7)));
    s.tri(flat(q(2, 3), q(0)), flat(q(2, 3), q(-1)), flat(q(2), q(0)));
    s.tri(flat(q(1, 7), q(1, 7)), flat(q(1, 3), q(1, 7)), flat(q(1, 7), q(2, 7)));
    out.push_back(s);
  }
  const ExactVec3 a{q(-1, 3), q(-1, 3), q(0)}, b{q(5, 3), q(-1, 3), q(0)}, c{q(-1, 3), q(5, 3), q(0)};
  // z = 0; one apex 1/10^30 above (no contact; in y = 1/7), one 1/10^30 below (a tiny cut;
  // y >= 1/5), one on it (x <= 1/7, y >= 2/3): the three upper triangles are disjoint.
  {
    Scene s{"apexes 1/10^30 from a plane", {}};
    s.tri(a, b, c);
    s.tri({q(1, 3), q(1, 7), pow10(-30)}, {q(-1, 6), q(1, 7), q(1)}, {q(5, 6), q(1, 7), q(1)});
    s.tri({q(2, 3), q(1, 5), -pow10(-30)}, {q(1, 6), q(1, 5), q(1)}, {q(1), q(7, 10), q(1)});
    s.tri({q(1, 7), q(2, 3), q(0)}, {q(1, 7), q(1), q(1)}, {q(-1, 7), q(2, 3), q(1)});
    out.push_back(s);
  }
  {  // z = 0, z = (x - 1/3)/10^20, z = (y - 1/5)/10^25: all three meet at (1/3, 1/5, 0)
    Scene s{"nearly parallel crossings", {}};
    s.tri(a, b, c);
    auto on1 = [](const Gmpq& x, const Gmpq& y) { return ExactVec3{x, y, (x - q(1, 3)) * pow10(-20)}; };
    auto on2 = [](const Gmpq& x, const Gmpq& y) { return ExactVec3{x, y, (y - q(1, 5)) * pow10(-25)}; };
    s.tri(on1(q(-1, 7), q(-1, 5)), on1(q(9, 7), q(-1, 5)), on1(q(-1, 7), q(6, 5)));
    s.tri(on2(q(-1, 5), q(-1, 7)), on2(q(6, 5), q(-1, 7)), on2(q(-1, 5), q(9, 7)));
    out.push_back(s);
  }
  {  // two slivers 1/10^20 thin, both through (1/3, 1/3, 0), crossing z = 0 and each other
    Scene s{"rational slivers", {}};
    s.tri(a, b, c);
    s.tri({q(0), q(1, 3), q(-1, 2)}, {q(2, 3), q(1, 3), q(1, 2)}, {q(1, 3), q(1, 3) + pow10(-20), pow10(-20)});
    s.tri({q(1, 3), q(0), q(-1, 2)}, {q(1, 3), q(2, 3), q(1, 2)}, {q(1, 3) + pow10(-20), q(1, 3), pow10(-21)});
    out.push_back(s);
  }
  return out;
}

Scene scaled(Scene s, int k) {
  const Gmpq f = pow10(k);
  for (ExactVec3& v : s.soup.vertices) v = mul(f, v);
  s.name += " x 10^" + std::to_string(k);
  return s;
}

// ---- the reference -------------------------------------------------------------------

struct Reference {
  std::vector<ExactVec3> pair_vertices;  // sorted, unique
  bool coplanar_overlap = false;         // some pair meets in a triangle or polygon
};

Reference reference(const std::vector<KT>& tris) {
  Reference r;
  for (std::size_t i = 0; i < tris.size(); ++i)
    for (std::size_t j = i + 1; j < tris.size(); ++j) {
      if (!CGAL::do_overlap(tris[i].bbox(), tris[j].bbox())) continue;
      const auto x = CGAL::intersection(tris[i], tris[j]);
      if (!x) continue;
      if (const KP* p = boost::get<KP>(&*x)) {
        r.pair_vertices.push_back(ev(*p));
      } else if (const K::Segment_3* s = boost::get<K::Segment_3>(&*x)) {
        r.pair_vertices.push_back(ev(s->source()));
        r.pair_vertices.push_back(ev(s->target()));
      } else if (const KT* t = boost::get<KT>(&*x)) {
        r.coplanar_overlap = true;
        for (int k = 0; k < 3; ++k) r.pair_vertices.push_back(ev(t->vertex(k)));
      } else if (const auto* poly = boost::get<std::vector<KP>>(&*x)) {
        r.coplanar_overlap = true;
        for (const KP& p : *poly) r.pair_vertices.push_back(ev(p));
      }
    }
  std::sort(r.pair_vertices.begin(), r.pair_vertices.end());
  r.pair_vertices.erase(std::unique(r.pair_vertices.begin(), r.pair_vertices.end()), r.pair_vertices.end());
  return r;
}

// v is where the planes of three input triangles that contain v meet.
bool is_triple_point(const ExactVec3& v, const std::vector<KT>& tris) {
  const KP p = kp(v);
  std::vector<K::Plane_3> on;
  for (const KT& t : tris)
    if (t.has_on(p)) on.push_back(t.supporting_plane());
  for (std::size_t i = 0; i < on.size(); ++i)
    for (std::size_t j = i + 1; j < on.size(); ++j)
      for (std::size_t k = j + 1; k < on.size(); ++k) {
        const auto x = CGAL::intersection(on[i], on[j], on[k]);
        if (!x) continue;
        if (const KP* t = boost::get<KP>(&*x)) {
          if (*t == p) return true;
        }
      }
  return false;
}

int dominant_axis(const ExactVec3& a, const ExactVec3& b, const ExactVec3& c) {
  const ExactVec3 n = cross(sub(b, a), sub(c, a));
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (CGAL::abs(n[i]) > CGAL::abs(n[k])) k = i;
  return k;
}
// Twice the signed area of abc projected along axis k.
Gmpq area2(const ExactVec3& a, const ExactVec3& b, const ExactVec3& c, int k) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  return (b[i] - a[i]) * (c[j] - a[j]) - (b[j] - a[j]) * (c[i] - a[i]);
}

void check_against_reference(const Scene& scene) {
  SCOPED_TRACE(scene.name);
  const ExactTriangleSoup& in = scene.soup;
  const ExactArrangeResult r = arrange(in, ArrangeOptions{});
  const ExactOutputMesh& m = r.mesh;
  std::vector<KT> tris;
  for (const Tri& t : in.triangles)
    tris.emplace_back(kp(in.vertices[t[0]]), kp(in.vertices[t[1]]), kp(in.vertices[t[2]]));
  const Reference ref = reference(tris);
  const std::vector<ExactVec3> out = sorted_vertices(m);
  auto is_output = [&](const ExactVec3& v) { return std::binary_search(out.begin(), out.end(), v); };

  // (a)
  for (const ExactVec3& v : ref.pair_vertices)
    EXPECT_TRUE(is_output(v)) << "pairwise intersection vertex missing: " << str(v);
  for (const ExactVec3& v : in.vertices) EXPECT_TRUE(is_output(v)) << "input vertex missing: " << str(v);
  // (b)
  std::vector<ExactVec3> known = in.vertices;
  known.insert(known.end(), ref.pair_vertices.begin(), ref.pair_vertices.end());
  std::sort(known.begin(), known.end());
  std::size_t triple_points = 0;
  for (const ExactVec3& v : out) {
    if (std::binary_search(known.begin(), known.end(), v)) continue;
    ++triple_points;
    EXPECT_TRUE(is_triple_point(v, tris)) << "output vertex " << str(v) << " is not an input vertex, a vertex of a "
                                          << "pairwise intersection or a triple point of three input triangles";
  }
  EXPECT_TRUE(std::adjacent_find(out.begin(), out.end()) == out.end()) << "two output vertices at one position";
  // (c)
  const ArrangementCheck check = check_arrangement(m);
  EXPECT_TRUE(check.ok()) << check.violations << " violations, " << check.degenerate_triangles << " degenerate"
                          << (check.examples.empty() ? "" : ": " + check.examples.front());
  // (d)
  for (std::size_t t = 0; t < in.triangles.size(); ++t) {
    const ExactVec3 &a = in.vertices[in.triangles[t][0]], &b = in.vertices[in.triangles[t][1]],
                    &c = in.vertices[in.triangles[t][2]];
    const int k = dominant_axis(a, b, c);
    const Gmpq whole = area2(a, b, c, k);
    Gmpq by_source = 0, by_label = 0;
    for (std::size_t f = 0; f < m.triangles.size(); ++f) {
      const ExactVec3 &fa = m.vertices[m.triangles[f][0]], &fb = m.vertices[m.triangles[f][1]],
                      &fc = m.vertices[m.triangles[f][2]];
      const LabelSet& labels = m.label_sets[m.label_set[f]];
      const bool covers = std::binary_search(labels.begin(), labels.end(), static_cast<std::uint32_t>(t));
      if (m.source[f] == static_cast<std::int64_t>(t)) by_source += area2(fa, fb, fc, k);
      if (!covers) continue;
      by_label += CGAL::abs(area2(fa, fb, fc, k));
      for (const ExactVec3* v : {&fa, &fb, &fc})
        EXPECT_EQ(CGAL::orientation(tris[t][0], tris[t][1], tris[t][2], kp(*v)), CGAL::COPLANAR)
            << "output triangle " << f << " labelled " << t << " leaves its plane at " << str(*v);
    }
    EXPECT_EQ(by_label, CGAL::abs(whole)) << "triangle " << t << " is not tiled by the triangles labelled with it";
    if (!ref.coplanar_overlap) {
      EXPECT_EQ(by_source, whole) << "triangle " << t << ": its pieces' signed areas";
    }
  }
  // (e)
  const ExactArrangeResult again = arrange(arrangements::as_input(m), ArrangeOptions{});
  EXPECT_EQ(again.stats.intersection_points, 0u);
  EXPECT_EQ(again.stats.tpi, 0u);
  EXPECT_EQ(again.stats.out_triangles, r.stats.out_triangles);
  EXPECT_EQ(sorted_vertices(again.mesh), out);
  // The scene's own facts: it has new points and their count is the pipeline's.
  EXPECT_EQ(r.stats.tpi, triple_points) << "output vertices that are triple points only";
}

TEST(ExactRational, ScenesMatchTheEpeckReference) {
  for (const Scene& s : rational_scenes()) check_against_reference(s);
}

TEST(ExactRational, ScaledScenesMatchTheEpeckReference) {
  for (const Scene& s : rational_scenes())
    for (int k : {20, -20}) check_against_reference(scaled(s, k));
}

// Facts of the scenes derived by hand, so that the reference is seen to find them.
TEST(ExactRational, ReferenceFindsTheHandDerivedPoints) {
  const std::vector<Scene> scenes = rational_scenes();
  auto find = [&](const std::string& prefix) {
    for (const Scene& s : scenes)
      if (s.name.starts_with(prefix)) return arrange(s.soup, ArrangeOptions{});
    ADD_FAILURE() << "no scene " << prefix;
    return ExactArrangeResult{};
  };
  auto has = [](const ExactArrangeResult& r, const ExactVec3& v) {
    const auto out = sorted_vertices(r.mesh);
    return std::binary_search(out.begin(), out.end(), v);
  };
  // z = 1/5, y = x/2 + 1/7, z = (x - y)/3 + 1/10 meet at x = 31/35, y = 41/70.
  EXPECT_TRUE(has(find("grids"), {q(31, 35), q(41, 70), q(1, 5)}));
  EXPECT_TRUE(has(find("tilted"), {q(1, 3), q(1, 7), q(1, 11)}));
  EXPECT_TRUE(has(find("three triangles"), {q(2, 3), q(-1, 7), q(5, 11)}));
  EXPECT_TRUE(has(find("nearly parallel"), {q(1, 3), q(1, 5), q(0)}));
  // The apex 1/10^30 below z = 0 cuts a triangle of z = 0 whose corners are on its edges.
  const ExactArrangeResult apex = find("apexes");
  EXPECT_TRUE(has(apex, {q(1, 7), q(2, 3), q(0)}));   // the apex on the plane
  EXPECT_FALSE(has(apex, {q(1, 3), q(1, 7), q(0)}));  // the one above: no contact
  EXPECT_EQ(apex.stats.intersection_points, 2u);  // the cut below: its two edges from the apex
  EXPECT_EQ(apex.stats.intersecting_pairs, 2u);   // below, and the apex on the plane
}

// Exact input must lie in the double range (arrange.h, validate_soup: the box search bounds
// every point by doubles), as the file loader, Eigen and Python require. Three cells of
// z = 1/5 (6 triangles) and two of the vertical plane y = x/2 + 1/7 (4 triangles) crossing
// them: arranged right at scale 1 and 10^300, refused at 10^309 (past DBL_MAX ~ 1.8 10^308,
// where double boxes would be infinite and pairs would be missed).
TEST(ExactRational, CoordinatesBeyondTheDoubleRangeAreRefusedOrArranged) {
  Scene s{"beyond DBL_MAX", {}};
  for (int j = 1; j <= 3; ++j) {
    const ExactVec3 a{q(4, 3), q(j, 3), q(1, 5)}, b{q(5, 3), q(j, 3), q(1, 5)}, c{q(5, 3), q(j + 1, 3), q(1, 5)},
        d{q(4, 3), q(j + 1, 3), q(1, 5)};
    s.tri(a, b, c);
    s.tri(a, c, d);
  }
  for (int j = -1; j <= 1; j += 2) {
    const ExactVec3 a{q(8, 7), q(5, 7), q(j, 7)}, b{q(10, 7), q(6, 7), q(j, 7)}, c{q(10, 7), q(6, 7), q(j + 2, 7)},
        d{q(8, 7), q(5, 7), q(j + 2, 7)};
    s.tri(a, b, c);
    s.tri(a, c, d);
  }
  for (int k : {0, 300, 309}) {
    const Scene t = scaled(s, k);
    try {
      (void)arrange(t.soup, ArrangeOptions{});
    } catch (const std::invalid_argument&) {
      EXPECT_GE(k, 309) << "refused, yet within the double range";
      continue;
    }
    check_against_reference(t);
  }
}

// ---- bad input -----------------------------------------------------------------------

TEST(ExactRational, BadIndicesAndLabelSetsAreRefused) {
  Scene s{"one triangle", {}};
  s.tri({q(1, 3), q(0), q(0)}, {q(0), q(1, 7), q(0)}, {q(0), q(0), q(1, 11)});
  EXPECT_NO_THROW(arrange(s.soup, ArrangeOptions{}));
  auto refused = [](ExactTriangleSoup soup, const char* what) {
    EXPECT_THROW(arrange(soup, ArrangeOptions{}), std::invalid_argument) << what;
  };
  ExactTriangleSoup bad = s.soup;
  bad.triangles[0][2] = 3;
  refused(bad, "vertex index == #V");
  bad = s.soup;
  bad.triangles[0][1] = -1;
  refused(bad, "negative vertex index");
  bad = s.soup;
  bad.label_set[0] = 1;
  refused(bad, "label set index == #label_sets");
  bad = s.soup;
  bad.label_set[0] = -1;
  refused(bad, "negative label set index");
  bad = s.soup;
  bad.label_set.clear();
  refused(bad, "no label set per triangle");
  bad = s.soup;
  bad.source.push_back(1);
  refused(bad, "two sources for one triangle");
}

// ---- the arrange tool on exact files -------------------------------------------------

// Two triangles: A = (0,0,0), (4/3,0,0), (0,4/3,0) in z = 0; B = (1/3,1/3,-1/3), (1,1/3,-1/3),
// (1/3,1/3,1/3) in y = 1/3. B's edges from (1/3,1/3,-1/3) and (1,1/3,-1/3) to its top cross
// z = 0 at p = (1/3,1/3,0) and q = (2/3,1/3,0), inside A (x + y < 4/3): two LPIs, no TPI.
// A with the segment pq inside: 5 vertices, 5 triangles, 9 edges; B cut by pq into the
// triangle (top, p, q) and a quadrilateral: 3 triangles, 7 edges; pq shared:
// V = 6 + 2, E = 9 + 7 - 1 = 15, F = 8, Euler 1.
const char* kThirds =
    "v 0 0 0\nv 4/3 0 0\nv 0 4/3 0\nv 1/3 1/3 -1/3\nv 1 1/3 -1/3\nv 1/3 1/3 1/3\nf 1 2 3\nf 4 5 6\n";

long long stat(const std::string& json, const std::string& key) {
  const std::string k = "\"" + key + "\": ";
  const std::size_t at = json.find(k);
  if (at == std::string::npos) {
    ADD_FAILURE() << "no key " << key << " in " << json;
    return -1;
  }
  return std::stoll(json.substr(at + k.size()));
}

TEST(ExactRationalCli, ArrangesAFileWithThirds) {
  tritri_test::TempDir dir;
  const std::string in = dir.write("thirds.obj", kThirds), out = dir.path("out.obj");
  const tritri_test::Exit e =
      tritri_test::spawn(ARRANGE_BIN, {in, "--stats", "--check", "-o", out, "--exact"}, dir.path());
  ASSERT_TRUE(e.exited);
  ASSERT_EQ(e.code, 0) << e.err;
  for (const auto& [key, value] : std::vector<std::pair<std::string, long long>>{{"in_triangles", 2},
                                                                                {"intersecting_pairs", 1},
                                                                                {"intersection_points", 2},
                                                                                {"tpi", 0},
                                                                                {"coplanar_pairs", 0},
                                                                                {"out_vertices", 8},
                                                                                {"out_edges", 15},
                                                                                {"out_triangles", 8},
                                                                                {"euler", 1}})
    EXPECT_EQ(stat(e.out, key), value) << key << " in " << e.out;
  // The written arrangement, read back exactly: the six corners and p, q.
  const AnyTriangleSoup back = load_mesh_files({out});
  ASSERT_TRUE(std::holds_alternative<ExactTriangleSoup>(back));
  std::vector<ExactVec3> v = std::get<ExactTriangleSoup>(back).vertices;
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  std::vector<ExactVec3> expected{{q(0), q(0), q(0)},         {q(4, 3), q(0), q(0)},        {q(0), q(4, 3), q(0)},
                                  {q(1, 3), q(1, 3), q(-1, 3)}, {q(1), q(1, 3), q(-1, 3)}, {q(1, 3), q(1, 3), q(1, 3)},
                                  {q(1, 3), q(1, 3), q(0)},     {q(2, 3), q(1, 3), q(0)}};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(v, expected);
}

TEST(ExactRationalCli, RefusesBadRationalsWithExitOne) {
  tritri_test::TempDir dir;
  const std::string tail = "v 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const std::string huge(100001, '7');
  const std::vector<std::pair<std::string, std::string>> cases{
      {"v 1/0 0 0\n", "has a zero denominator"},
      {"v 1/3/5 0 0\n", "is not a number"},
      {"v 0 x/3 0\n", "is not a number"},
      {"v 0 0 " + huge + "/3\n", "is beyond the largest finite double"},  // read whole, judged by its value
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string name = "bad" + std::to_string(i) + ".obj";
    const std::string path = dir.write(name, cases[i].first + tail);
    const tritri_test::Exit e = tritri_test::spawn(ARRANGE_BIN, {path, "--stats"}, dir.path());
    ASSERT_TRUE(e.exited) << name;
    EXPECT_EQ(e.code, 1) << name;
    EXPECT_NE(e.err.find(cases[i].second), std::string::npos) << name << ": " << e.err;
    EXPECT_NE(e.err.find(name), std::string::npos) << "the message names the file: " << e.err;
    EXPECT_EQ(e.out, "") << name;
  }
}

}  // namespace
