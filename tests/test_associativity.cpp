// Arrangements that can be iterated (issue 14): arranging A and B, then the result with C,
// gives the arrangement of A, B and C at once, refined. For operands A, B, C (labels 0, 1,
// 2) the one-shot R = arrange(A u B u C) and, for both groupings, the iterated
//   (A u B) u C:  R1 = arrange(A u B) (the double path when A and B have double
//                 coordinates), R2 = arrange(exact(R1) u exact(C)) (the exact path; R1's
//                 label sets and sources carried, C labelled 2);
//   A u (B u C):  the same with R1 = arrange(B u C) and A added last.
// Checks: (i) R2 and R have the same Euler characteristic (the same union of triangles);
// (ii) every vertex of R is a vertex of R2 (exact rationals: R2 only adds points where C
// crosses R1's triangulation edges); (iii) check_arrangement(R2) is ok; (iv) R2 arranged again
// finds no new point (no LPI, no TPI).
// Operands:
//   - the 32 MCUT benchmark pairs (shared meshes, mcut/benchmarks/src-meshNNN.off as A,
//     cut-meshNNN.off as B; at most 124 triangles each), with C a sphere across both (double
//     coordinates: R on the double path) and with C = B rotated by a rational rotation
//     (cosines 3/5 and 5/13) and moved by extent/70, extent/110, extent/130 (not doubles: R on
//     the exact path);
//   - generated triples: three spheres, three rotated boxes, three rotated coplanar grids
//     (coplanar overlaps across the iterations), three grids sharing cells (duplicate
//     triangles), a grid through a sphere with a box through both, three triangles through one
//     triple point;
//   - sphere1.obj and sphere2.obj of cherchi_booleans (shared meshes, 2880 triangles each)
//     with C = sphere2 turned by the rational rotation.
//   - the EMBER pairs (ember-88566-58011, ember-1063852-72214, ember-79741-65004, built by
//     ../shared/tools/make_ember_pairs.py; 16K to 70K triangles), each pair file as A u B
//     and C a sphere across it: the grouping (A u B) u C only (the file holds both operands
//     together), checks (i), (ii) and (iv) (the exact check of a 20K-40K triangle exact
//     mesh takes minutes). Below test scale 1 (sanitizers) the smallest pair only.
#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include <tritri/implicit_point.h>

#include "arrangements/arrange.h"
#include "arrangements/as_input.h"
#include "arrangements/check_arrangement.h"
#include "arrangements/load_triangle_soup.h"
#include "support/arrangement_scenes.h"
#include "support/bounding_box.h"
#include "support/exact_soups.h"
#include "support/shared_meshes.h"
#include "support/temp_dir.h"
#include "support/test_scale.h"

namespace {

using namespace arrangements;
using CGAL::Gmpq;
using arrangements::as_input;
using tritri_test::sorted_vertices;

// An operand: every triangle labelled {label}, sources numbered from the operand's first
// triangle in A u B u C (so that the one-shot and iterated inputs name triangles alike).
struct Operand {
  ExactTriangleSoup soup;
  bool doubles = true;  // every coordinate is a double
};

Operand operand(ExactTriangleSoup s, bool doubles, std::uint32_t label, std::int64_t first_source) {
  s.label_sets = {{label}};
  s.label_set.assign(s.triangles.size(), 0);
  s.source.clear();
  for (std::size_t t = 0; t < s.triangles.size(); ++t) s.source.push_back(first_source + static_cast<std::int64_t>(t));
  s.polygon.clear();
  return {std::move(s), doubles};
}
Operand operand(const TriangleSoup& s, std::uint32_t label, std::int64_t first_source) {
  return operand(arrangements::to_exact(s), true, label, first_source);
}

// The parts in order, vertex indices shifted; each triangle keeps its label set and source.
ExactTriangleSoup join(const std::vector<const ExactTriangleSoup*>& parts) {
  ExactTriangleSoup out;
  for (const ExactTriangleSoup* p : parts) {
    const int base = static_cast<int>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), p->vertices.begin(), p->vertices.end());
    for (std::size_t t = 0; t < p->triangles.size(); ++t) {
      const Tri& f = p->triangles[t];
      out.triangles.push_back({base + f[0], base + f[1], base + f[2]});
      const LabelSet& labels = p->label_sets[p->label_set[t]];
      auto it = std::find(out.label_sets.begin(), out.label_sets.end(), labels);
      if (it == out.label_sets.end()) it = out.label_sets.insert(it, labels);
      out.label_set.push_back(static_cast<int>(it - out.label_sets.begin()));
      out.source.push_back(p->source[t]);
    }
  }
  return out;
}

