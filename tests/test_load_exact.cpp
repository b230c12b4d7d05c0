// Specification of load_mesh_files (arrangements/load_triangle_soup.h), the loader of exact
// rational coordinates:
// - an exact OBJ / OFF file (write_mesh with exact = true, or written by hand) comes back
//   as an ExactTriangleSoup holding every coordinate exactly; decimals keep their meaning
//   (the correctly rounded double), non-reduced fractions are their value;
// - files whose rationals are all doubles give the TriangleSoup, identical to what
//   load_triangle_soups gives for the same values written as decimals;
// - polygons with rational corners are triangulated on the exact coordinates;
// - several files, one of them exact: all exact, labels, source and polygon ids as for
//   load_triangle_soups;
// - zero denominators, malformed rationals and values beyond the double range
//   are refused with InputError naming the file and the line; load_triangle_soup refuses
//   exact files and names load_mesh_files.
// - read_exact_mesh, the same OBJ / OFF readers with every decimal taken exactly, agrees with
//   load_triangle_soup on real files: the same triangles, and each exact coordinate rounds
//   (tritri::to_double, independent of the loader's from_chars) to the loader's double.
// Expected values are CGAL::Gmpq rationals written by hand (or GMP powers of two).
#include <gtest/gtest.h>

#include <arrangements/load_triangle_soup.h>
#include <arrangements/read_exact_mesh.h>
#include <arrangements/write_mesh.h>
#include <tritri/implicit_point.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "support/shared_meshes.h"
#include "support/temp_dir.h"

namespace {

using arrangements::AnyTriangleSoup;
using arrangements::ExactTriangleSoup;
using arrangements::ExactVec3;
using arrangements::InputError;
using arrangements::InputErrorKind;
using arrangements::LabelSet;
using arrangements::load_mesh_files;
using arrangements::load_triangle_soup;
using arrangements::load_triangle_soups;
using arrangements::Tri;
using arrangements::TriangleSoup;
using arrangements::Vec3;
using CGAL::Gmpq;
using tritri::ImplicitPoint;
using tritri_test::TempDir;

Gmpq q(const char* text) { return Gmpq(std::string(text)); }  // "n/d", canonicalized by CGAL
ExactVec3 ev(const Gmpq& x, const Gmpq& y, const Gmpq& z) { return {x, y, z}; }

ExactTriangleSoup exact_of(const AnyTriangleSoup& any) {
  EXPECT_TRUE(std::holds_alternative<ExactTriangleSoup>(any)) << "expected exact coordinates";
  return std::holds_alternative<ExactTriangleSoup>(any) ? std::get<ExactTriangleSoup>(any) : ExactTriangleSoup{};
}
TriangleSoup double_of(const AnyTriangleSoup& any) {
  EXPECT_TRUE(std::holds_alternative<TriangleSoup>(any)) << "expected double coordinates";
  return std::holds_alternative<TriangleSoup>(any) ? std::get<TriangleSoup>(any) : TriangleSoup{};
}

// Field by field; coordinates bit for bit (so -0.0 differs from 0.0).
void expect_identical(const TriangleSoup& a, const TriangleSoup& b) {
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i)
    EXPECT_EQ(std::memcmp(a.vertices[i].data(), b.vertices[i].data(), sizeof(Vec3)), 0) << "vertex " << i;
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.label_set, b.label_set);
  EXPECT_EQ(a.label_sets, b.label_sets);
  EXPECT_EQ(a.source, b.source);
  EXPECT_EQ(a.polygon, b.polygon);
}

// 2^k as a decimal integer (GMP, independent of the loader).
std::string power_of_two(unsigned k) {
  mpz_t z;
  mpz_init(z);
  mpz_ui_pow_ui(z, 2, k);
  std::string s(mpz_sizeinbase(z, 10) + 2, '\0');
  mpz_get_str(s.data(), 10, z);
  mpz_clear(z);
  s.resize(std::strlen(s.c_str()));
  return s;
}

// The numerator of q in decimal (GMP).
std::string numerator_digits(const Gmpq& x) {
  std::string s(mpz_sizeinbase(mpq_numref(x.mpq()), 10) + 2, '\0');
  mpz_get_str(s.data(), 10, mpq_numref(x.mpq()));
  s.resize(std::strlen(s.c_str()));
  return s;
}
const std::string kMaxDigits = numerator_digits(Gmpq(std::numeric_limits<double>::max()));  // DBL_MAX, an integer

