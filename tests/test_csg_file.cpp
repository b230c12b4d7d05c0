// Specification of load_csg_file (arrangements/load_csg.h), the OpenSCAD CSG reader:
// - the trees of the QuickCSG scenes in ../shared/meshes (operands in file order, the ops
//   as written), and their soups, which are what load_mesh_files loads for the same files;
// - the grammar: an implicit top-level union, group, empty blocks, a child without braces,
//   named and positional arguments, ignored extra arguments, comments, optional ';';
// - paths relative to the .csg file's folder (absolute paths kept);
// - multmatrix exactly: decimal entries as exact rationals, nested matrices composed (the
//   outer applied last), the soup kept in doubles when every mapped coordinate is one and
//   exact otherwise, corners reversed by a mirror, exact operand files;
// - every refusal with its kind, the .csg file and the line.
// Expected coordinates are rationals computed by hand from the matrices.
#include <gtest/gtest.h>

#include <arrangements/load_csg.h>
#include <arrangements/load_triangle_soup.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "support/shared_meshes.h"
#include "support/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using arrangements::BooleanOp;
using arrangements::CsgNode;
using arrangements::CsgScene;
using arrangements::ExactTriangleSoup;
using arrangements::ExactVec3;
using arrangements::InputError;
using arrangements::InputErrorKind;
using arrangements::LabelSet;
using arrangements::load_csg_file;
using arrangements::Tri;
using arrangements::TriangleSoup;
using arrangements::Vec3;
using CGAL::Gmpq;
using tritri_test::TempDir;

// The tree in one line: a leaf is its label, an operation U, I, D or X of its children.
std::string shape(const CsgNode& node) {
  if (node.operand >= 0) return std::to_string(node.operand);
  const char* op = node.op == BooleanOp::Union          ? "U"
                   : node.op == BooleanOp::Intersection ? "I"
                   : node.op == BooleanOp::Difference   ? "D"
                                                        : "X";
  std::string s = std::string(op) + "(";
  for (std::size_t i = 0; i < node.children.size(); ++i) s += (i ? "," : "") + shape(node.children[i]);
  return s + ")";
}

// op over the labels first .. last - 1, as shape() writes it.
std::string over(const char* op, int first, int last) {
  std::string s = std::string(op) + "(";
  for (int i = first; i < last; ++i) s += (i > first ? "," : "") + std::to_string(i);
  return s + ")";
}

// A tetrahedron with a corner at (1, 2, 3), as an OFF file.
const char* kTetra = "OFF\n4 4 0\n1 2 3\n2 2 3\n1 3 3\n1 2 4\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
const std::vector<Vec3> kTetraVertices = {{1, 2, 3}, {2, 2, 3}, {1, 3, 3}, {1, 2, 4}};
const std::vector<Tri> kTetraTriangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

// A folder with a.off and b.off (the tetrahedron) and the scene.csg `text`.
struct Scene {
  TempDir dir;
  std::string csg;
  explicit Scene(const std::string& text) {
    dir.write("a.off", kTetra);
    dir.write("b.off", kTetra);
    csg = dir.write("scene.csg", text);
  }
};

const TriangleSoup& doubles(const CsgScene& s) {
  EXPECT_TRUE(std::holds_alternative<TriangleSoup>(s.soup)) << "expected the double soup";
  return std::get<TriangleSoup>(s.soup);
}
const ExactTriangleSoup& exact(const CsgScene& s) {
  EXPECT_TRUE(std::holds_alternative<ExactTriangleSoup>(s.soup)) << "expected the exact soup";
  return std::get<ExactTriangleSoup>(s.soup);
}