TriangleSoup to_doubles(const ExactTriangleSoup& e) {  // exact: the coordinates are doubles
  return tritri_test::with_vertices<Vec3>(e, [](const ExactVec3& v) { return tritri::to_double(v); });
}

struct Arranged {
  ExactOutputMesh mesh;
  ArrangeStats stats;
};
Arranged arrange_any(const ExactTriangleSoup& s, bool doubles) {
  if (doubles) {
    const ArrangeResult r = arrange(to_doubles(s), ArrangeOptions{});
    return {tritri_test::exact_mesh(r.mesh), r.stats};
  }
  ExactArrangeResult r = arrange(s, ArrangeOptions{});
  return {std::move(r.mesh), r.stats};
}

std::vector<ExactVec3> unique_sorted_vertices(const ExactOutputMesh& m) {
  std::vector<ExactVec3> v = sorted_vertices(m);
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

void check_triple(const std::string& what, const Operand& a, const Operand& b, const Operand& c) {
  SCOPED_TRACE(what);
  const Arranged one = arrange_any(join({&a.soup, &b.soup, &c.soup}), a.doubles && b.doubles && c.doubles);
  const std::vector<ExactVec3> all = unique_sorted_vertices(one.mesh);
  ASSERT_EQ(all.size(), one.mesh.vertices.size()) << "two vertices of the one-shot arrangement at one position";
  struct Grouping {
    const char* name;
    const Operand *first, *second, *last;
  };
  for (const Grouping& g : {Grouping{"(A u B) u C", &a, &b, &c}, Grouping{"A u (B u C)", &b, &c, &a}}) {
    SCOPED_TRACE(g.name);
    const Arranged r1 = arrange_any(join({&g.first->soup, &g.second->soup}), g.first->doubles && g.second->doubles);
    const ExactTriangleSoup s1 = as_input(r1.mesh);
    const ExactArrangeResult r2 = arrange(join({&s1, &g.last->soup}), ArrangeOptions{});
    // (i)
    EXPECT_EQ(r2.stats.euler, one.stats.euler);
    // (ii)
    const std::vector<ExactVec3> refined = unique_sorted_vertices(r2.mesh);
    EXPECT_EQ(refined.size(), r2.mesh.vertices.size()) << "two vertices of R2 at one position";
    std::vector<ExactVec3> missing;
    std::set_difference(all.begin(), all.end(), refined.begin(), refined.end(), std::back_inserter(missing));
    EXPECT_TRUE(missing.empty()) << missing.size() << " of the one-shot arrangement's " << all.size()
                                 << " vertices are not vertices of the iterated one, e.g. (" << missing.front()[0]
                                 << ", " << missing.front()[1] << ", " << missing.front()[2] << ")";
    EXPECT_GE(r2.stats.out_vertices, one.stats.out_vertices);
    // (iii)
    const ArrangementCheck check = check_arrangement(r2.mesh);
    EXPECT_TRUE(check.ok()) << check.violations << " violations, " << check.degenerate_triangles << " degenerate"
                            << (check.examples.empty() ? "" : ": " + check.examples.front());
    // (iv)
    const ExactArrangeResult again = arrange(as_input(r2.mesh), ArrangeOptions{});
    EXPECT_EQ(again.stats.intersection_points, 0u);
    EXPECT_EQ(again.stats.tpi, 0u);
    EXPECT_EQ(again.stats.out_triangles, r2.stats.out_triangles);
  }
}

// (A u B) u C against A u B u C for an operand A u B given as one soup: checks (i), (ii)
// and (iv) of check_triple.
void check_pair_then_third(const std::string& what, const Operand& ab, const Operand& c) {
  SCOPED_TRACE(what);
  const Arranged one = arrange_any(join({&ab.soup, &c.soup}), ab.doubles && c.doubles);
  const std::vector<ExactVec3> all = unique_sorted_vertices(one.mesh);
  const Arranged r1 = arrange_any(ab.soup, ab.doubles);
  const ExactTriangleSoup s1 = as_input(r1.mesh);
  const ExactArrangeResult r2 = arrange(join({&s1, &c.soup}), ArrangeOptions{});
  EXPECT_EQ(r2.stats.euler, one.stats.euler);
  const std::vector<ExactVec3> refined = unique_sorted_vertices(r2.mesh);
  std::vector<ExactVec3> missing;
  std::set_difference(all.begin(), all.end(), refined.begin(), refined.end(), std::back_inserter(missing));
  EXPECT_TRUE(missing.empty()) << missing.size() << " of " << all.size() << " one-shot vertices missing";
  EXPECT_GT(r2.stats.intersection_points, 0u) << "C crosses nothing: the test tells nothing";
  const ExactArrangeResult again = arrange(as_input(r2.mesh), ArrangeOptions{});
  EXPECT_EQ(again.stats.intersection_points, 0u);
  EXPECT_EQ(again.stats.tpi, 0u);
  EXPECT_EQ(again.stats.out_triangles, r2.stats.out_triangles);
}

// ---- generated triples ---------------------------------------------------------------

// Triangles [first, first + count) of s, with the vertices they use.
TriangleSoup part_of(const TriangleSoup& s, std::size_t first, std::size_t count) {
  TriangleSoup p;
  std::vector<int> index(s.vertices.size(), -1);
  for (std::size_t t = first; t < first + count; ++t) {
    Tri f;
    for (int k = 0; k < 3; ++k) {
      int& i = index[s.triangles[t][k]];
      if (i < 0) {
        i = static_cast<int>(p.vertices.size());
        p.vertices.push_back(s.vertices[s.triangles[t][k]]);
      }
      f[k] = i;
    }
    p.triangles.push_back(f);
  }
  return p;
}

// The k copies of rotated_copies(s, 3), as three soups.
std::vector<TriangleSoup> three_rotated(const TriangleSoup& s) {
  const TriangleSoup all = rotated_copies(s, 3);
  std::vector<TriangleSoup> out;
  for (std::size_t i = 0; i < 3; ++i) out.push_back(part_of(all, i * s.triangles.size(), s.triangles.size()));
  return out;
}

void check_generated(const std::string& what, const TriangleSoup& a, const TriangleSoup& b, const TriangleSoup& c) {
  const auto na = static_cast<std::int64_t>(a.triangles.size()), nb = static_cast<std::int64_t>(b.triangles.size());
  check_triple(what, operand(a, 0, 0), operand(b, 1, na), operand(c, 2, na + nb));
}

TEST(Associativity, GeneratedTriples) {
  check_generated("three spheres", uv_sphere({0, 0, 0}, 1.0, 8, 12), uv_sphere({1, 0.05, 0.02}, 0.95, 7, 11),
                  uv_sphere({0.45, 0.85, -0.03}, 1.05, 9, 10));
  const auto boxes = three_rotated(box({0, 0, 0}, {2, 1, 1}));
  check_generated("three rotated boxes", boxes[0], boxes[1], boxes[2]);
  const auto grids = three_rotated(grid(4, 1.0, 0.0));
  check_generated("three rotated coplanar grids", grids[0], grids[1], grids[2]);
  check_generated("three grids sharing cells", grid(4, 1.0, 0.0), grid(4, 1.0, 0.0, 1.0, 0.0),
                  grid(4, 1.0, 0.0, 0.5, 0.25));
  check_generated("grid through sphere, box through both", grid(8, 0.25, 0.0, -1, -1),
                  uv_sphere({0, 0, 0}, 0.9, 8, 12), box({-0.5, -0.25, -1.2}, {0.25, 0.5, 0.3}));
  const TriangleSoup t = tritri_test::arrangement::three_triangles_triple_point();
  check_generated("three triangles, triple point", part_of(t, 0, 1), part_of(t, 1, 1), part_of(t, 2, 1));
}

// The rational operand (exact path) on generated meshes too: the third sphere moved by 1/3.
TEST(Associativity, GeneratedTripleWithARationalOperand) {
  const TriangleSoup a = uv_sphere({0, 0, 0}, 1.0, 8, 12), b = uv_sphere({1, 0.05, 0.02}, 0.95, 7, 11);
  ExactTriangleSoup c = arrangements::to_exact(uv_sphere({0.45, 0.85, -0.03}, 1.05, 9, 10));
  for (ExactVec3& v : c.vertices) v[0] += Gmpq(1, 3);
  const auto na = static_cast<std::int64_t>(a.triangles.size()), nb = static_cast<std::int64_t>(b.triangles.size());
  check_triple("three spheres, the third moved by 1/3", operand(a, 0, 0), operand(b, 1, na),
               operand(c, false, 2, na + nb));
}

// ---- MCUT pairs ----------------------------------------------------------------------

// The centre of the bounding box of the soups and its largest side.
struct Frame {
  Vec3 centre;
  double extent = 0;
};
Frame frame(const std::vector<const TriangleSoup*>& soups) {
  BoundingBox box;
  for (const TriangleSoup* s : soups)
    for (const Vec3& v : s->vertices) box.add(v);
  return Frame{box.centre(), box.extent()};
}

// s rotated about `centre` by Rx(5/13, 12/13) Rz(3/5, 4/5), then moved by (d/70, d/110, d/130).
ExactTriangleSoup rotated_rational(const TriangleSoup& s, const Vec3& centre, double d) {
  ExactTriangleSoup e = arrangements::to_exact(s);
  const ExactVec3 c{Gmpq(centre[0]), Gmpq(centre[1]), Gmpq(centre[2])};
  const Gmpq cz(3, 5), sz(4, 5), cx(5, 13), sx(12, 13), D(d);
  for (ExactVec3& v : e.vertices) {
    const Gmpq x = v[0] - c[0], y = v[1] - c[1], z = v[2] - c[2];
    const Gmpq x1 = cz * x - sz * y, y1 = sz * x + cz * y;
    const Gmpq y2 = cx * y1 - sx * z, z2 = sx * y1 + cx * z;
    v = {c[0] + x1 + D / 70, c[1] + y2 + D / 110, c[2] + z2 + D / 130};
  }
  return e;
}

TEST(Associativity, McutPairs) {
  const std::filesystem::path dir = tritri_test::shared_meshes_dir() / "mcut" / "benchmarks";
  TRITRI_REQUIRE_DATA(dir);
  std::vector<std::string> ids;
  for (const auto& f : std::filesystem::directory_iterator(dir)) {
    const std::string name = f.path().filename().string();
    if (name.starts_with("src-mesh") && std::filesystem::exists(dir / ("cut-mesh" + name.substr(8))))
      ids.push_back(name.substr(8, name.size() - 8 - 4));
  }
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(ids.size(), 32u) << "MCUT pairs in " << dir;
  for (const std::string& id : ids) {
    const TriangleSoup a = load_triangle_soup((dir / ("src-mesh" + id + ".off")).string());
    const TriangleSoup b = load_triangle_soup((dir / ("cut-mesh" + id + ".off")).string());
    const auto na = static_cast<std::int64_t>(a.triangles.size()), nb = static_cast<std::int64_t>(b.triangles.size());
    const Frame f = frame({&a, &b});
    const Operand A = operand(a, 0, 0), B = operand(b, 1, na);
    check_triple("MCUT " + id + " with a sphere across both", A, B,
                 operand(uv_sphere(f.centre, 0.35 * f.extent, 8, 12), 2, na + nb));
    check_triple("MCUT " + id + " with the cut mesh turned by a rational rotation", A, B,
                 operand(rotated_rational(b, f.centre, f.extent), false, 2, na + nb));
  }
}

// Two medium meshes: the boolean demo operands of cherchi_booleans (2880 triangles each),
// and the second turned by the rational rotation.
TEST(Associativity, SharedSpheres) {
  const std::filesystem::path dir = tritri_test::shared_meshes_dir() / "cherchi_booleans";
  TRITRI_REQUIRE_DATA(dir / "sphere1.obj");
  TRITRI_REQUIRE_DATA(dir / "sphere2.obj");
  const TriangleSoup a = load_triangle_soup((dir / "sphere1.obj").string());
  const TriangleSoup b = load_triangle_soup((dir / "sphere2.obj").string());
  const auto na = static_cast<std::int64_t>(a.triangles.size()), nb = static_cast<std::int64_t>(b.triangles.size());
  const Frame f = frame({&a, &b});
  check_triple("sphere1, sphere2, sphere2 turned", operand(a, 0, 0), operand(b, 1, na),
               operand(rotated_rational(b, f.centre, f.extent), false, 2, na + nb));
}

TEST(Associativity, EmberPairs) {
  const std::filesystem::path shared = tritri_test::shared_meshes_dir().parent_path();
  const std::filesystem::path script = shared / "tools" / "make_ember_pairs.py";
  TRITRI_REQUIRE_DATA(script);
  tritri_test::TempDir tmp;
  const std::string command = "python3 '" + script.string() + "' '" + tmp.path().string() + "' > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  std::vector<std::string> names{"ember-88566-58011", "ember-1063852-72214", "ember-79741-65004"};
  if (tritri_test::scaled_down()) names.resize(1);
  for (const std::string& name : names) {
    const TriangleSoup ab = load_triangle_soup((tmp.path() / (name + ".off")).string());
    const std::int64_t n = static_cast<std::int64_t>(ab.triangles.size());
    const Frame f = frame({&ab});
    check_pair_then_third(name + " with a sphere across it", operand(ab, 0, 0),
                          operand(uv_sphere(f.centre, 0.37 * f.extent, 24, 48), 1, n));
  }
}

}  // namespace