std::string obj_triangle(const std::string& a, const std::string& b, const std::string& c) {
  return "v " + a + "\nv " + b + "\nv " + c + "\nf 1 2 3\n";
}

// ---- exact files ----------------------------------------------------------------------

TEST(LoadMeshFiles, AnExactMeshWrittenByWriteMeshReadsBackExactly) {
  TempDir dir;
  using P = std::array<double, 3>;
  const P o{0, 0, 0}, ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
  arrangements::OutputMesh m;
  m.vertices = {ImplicitPoint::explicit_point(0.1, -2.5, 0), ImplicitPoint::explicit_point(1, 0, 0),
                // (0,0,0)-(1,1,1) meets x + y + z = 1 at (1/3, 1/3, 1/3)
                ImplicitPoint::lpi(o, P{1, 1, 1}, ex, ey, ez),
                // (0,0,0)-(1,2,3) meets x + y + z = 1 at (1/6, 1/3, 1/2)
                ImplicitPoint::lpi(o, P{1, 2, 3}, ex, ey, ez),
                // x + y + z = 1, x = y, z = 3x meet at (1/5, 1/5, 3/5)
                ImplicitPoint::tpi(ex, ey, ez, o, P{1, 1, 0}, ez, o, ey, P{1, 0, 3})};
  m.triangles = {{0, 1, 2}, {2, 3, 4}, {4, 1, 0}};
  m.source = {0, 1, 2};
  m.label_set = {0, 0, 0};
  m.label_sets = {{0}};
  const std::vector<ExactVec3> expected = {ev(Gmpq(0.1), q("-5/2"), 0), ev(1, 0, 0), ev(q("1/3"), q("1/3"), q("1/3")),
                                           ev(q("1/6"), q("1/3"), q("1/2")), ev(q("1/5"), q("1/5"), q("3/5"))};
  for (const char* name : {"m.obj", "m.off"}) {
    SCOPED_TRACE(name);
    arrangements::write_mesh(dir.path(name), m, arrangements::WriteOptions{.exact = true});
    const ExactTriangleSoup s = exact_of(load_mesh_files({dir.path(name)}));
    EXPECT_EQ(s.vertices, expected);
    EXPECT_EQ(s.triangles, m.triangles);
    EXPECT_EQ(s.label_set, (std::vector<int>{0, 0, 0}));
    EXPECT_EQ(s.label_sets, (std::vector<LabelSet>{{0}}));
    EXPECT_EQ(s.source, (std::vector<std::int64_t>{0, 1, 2}));
    EXPECT_TRUE(s.polygon.empty());
  }
}

TEST(LoadMeshFiles, DecimalsAndRationalsMixInOneFileAndFractionsNeedNotBeReduced) {
  TempDir dir;
  const std::string obj = dir.write("mix.obj",
                                    "# thirds and sevenths\nv 0.1 1/3 -2\nv 2/6 -4/14 +5/7\n"
                                    "v 1e-3 3/21 0.5\nf 1 2 3\n");
  const ExactTriangleSoup s = exact_of(load_mesh_files({obj}));
  // A decimal is its correctly rounded double (0.1 is not 1/10), a rational its value.
  EXPECT_NE(Gmpq(0.1), q("1/10"));
  EXPECT_EQ(s.vertices, (std::vector<ExactVec3>{ev(Gmpq(0.1), q("1/3"), -2), ev(q("1/3"), q("-2/7"), q("5/7")),
                                                ev(Gmpq(1e-3), q("1/7"), q("1/2"))}));
  const std::string off = dir.write("mix.off", "OFF\n3 1 0\n0.25 1/3 0 # comment\n\n1 -1/9 7/3\n0 1 2/3\n3 0 1 2\n");
  EXPECT_EQ(exact_of(load_mesh_files({off})).vertices,
            (std::vector<ExactVec3>{ev(q("1/4"), q("1/3"), 0), ev(1, q("-1/9"), q("7/3")), ev(0, 1, q("2/3"))}));
}