// The InputError of loading path (fails the test if it loads).
InputError refusal(const std::string& path) {
  try {
    load_csg_file(path);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << path << ": loaded, but must be refused";
  return InputError(InputErrorKind::malformed, "");
}

// Refusing `text` as scene.csg: the kind, and a message that names the file and line and
// contains `phrase`.
void expect_refused(const std::string& text, InputErrorKind kind, int line, const std::string& phrase) {
  Scene s(text);
  const InputError e = refusal(s.csg);
  EXPECT_EQ(e.kind, kind) << e.what();
  const std::string where = "scene.csg: line " + std::to_string(line) + ": ";
  EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << e.what() << "\nwanted: " << where;
  EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what() << "\nwanted: " << phrase;
}

// ---- the QuickCSG scenes -----------------------------------------------------------------

fs::path quickcsg(const char* name) { return tritri_test::shared_meshes_dir() / "thingicsg" / "QuickCSG" / name; }

TEST(CsgFile, OrganicIsAUnionOfThreeDifferencesOverSixOperandsInFileOrder) {
  const fs::path csg = quickcsg("Organic/organic.csg");
  TRITRI_REQUIRE_DATA(csg);
  const CsgScene s = load_csg_file(csg.string());
  EXPECT_EQ(shape(s.tree), "U(D(0,1),D(2,3),D(4,5))");
  const std::vector<std::string> names = {"bunny_remap.off", "ears_box.off", "0.off",
                                          "dragon_box.off",  "1.off",        "head_box.off"};
  ASSERT_EQ(s.operand_files.size(), names.size());
  for (std::size_t i = 0; i < names.size(); ++i)
    EXPECT_EQ(s.operand_files[i], (csg.parent_path() / names[i]).string());
  // No transform: exactly what load_mesh_files loads for the same files, labels 0..5.
  const TriangleSoup& soup = doubles(s);
  const TriangleSoup files = std::get<TriangleSoup>(arrangements::load_mesh_files(s.operand_files));
  EXPECT_EQ(soup.vertices, files.vertices);
  EXPECT_EQ(soup.triangles, files.triangles);
  EXPECT_EQ(soup.label_set, files.label_set);
  EXPECT_EQ(soup.source, files.source);
  EXPECT_EQ(soup.label_sets, (std::vector<LabelSet>{{0}, {1}, {2}, {3}, {4}, {5}}));
}

TEST(CsgFile, T1IsTheDifferenceOfTwoUnionsOf25Operands) {
  const fs::path csg = quickcsg("T1/T1.csg");
  TRITRI_REQUIRE_DATA(csg);
  const CsgScene s = load_csg_file(csg.string());
  EXPECT_EQ(shape(s.tree), "D(" + over("U", 0, 25) + "," + over("U", 25, 50) + ")");
  ASSERT_EQ(s.operand_files.size(), 50u);
  for (int i = 0; i < 50; ++i)
    EXPECT_EQ(s.operand_files[i], (csg.parent_path() / ("t1_" + std::to_string(i) + ".off")).string());
  EXPECT_EQ(doubles(s).label_sets.size(), 50u);
}

TEST(CsgFile, KnotsAreIntersectionsOf42And31Cones) {
  for (const auto& [name, n] : {std::pair{"knots42/H.csg", 42}, std::pair{"knots42/H0.csg", 31}}) {
    const fs::path csg = quickcsg(name);
    TRITRI_REQUIRE_DATA(csg);
    const CsgScene s = load_csg_file(csg.string());
    EXPECT_EQ(shape(s.tree), over("I", 0, n)) << name;
    ASSERT_EQ(s.operand_files.size(), static_cast<std::size_t>(n)) << name;
    EXPECT_EQ(s.operand_files.back(), (csg.parent_path() / ("cones" + std::to_string(n - 1) + ".off")).string());
    EXPECT_EQ(doubles(s).label_sets.size(), static_cast<std::size_t>(n));
  }
}

// ---- grammar -------------------------------------------------------------------------------

TEST(CsgFile, SeveralTopLevelStatementsAreTheirUnionAndOneIsItself) {
  Scene two("import(\"a.off\");\nimport(file = \"b.off\");\n");
  const CsgScene s = load_csg_file(two.csg);
  EXPECT_EQ(shape(s.tree), "U(0,1)");
  const TriangleSoup& soup = doubles(s);
  ASSERT_EQ(soup.triangles.size(), 8u);
  EXPECT_EQ(soup.label_set, (std::vector<int>{0, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(soup.source, (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(soup.triangles[4], (Tri{4, 6, 5}));  // operand 1's vertices follow operand 0's
  Scene one("difference() { import(\"a.off\"); import(\"b.off\"); }");
  EXPECT_EQ(shape(load_csg_file(one.csg).tree), "D(0,1)");
}

TEST(CsgFile, CommentsExtraArgumentsGroupsAndOptionalSemicolonsAreAccepted) {
  Scene s(
      "// OpenSCAD export\n"
      "group() {\n"
      "  /* a comment\n     over lines */ union(convexity = 2) {\n"
      "    import(file = \"a.off\", layer = \"\", origin = [0, 0], scale = 1, convexity = 3, $fn = 0,\n"
      "           $fa = 12, $fs = 2, timestamp = 12345, center = false, id = undef);\n"
      "    import(\"b.off\", 10);  // positional: the file, then an ignored argument\n"
      "  };\n"
      "  ;\n"
      "}; // trailing\n");
  EXPECT_EQ(shape(load_csg_file(s.csg).tree), "U(U(0,1))");
}

TEST(CsgFile, AStatementTakesOneChildWithoutBraces) {
  Scene s("difference() import(\"a.off\");\nunion() multmatrix(m = [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]])\n"
          "  intersection() { import(\"b.off\"); import(\"a.off\"); }\n");
  EXPECT_EQ(shape(load_csg_file(s.csg).tree), "U(D(0),U(I(1,2)))");
}

TEST(CsgFile, EmptyBlocksAreUnionsOfNothing) {
  Scene s("union() {}\ngroup();\ndifference() {}\nmultmatrix(m = [[2,0,0,0],[0,2,0,0],[0,0,2,0],[0,0,0,1]]) {}\n"
          "multmatrix([[2,0,0,0],[0,2,0,0],[0,0,2,0],[0,0,0,1]]) { import(\"a.off\"); import(\"b.off\"); }\n"
          "intersection() { union() {} import(\"a.off\"); }\n");
  EXPECT_EQ(shape(load_csg_file(s.csg).tree), "U(U(),U(),U(),U(),U(0,1),I(U(),2))");
}

TEST(CsgFile, RelativePathsAreResolvedAgainstTheCsgFolderAndAbsoluteOnesKept) {
  TempDir dir;
  fs::create_directories(dir.path() / "scenes" / "sub");
  fs::create_directories(dir.path() / "meshes");
  const std::string a = dir.write("meshes/a.off", kTetra);
  dir.write("scenes/sub/b.off", kTetra);
  const std::string csg =
      dir.write("scenes/s.csg", "union() { import(\"../meshes/a.off\"); import(\"sub/b.off\"); import(\"" + a + "\"); }");
  const CsgScene s = load_csg_file(csg);
  const fs::path folder = dir.path() / "scenes";
  EXPECT_EQ(s.operand_files,
            (std::vector<std::string>{(folder / "../meshes/a.off").string(), (folder / "sub/b.off").string(), a}));
  EXPECT_EQ(doubles(s).triangles.size(), 12u);
}

TEST(CsgFile, LinesAreCountedForEveryKindOfLineEnd) {
  for (const std::string eol : {"\n", "\r\n", "\r"})
    expect_refused("union() {" + eol + "import(\"a.off\");" + eol + eol + "cube(1);" + eol + "}",
                   InputErrorKind::malformed, 4, "unknown statement 'cube'");
}

// ---- multmatrix ------------------------------------------------------------------------------

const char* kMatrixRows = "[[1.0, 0, 0.0, -0], [0, 1e0, 0, 0], [0, 0, 10e-1, 0], [0, 0, 0, 1]]";

TEST(CsgFile, AnIdentityMatrixKeepsTheDoubleSoupUnchanged) {
  Scene s(std::string("multmatrix(m = ") + kMatrixRows + ") import(\"a.off\");");
  const CsgScene scene = load_csg_file(s.csg);
  const TriangleSoup& soup = doubles(scene);
  EXPECT_EQ(soup.vertices, kTetraVertices);
  EXPECT_EQ(soup.triangles, kTetraTriangles);
}

TEST(CsgFile, MappedCoordinatesThatAreDoublesKeepTheDoubleSoup) {
  // x -> 2 x + 0.5, y -> -y + 4, z -> z / 4 - 3: exact in doubles for the tetrahedron.
  Scene s("multmatrix(m = [[2, 0, 0, 0.5], [0, -1, 0, 4], [0, 0, 0.25, -3], [0, 0, 0, 1]]) import(\"a.off\");");
  const CsgScene scene = load_csg_file(s.csg);
  const TriangleSoup& soup = doubles(scene);
  EXPECT_EQ(soup.vertices, (std::vector<Vec3>{{2.5, 2, -2.25}, {4.5, 2, -2.25}, {2.5, 1, -2.25}, {2.5, 2, -2}}));
}

TEST(CsgFile, ATenthMakesTheWholeSoupExact) {
  // Operand 0 unchanged, operand 1 scaled by 0.1 = 1/10 exactly (not the double 0.1).
  Scene s("import(\"a.off\");\nmultmatrix(m = [[0.1, 0, 0, 0], [0, 0.1, 0, 0], [0, 0, 0.1, 0], [0, 0, 0, 1]])\n"
          "  import(\"b.off\");\n");
  const CsgScene scene = load_csg_file(s.csg);
  const ExactTriangleSoup& soup = exact(scene);
  ASSERT_EQ(soup.vertices.size(), 8u);
  EXPECT_EQ(soup.vertices[0], (ExactVec3{Gmpq(1), Gmpq(2), Gmpq(3)}));
  EXPECT_EQ(soup.vertices[4], (ExactVec3{Gmpq(1, 10), Gmpq(1, 5), Gmpq(3, 10)}));
  EXPECT_EQ(soup.vertices[7], (ExactVec3{Gmpq(1, 10), Gmpq(1, 5), Gmpq(2, 5)}));
  EXPECT_EQ(soup.label_set, (std::vector<int>{0, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(soup.triangles[7], (Tri{5, 6, 7}));
  EXPECT_EQ(soup.label_sets, (std::vector<LabelSet>{{0}, {1}}));
}

TEST(CsgFile, NestedMatricesComposeExactlyWithTheOuterAppliedLast) {
  // Outer: the rotation about z with cosine 0.6 and sine 0.8; inner: x + 1/2.
  // (1, 2, 3) -> (3/2, 2, 3) -> (0.6 * 3/2 - 0.8 * 2, 0.8 * 3/2 + 0.6 * 2, 3) = (-7/10, 12/5, 3).
  const std::string rotation = "[[0.6, -0.8, 0, 0], [0.8, 0.6, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]";
  const std::string shift = "[[1, 0, 0, 0.5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]";
  for (const std::string& text :
       {"multmatrix(m = " + rotation + ") {\n  multmatrix(m = " + shift + ") { import(\"a.off\"); }\n}\n",
        "multmatrix(" + rotation + ") multmatrix(" + shift + ") import(\"a.off\");"}) {
    Scene s(text + "import(\"b.off\");");
    const CsgScene scene = load_csg_file(s.csg);
    const ExactTriangleSoup& soup = exact(scene);
    ASSERT_EQ(soup.vertices.size(), 8u);
    EXPECT_EQ(soup.vertices[0], (ExactVec3{Gmpq(-7, 10), Gmpq(12, 5), Gmpq(3)})) << text;
    // (2, 2, 3) -> (5/2, 2, 3) -> (3/2 - 8/5, 2 + 6/5, 3) = (-1/10, 16/5, 3)
    EXPECT_EQ(soup.vertices[1], (ExactVec3{Gmpq(-1, 10), Gmpq(16, 5), Gmpq(3)})) << text;
    EXPECT_EQ(soup.vertices[4], (ExactVec3{Gmpq(1), Gmpq(2), Gmpq(3)})) << "the sibling outside is not moved";
    EXPECT_EQ(soup.triangles[0], (Tri{0, 2, 1})) << "a rotation keeps the orientation";
    EXPECT_EQ(shape(scene.tree), "U(0,1)");
  }
}

TEST(CsgFile, AMatrixAppliesToAllItsChildren) {
  Scene s("multmatrix(m = [[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
          "  import(\"a.off\");\n  union() { import(\"b.off\"); }\n}\nimport(\"a.off\");\n");
  const CsgScene scene = load_csg_file(s.csg);
  EXPECT_EQ(shape(scene.tree), "U(U(0,U(1)),2)");
  const TriangleSoup& soup = doubles(scene);
  ASSERT_EQ(soup.vertices.size(), 12u);
  EXPECT_EQ(soup.vertices[0], (Vec3{11, 2, 3}));
  EXPECT_EQ(soup.vertices[4], (Vec3{11, 2, 3}));
  EXPECT_EQ(soup.vertices[8], (Vec3{1, 2, 3}));
}

TEST(CsgFile, ANegativeDeterminantReversesEveryTriangle) {
  Scene s("multmatrix(m = [[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) import(\"a.off\");\n"
          "multmatrix(m = [[-1, 0, 0, 0], [0, -1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) import(\"b.off\");\n"
          "multmatrix(m = [[0, 0.5, 0, 0], [0.5, 0, 0, 0], [0, 0, 0.1, 0], [0, 0, 0, 1]]) import(\"a.off\");\n");
  const CsgScene scene = load_csg_file(s.csg);
  const ExactTriangleSoup& soup = exact(scene);  // the third operand's z / 10
  ASSERT_EQ(soup.triangles.size(), 12u);
  EXPECT_EQ(soup.vertices[0], (ExactVec3{Gmpq(-1), Gmpq(2), Gmpq(3)}));
  EXPECT_EQ(soup.vertices[8], (ExactVec3{Gmpq(1), Gmpq(1, 2), Gmpq(3, 10)}));
  for (int t = 0; t < 4; ++t) {
    const Tri& tri = kTetraTriangles[t];
    EXPECT_EQ(soup.triangles[t], (Tri{tri[2], tri[1], tri[0]})) << "a mirror (det -1)";
    EXPECT_EQ(soup.triangles[4 + t], (Tri{tri[0] + 4, tri[1] + 4, tri[2] + 4})) << "a half turn (det 1)";
    EXPECT_EQ(soup.triangles[8 + t], (Tri{tri[2] + 8, tri[1] + 8, tri[0] + 8})) << "a swap of x and y (det -1/40)";
  }
}

TEST(CsgFile, OperandFilesWithExactCoordinatesAreReadAndMappedExactly) {
  Scene s("multmatrix(m = [[3, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) import(\"r.off\");\n"
          "import(\"r.off\");\n");
  s.dir.write("r.off", "OFF\n3 1 0\n1/3 0 0\n0 2/7 0\n0 0 1\n3 0 1 2\n");
  const CsgScene scene = load_csg_file(s.csg);
  const ExactTriangleSoup& soup = exact(scene);
  ASSERT_EQ(soup.vertices.size(), 6u);
  EXPECT_EQ(soup.vertices[0], (ExactVec3{Gmpq(1), Gmpq(0), Gmpq(0)}));
  EXPECT_EQ(soup.vertices[1], (ExactVec3{Gmpq(0), Gmpq(2, 7), Gmpq(0)}));
  EXPECT_EQ(soup.vertices[3], (ExactVec3{Gmpq(1, 3), Gmpq(0), Gmpq(0)}));
}

// ---- refusals --------------------------------------------------------------------------------

TEST(CsgFile, UnknownStatementsAndSyntaxErrorsNameTheLine) {
  expect_refused("union() {\n  cube(size = 1);\n}\n", InputErrorKind::malformed, 2, "unknown statement 'cube'");
  expect_refused("union()\n  )\n", InputErrorKind::malformed, 2, "expected '{', ';' or a statement after union(...)");
  expect_refused("union {\n}\n", InputErrorKind::malformed, 1, "expected '(' after union");
  expect_refused("import(\"a.off\")\nimport(\"b.off\");\n", InputErrorKind::malformed, 2,
                 "expected ';' after import(...)");
  expect_refused("import(\"a.off\" \"b.off\");\n", InputErrorKind::malformed, 1,
                 "expected ',' or ')' in the arguments of import()");
  expect_refused("import(convexity = 1.2.3, \"a.off\");\n", InputErrorKind::malformed, 1, "'1.2.3' is not a number");
  expect_refused("\nimport(file = 1);\n", InputErrorKind::malformed, 2, "import() needs a file name");
  expect_refused("import(\"a.off\", file = \"b.off\");\n", InputErrorKind::malformed, 1, "file given twice");
  expect_refused("union() { import(\"a.off\"); } #\n", InputErrorKind::malformed, 1, "unexpected character '#'");
  expect_refused("import(\"a\\q.off\");\n", InputErrorKind::malformed, 1, "unknown escape '\\\\q'");
  expect_refused("multmatrix(m = [[1, 0, 0, 0], [0, 1, 0, 0]\n", InputErrorKind::malformed, 2,
                 "expected ',' or ']' in a vector");
}

TEST(CsgFile, UnbalancedBracesAreRefused) {
  expect_refused("union() {\n  difference() {\n    import(\"a.off\");\n  }\n", InputErrorKind::malformed, 5,
                 "the block of union() at line 1 is not closed");
  expect_refused("import(\"a.off\");\n}\n", InputErrorKind::malformed, 2, "'}' closes no block");
  expect_refused("union() {\n  multmatrix(m = [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]])\n}\n",
                 InputErrorKind::malformed, 3, "expected '{', ';' or a statement after multmatrix(...), found '}'");
  expect_refused("union() multmatrix(m = [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]])", InputErrorKind::malformed, 1,
                 "after multmatrix(...), found the end of the file");
}

TEST(CsgFile, UnterminatedCommentsAndStringsNameTheLineWhereTheyBegin) {
  expect_refused("import(\"a.off\");\n/* open\n\nimport(\"b.off\");\n", InputErrorKind::malformed, 2,
                 "unterminated comment");
  expect_refused("import(\"a.off\");\nimport(\"b.off);\n\n", InputErrorKind::malformed, 2, "unterminated string");
}

TEST(CsgFile, BadMatricesAreRefused) {
  const auto with = [](const std::string& m) { return "\nmultmatrix(m = " + m + ") import(\"a.off\");\n"; };
  expect_refused(with("[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]"), InputErrorKind::malformed, 2,
                 "m must be a 4 x 4 matrix");
  expect_refused(with("[[1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, 0]]"), InputErrorKind::malformed, 2,
                 "m must be a 4 x 4 matrix");
  expect_refused(with("[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, x], [0, 0, 0, 1]]"), InputErrorKind::malformed, 2,
                 "m must be a 4 x 4 matrix");
  expect_refused(with("[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0.5, 1]]"), InputErrorKind::malformed, 2,
                 "the last row must be [0, 0, 0, 1], found [0, 0, 0.5, 1]");
  expect_refused(with("[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.000001]]"), InputErrorKind::malformed,
                 2, "the last row must be");
  expect_refused(with("[[1, 2, 3, 0], [2, 4, 6, 0], [0, 0, 1, 0], [0, 0, 0, 1]]"), InputErrorKind::malformed, 2,
                 "singular multmatrix");
  expect_refused(with("[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1e5000, 0], [0, 0, 0, 1]]"), InputErrorKind::too_large, 2,
                 "'1e5000' has more than");
  expect_refused("\nmultmatrix() import(\"a.off\");\n", InputErrorKind::malformed, 2, "without its matrix m");
  // 1e300 * 1e300 is no longer a finite double: refused at the import's line.
  Scene big("import(\"a.off\");\nmultmatrix(m = [[1e300, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])\n"
            "  import(\"big.off\");\n");
  big.dir.write("big.off", "OFF\n3 1 0\n1e300 0 0\n0 1 0\n0 0 1\n3 0 1 2\n");
  const InputError e = refusal(big.csg);
  EXPECT_EQ(e.kind, InputErrorKind::non_finite_coordinate) << e.what();
  EXPECT_NE(std::string(e.what()).find("scene.csg: line 3: import: "), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("beyond the largest finite double"), std::string::npos) << e.what();
}

TEST(CsgFile, MissingAndUnreadableOperandsNameTheResolvedPathAndTheImport) {
  Scene s("import(\"a.off\");\n\nimport(\"sub/missing.off\");\n");
  InputError e = refusal(s.csg);
  EXPECT_EQ(e.kind, InputErrorKind::unreadable_file);
  const std::string missing = (s.dir.path() / "sub/missing.off").string();
  EXPECT_NE(std::string(e.what()).find("scene.csg: line 3: imported file '" + missing + "' does not exist"),
            std::string::npos)
      << e.what();
  expect_refused("import(\"a.off\");\nimport(\"a.txt\");\n", InputErrorKind::unreadable_file, 2, "a.txt' does not exist");
  Scene txt("import(\"a.off\");\nimport(\"a.txt\");\n");
  txt.dir.write("a.txt", "");
  e = refusal(txt.csg);
  EXPECT_EQ(e.kind, InputErrorKind::unknown_format) << e.what();
  EXPECT_NE(std::string(e.what()).find("line 2: imported file"), std::string::npos) << e.what();
  // An operand that its reader refuses: its message, after the import's place.
  Scene bad("union() {\n  import(\"a.off\");\n  import(\"bad.off\");\n}\n");
  bad.dir.write("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  e = refusal(bad.csg);
  EXPECT_EQ(e.kind, InputErrorKind::index_out_of_range) << e.what();
  EXPECT_NE(std::string(e.what()).find("scene.csg: line 3: import: " + (bad.dir.path() / "bad.off").string() + ": line 6"),
            std::string::npos)
      << e.what();
}

TEST(CsgFile, AFileWithoutOperandsIsRefused) {
  for (const std::string text : {"", "\n// only a comment\n", "union() {}\ngroup() { difference(); }\n"}) {
    Scene s(text);
    const InputError e = refusal(s.csg);
    EXPECT_EQ(e.kind, InputErrorKind::empty_mesh) << e.what();
    EXPECT_NE(std::string(e.what()).find("no operand"), std::string::npos) << e.what();
  }
  expect_refused("import(\"a.off\");\n\nintersection() { }\n", InputErrorKind::malformed, 3, "intersection() of nothing");
  TempDir dir;
  EXPECT_EQ(refusal(dir.path("none.csg")).kind, InputErrorKind::unreadable_file);
}

TEST(CsgFile, NestingIsBoundedAt10000Statements) {
  const auto nested = [](int depth) {
    std::string text;
    for (int i = 0; i < depth; ++i) text += "union() {\n";
    text += "import(\"a.off\");\n";
    for (int i = 0; i < depth; ++i) text += "}\n";
    return text;
  };
  Scene deep(nested(10000));
  const CsgScene s = load_csg_file(deep.csg);
  const CsgNode* node = &s.tree;
  int depth = 0;
  for (; node->operand < 0; ++depth) node = &node->children.at(0);
  EXPECT_EQ(depth, 10000);
  expect_refused(nested(10001), InputErrorKind::too_large, 10001, "nested more than 10000 deep");
}

}  // namespace