TEST(LoadMeshFiles, RationalsThatAreDoublesGiveTheDoubleSoupOfLoadTriangleSoups) {
  TempDir dir;
  // 0.1 as write_mesh writes it exactly; 3/4, 6/3 (not reduced), the smallest subnormal
  // 2^-1074 and the largest double written as an integer.
  const std::string& max = kMaxDigits;
  const std::string rational =
      dir.write("r.obj", "v 3602879701896397/36028797018963968 3/4 6/3\nv 1/" + power_of_two(1074) + " " + max +
                             "/1 -1\nv 0 1 0\nv 1 1 -0/5\nf 1 2 3 4\n");
  const std::string decimal = dir.write("d.obj",
                                        "v 0.1 0.75 2\nv 4.9406564584124654e-324 1.7976931348623157e308 -1\nv 0 1 0\n"
                                        "v 1 1 -0\nf 1 2 3 4\n");
  const TriangleSoup s = double_of(load_mesh_files({rational}));
  expect_identical(s, load_triangle_soups({rational}));
  expect_identical(s, load_triangle_soups({decimal}));
  EXPECT_EQ(s.vertices[0], (Vec3{0.1, 0.75, 2}));
  EXPECT_EQ(s.vertices[1][0], std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(s.vertices[1][1], std::numeric_limits<double>::max());
  // Negative zero: "-0/5" is -0.0, as the decimal "-0" is.
  EXPECT_TRUE(std::signbit(s.vertices[3][2]));
  EXPECT_EQ(s.triangles.size(), 2u);
}

TEST(LoadMeshFiles, DoubleFilesGiveExactlyWhatLoadTriangleSoupsGives) {
  TempDir dir;
  const std::string a = dir.write("a.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0.5 0.2 0\nv 0 1 0\nf 1 2 3 4 5\n");
  const std::string b = dir.write("b.off", "OFF\n4 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n4 0 1 2 3\n");
  const std::string c = dir.write("c.stl",
                                  "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 2\nvertex 1 0 2\n"
                                  "vertex 0 1 2\nendloop\nendfacet\nendsolid s\n");
  const std::vector<std::string> paths = {a, b, c, a};
  expect_identical(double_of(load_mesh_files(paths)), load_triangle_soups(paths));
  EXPECT_TRUE(double_of(load_mesh_files({})).vertices.empty());
}

TEST(LoadMeshFiles, NegativeZeroAndTheSmallestNonDoublesAreExact) {
  TempDir dir;
  // 2^-1075 is below the smallest subnormal; 2^53 + 1 needs 54 bits; 1/3 is not dyadic.
  const std::string path = dir.write(
      "z.obj", obj_triangle("-0/5 -0 1/" + power_of_two(1075), "9007199254740993/1 9007199254740992/1 0", "0 1/3 0"));
  const ExactTriangleSoup s = exact_of(load_mesh_files({path}));
  Gmpq tiny(1);
  tiny /= Gmpq(std::string(power_of_two(1075)));
  EXPECT_EQ(s.vertices, (std::vector<ExactVec3>{ev(0, 0, tiny),
                                                ev(Gmpq(std::string("9007199254740993")), Gmpq(9007199254740992.0), 0),
                                                ev(0, q("1/3"), 0)}));
}

// ---- polygons -------------------------------------------------------------------------

// Each triangle rotated to start at its smallest index (orientation kept), then sorted.
std::vector<Tri> canonical(std::vector<Tri> ts) {
  for (Tri& t : ts) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(ts.begin(), ts.end());
  return ts;
}

TEST(LoadMeshFiles, PolygonsWithRationalCornersAreTriangulatedExactly) {
  TempDir dir;
  // Plane z = 1/3. A convex pentagon: the fan. A quad A B C D with B = C / 3 exactly on AC
  // (A = 0, C = (1, 3/7)): no fan from A (A B C is degenerate), the fan from B. An arrow
  // (x7: A(0,0) B(2,0) C(2,2) D(1,1/3) E(0,2), reflex at D): its only triangulation
  // {A B D, B C D, A D E}. A bow tie: not simple, the fan and no polygon id.
  const std::string path = dir.write("p.obj",
                                     "v 0 0 1/3\nv 1/2 0 1/3\nv 2/3 1/2 1/3\nv 1/4 5/6 1/3\nv -1/5 1/3 1/3\n"
                                     "v 0 0 1/3\nv 1/3 1/7 1/3\nv 1 3/7 1/3\nv 0 1 1/3\n"
                                     "v 0 0 1/3\nv 2/7 0 1/3\nv 2/7 2/7 1/3\nv 1/7 1/21 1/3\nv 0 2/7 1/3\n"
                                     "v 0 0 1/3\nv 1/3 1/3 1/3\nv 1/3 0 1/3\nv 0 1/3 1/3\n"
                                     "f 1 2 3 4 5\nf 6 7 8 9\nf 10 11 12 13 14\nf 15 16 17 18\n");
  const ExactTriangleSoup s = exact_of(load_mesh_files({path}));
  ASSERT_EQ(s.triangles.size(), 3u + 2u + 3u + 2u);
  const std::vector<Tri> t(s.triangles.begin(), s.triangles.end());
  EXPECT_EQ(std::vector<Tri>(t.begin(), t.begin() + 3), (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
  EXPECT_EQ(std::vector<Tri>(t.begin() + 3, t.begin() + 5), (std::vector<Tri>{{6, 7, 8}, {6, 8, 5}}));
  EXPECT_EQ(canonical({t.begin() + 5, t.begin() + 8}), (std::vector<Tri>{{9, 10, 12}, {9, 12, 13}, {10, 11, 12}}));
  EXPECT_EQ(std::vector<Tri>(t.begin() + 8, t.end()), (std::vector<Tri>{{14, 15, 16}, {14, 16, 17}}));
  EXPECT_EQ(s.polygon, (std::vector<std::int64_t>{0, 0, 0, 3, 3, 5, 5, 5, -1, -1}));
  EXPECT_EQ(s.source, (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(s.vertices[6], ev(q("1/3"), q("1/7"), q("1/3")));
}

TEST(LoadMeshFiles, PolygonPredicatesUseTheRationalsNotTheirRoundedDoubles) {
  TempDir dir;
  // The quad (0,0) (1,0) (1,1) (1/3, 1/3 + 10^-40): its last corner is left of the
  // diagonal from (0,0) to (1,1), so the fan from corner 0 is valid. Rounded to doubles
  // both its coordinates are the same double: the corner is on the diagonal, and the
  // split is the fan from corner 1 instead.
  const std::string y = "1" + std::string(39, '0') + "3/3" + std::string(40, '0');
  const std::string exact = dir.write("thin.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n1/3 " + y + " 0\n4 0 1 2 3\n");
  const ExactTriangleSoup s = exact_of(load_mesh_files({exact}));
  EXPECT_EQ(s.vertices[3], ev(q("1/3"), Gmpq(y), 0));
  EXPECT_EQ(s.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(s.polygon, (std::vector<std::int64_t>{0, 0}));
  const std::string rounded =
      dir.write("rounded.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0.3333333333333333 0.3333333333333333 0\n4 0 1 2 3\n");
  EXPECT_EQ(load_triangle_soup(rounded).triangles, (std::vector<Tri>{{1, 2, 3}, {1, 3, 0}}));
}

// ---- several files --------------------------------------------------------------------

TEST(LoadMeshFiles, OneExactFileAmongDoubleFilesMakesAllExactWithLabelsAndSourceKept) {
  TempDir dir;
  const std::string a = dir.write("a.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  const std::string b = dir.write("b.off", "OFF\n3 1 0\n0 0 1/3\n1 0 1/3\n0 1 1/3\n3 0 1 2\n");
  const std::string c = dir.write("c.obj", "v 0.5 0 2\nv 1 0 2\nv 1 1 2\nv 0 1 2\nf 1 2 3 4\nf 1 2 3\n");
  const ExactTriangleSoup s = exact_of(load_mesh_files({a, b, c}));
  EXPECT_EQ(s.vertices, (std::vector<ExactVec3>{ev(0, 0, 0), ev(1, 0, 0), ev(1, 1, 0), ev(0, 1, 0), ev(0, 0, q("1/3")),
                                                ev(1, 0, q("1/3")), ev(0, 1, q("1/3")), ev(q("1/2"), 0, 2), ev(1, 0, 2),
                                                ev(1, 1, 2), ev(0, 1, 2)}));
  // Convex quads: the fan from their first corner.
  EXPECT_EQ(s.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {7, 8, 9}, {7, 9, 10}, {7, 8, 9}}));
  EXPECT_EQ(s.label_set, (std::vector<int>{0, 0, 1, 2, 2, 2}));
  EXPECT_EQ(s.label_sets, (std::vector<LabelSet>{{0}, {1}, {2}}));
  EXPECT_EQ(s.source, (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(s.polygon, (std::vector<std::int64_t>{0, 0, -1, 3, 3, -1}));
  // The exact file first: the double files after it are converted too.
  const ExactTriangleSoup r = exact_of(load_mesh_files({b, a}));
  EXPECT_EQ(r.vertices.size(), 7u);
  EXPECT_EQ(r.vertices[3], ev(0, 0, 0));
  EXPECT_EQ(r.triangles, (std::vector<Tri>{{0, 1, 2}, {3, 4, 5}, {3, 5, 6}}));
  EXPECT_EQ(r.label_set, (std::vector<int>{0, 1, 1}));
  EXPECT_EQ(r.polygon, (std::vector<std::int64_t>{-1, 1, 1}));
}

// ---- refusals -------------------------------------------------------------------------

struct Refusal {
  std::string coordinate;  // the z coordinate of vertex 2 (line 2 of an OBJ, 4 of an OFF)
  InputErrorKind kind;
  std::string message;  // after "vertex 2: coordinate "
};

std::vector<Refusal> refusals() {
  const std::string digits(100001, '7');
  const std::string& max = kMaxDigits;
  return {
      {"1/0", InputErrorKind::malformed, "'1/0' has a zero denominator"},
      {"-0/000", InputErrorKind::malformed, "'-0/000' has a zero denominator"},
      {"1/", InputErrorKind::malformed, "'1/' is not a number"},
      {"/2", InputErrorKind::malformed, "'/2' is not a number"},
      {"1/2/3", InputErrorKind::malformed, "'1/2/3' is not a number"},
      {"1.5/2", InputErrorKind::malformed, "'1.5/2' is not a number"},
      {"0x1/3", InputErrorKind::malformed, "'0x1/3' is not a number"},
      {"1/-3", InputErrorKind::malformed, "'1/-3' is not a number"},
      {"+-1/3", InputErrorKind::malformed, "'+-1/3' is not a number"},
      {"1/2e3", InputErrorKind::malformed, "'1/2e3' is not a number"},
      // Any number of digits is read (test_hostile_input_limits): this one is judged by its value.
      {digits + "/3", InputErrorKind::non_finite_coordinate, "is beyond the largest finite double"},
      {max + "1/10", InputErrorKind::non_finite_coordinate, "is beyond the largest finite double"},
      {"-" + max + "1/1", InputErrorKind::non_finite_coordinate, "the pipeline needs finite bounding boxes"},
      {"inf", InputErrorKind::non_finite_coordinate, "'inf' is not a finite double"},
  };
}

// Refused alike by load_mesh_files and load_triangle_soup.
void expect_refused(const std::string& path, const std::string& place, const Refusal& r) {
  SCOPED_TRACE(path + " " + r.coordinate.substr(0, 60));
  const auto check = [&](auto&& load) {
    try {
      load();
      ADD_FAILURE() << "loaded, but must be refused";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.kind, r.kind) << what;
      EXPECT_EQ(what.rfind(path + ": " + place + ": vertex 2: coordinate ", 0), 0u) << what;
      EXPECT_NE(what.find(r.message), std::string::npos) << what;
    }
  };
  check([&] { load_mesh_files({path}); });
  check([&] { load_triangle_soup(path); });
}

TEST(LoadMeshFiles, RefusesBadRationalsNamingFileAndLine) {
  TempDir dir;
  for (const Refusal& r : refusals()) {
    const std::string obj = dir.write("bad.obj", "v 0 0 0\nv 1 0 " + r.coordinate + "\nv 0 1 0\nf 1 2 3\n");
    expect_refused(obj, "line 2", r);
    const std::string off = dir.write("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 " + r.coordinate + "\n0 1 0\n3 0 1 2\n");
    expect_refused(off, "line 4", r);
  }
  // The largest finite double itself is accepted, in either sign.
  const std::string& max = kMaxDigits;
  const std::string edge = dir.write("max.obj", obj_triangle("0 0 " + max + "/1", "-" + max + "0/10 0 0", "0 1 0"));
  EXPECT_EQ(double_of(load_mesh_files({edge})).vertices[1][0], -std::numeric_limits<double>::max());
  // 100000 digits are still accepted: 1 / 10^99999.
  const std::string many = dir.write("many.obj", obj_triangle("0 0 1/1" + std::string(99999, '0'), "1 0 0", "0 1 0"));
  Gmpq tiny(1);
  tiny /= Gmpq("1" + std::string(99999, '0'));
  EXPECT_EQ(exact_of(load_mesh_files({many})).vertices[0][2], tiny);
}

TEST(LoadMeshFiles, LoadTriangleSoupRefusesExactFilesAndNamesLoadMeshFiles) {
  TempDir dir;
  const Refusal r{"1/3", InputErrorKind::unsupported_variant,
                  "'1/3' is an exact rational that is not a double: the file has exact rational coordinates, "
                  "which load_mesh_files reads"};
  const std::string obj = dir.write("e.obj", "v 0 0 0\nv 1 0 1/3\nv 0 1 0\nf 1 2 3\n");
  const std::string off = dir.write("e.off", "OFF\n3 1 0\n0 0 0\n1 0 1/3\n0 1 0\n3 0 1 2\n");
  const std::string doubles = dir.write("d.obj", "v 0 0 0\nv 1 0 1/4\nv 0 1 0\nf 1 2 3\n");
  for (const auto& [path, place] : {std::pair{obj, std::string("line 2")}, std::pair{off, std::string("line 4")}}) {
    try {
      load_triangle_soups({doubles, path});
      ADD_FAILURE() << path << ": loaded, but must be refused";
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind, r.kind);
      EXPECT_EQ(std::string(e.what()).rfind(path + ": " + place + ": vertex 2: coordinate " + r.message, 0), 0u)
          << e.what();
    }
  }
}

TEST(LoadMeshFiles, StlPlyAndOffNormalsStayDecimalOnly) {
  TempDir dir;
  const std::string stl = dir.write("r.stl",
                                    "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 1/3\nvertex 1 0 0\n"
                                    "vertex 0 1 0\nendloop\nendfacet\nendsolid s\n");
  const std::string ply = dir.write("r.ply",
                                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
                                    "property double y\nproperty double z\nelement face 1\n"
                                    "property list uchar int vertex_indices\nend_header\n"
                                    "0 0 1/2\n1 0 0\n0 1 0\n3 0 1 2\n");
  const std::string noff = dir.write("r.off", "NOFF\n3 1 0\n0 0 0 0 0 1/2\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n");
  const std::pair<std::string, std::string> files[] = {
      {stl, "line 4: facet 1: coordinate '1/3' is not a number"},
      {ply, "line 10: vertex 1: property 'z' value '1/2' is not a valid double"},
      {noff, "line 3: vertex 1: normal coordinate '1/2' is not a number"}};
  for (const auto& [path, message] : files) {
    try {
      load_mesh_files({path});
      ADD_FAILURE() << path << ": loaded, but must be refused";
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind, InputErrorKind::malformed) << e.what();
      EXPECT_EQ(std::string(e.what()), path + ": " + message);
    }
  }
}

// ---- read_exact_mesh -------------------------------------------------------------------

TEST(ReadExactMesh, AgreesWithLoadTriangleSoupOnRealObjAndOffFiles) {
  const std::filesystem::path dir = tritri_test::shared_meshes_dir();
  TRITRI_REQUIRE_DATA(dir);
  // OBJ and OFF files whose decimals are mostly not doubles ("0.063974"), parsed both ways.
  const char* names[] = {"cgal_data/pig.off",         "cgal_data/mask_cone.off",        "cgal_data/couplingdown.off",
                         "cgal_data/knot1.off",       "common3d/teapot.obj",            "libigl_tutorial/truck.obj",
                         "cherchi_booleans/sphere1.obj", "manifold_tests/Offset1.obj"};
  std::vector<std::filesystem::path> files;
  for (const char* name : names) {
    TRITRI_REQUIRE_DATA(dir / name);
    files.push_back(dir / name);
  }
  std::size_t non_doubles = 0;
  for (const auto& f : files) {
    SCOPED_TRACE(f.string());
    const arrangements::ExactMesh exact = arrangements::read_exact_mesh(f.string());
    const TriangleSoup loaded = load_triangle_soup(f.string());
    ASSERT_EQ(exact.vertices.size(), loaded.vertices.size());
    EXPECT_EQ(exact.triangles, loaded.triangles);
    for (std::size_t v = 0; v < exact.vertices.size(); ++v) {
      EXPECT_EQ(tritri::to_double(exact.vertices[v]), loaded.vertices[v]) << "vertex " << v;
      for (int k = 0; k < 3; ++k) non_doubles += exact.vertices[v][k] != Gmpq(loaded.vertices[v][k]);
    }
  }
  EXPECT_GT(non_doubles, 0u) << "no decimal of these files was inexact: the test compares nothing exact";
}

}  // namespace
