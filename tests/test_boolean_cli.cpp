// `arrange --boolean` and `arrange --csg` (the Boolean through the command line): exact
// outputs read back with their volumes known by hand, a Boolean of exact Boolean outputs
// equal to the same tree done at once (iterable: the same exact volume and corners), 1 and 2 threads byte-identical, --round
// safe still closed and checked, an open operand named in the error (exit 1), usage
// errors (exit 2), a CSG file with a line number in its error.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "arrangements/csg.h"
#include "arrangements/load_triangle_soup.h"
#include "arrangements/read_exact_mesh.h"
#include "arrangements/write_mesh.h"
#include "support/boolean_checks.h"
#include "support/mesh_generators.h"
#include "support/run_program.h"
#include "support/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using namespace arrangements;
using tritri_test::Exit;
using tritri_test::spawn;
using tritri_test::volume;

std::string box_file(const fs::path& dir, const std::string& name, const Vec3& lo, const Vec3& hi) {
  const TriangleSoup b = box(lo, hi);
  OutputMesh m;
  for (const Vec3& p : b.vertices) m.vertices.push_back(tritri::ImplicitPoint::explicit_point(p));
  m.triangles = b.triangles;
  m.source = b.source;
  m.label_set.assign(b.triangles.size(), 0);
  m.label_sets = {{0}};
  const std::string path = (dir / name).string();
  write_mesh(path, m);
  return path;
}

Exit run(const std::vector<std::string>& args, const fs::path& dir) { return spawn(ARRANGE_BIN, args, dir); }

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(BooleanCli, VolumesByHandAndReadBack) {
  tritri_test::TempDir dir;
  const std::string a = box_file(dir.path(), "a.off", {0, 0, 0}, {2, 2, 2});
  const std::string b = box_file(dir.path(), "b.off", {1, 1, 1}, {3, 3, 3});
  const std::pair<const char*, int> expected[] = {{"union", 15}, {"intersection", 1}, {"difference", 7}, {"xor", 14}};
  for (const auto& [op, vol] : expected) {
    const std::string out = (dir.path() / (std::string(op) + ".obj")).string();
    const Exit e = run({a, b, "--boolean", op, "--exact", "-o", out, "--check"}, dir.path());
    ASSERT_EQ(e.code, 0) << e.err;
    const ExactMesh m = read_exact_mesh(out);
    EXPECT_EQ(volume(m), vol) << op;
    EXPECT_EQ(tritri_test::unbalanced_edges(m), 0u) << op;
  }
}

TEST(BooleanCli, BooleanOfExactOutputsEqualsOneTree) {
  tritri_test::TempDir dir;
  const std::string a = box_file(dir.path(), "a.off", {0, 0, 0}, {2, 2, 2});
  const std::string b = box_file(dir.path(), "b.off", {1, 1, 1}, {3, 3, 3});
  const std::string c = box_file(dir.path(), "c.off", {0.5, 0.25, 1.5}, {2.5, 2.75, 3.5});
  const std::string u = (dir.path() / "u.obj").string(), d = (dir.path() / "d.obj").string();
  ASSERT_EQ(run({a, b, "--boolean", "union", "--exact", "-o", u}, dir.path()).code, 0);
  const Exit e = run({u, c, "--boolean", "difference", "--exact", "-o", d}, dir.path());
  ASSERT_EQ(e.code, 0) << e.err;
  std::ofstream(dir.path() / "tree.csg") << "difference() {\n  union() { import(file=\"a.off\"); "
                                            "import(file=\"b.off\"); }\n  import(file=\"c.off\");\n}\n";
  const std::string t = (dir.path() / "t.obj").string();
  const Exit f = run({"--csg", (dir.path() / "tree.csg").string(), "--exact", "-o", t}, dir.path());
  ASSERT_EQ(f.code, 0) << f.err;
  const ExactMesh two_steps = read_exact_mesh(d), at_once = read_exact_mesh(t);
  EXPECT_EQ(volume(two_steps), volume(at_once));
  EXPECT_GT(volume(at_once), 0);
  // the same solid: the same corners (each output also has vertices inside flat parts,
  // where the other operands' cuts ended, which differ between the two ways)
  EXPECT_EQ(tritri_test::solid_corners(two_steps), tritri_test::solid_corners(at_once));
  EXPECT_GE(tritri_test::solid_corners(at_once).size(), 8u);
}

TEST(BooleanCli, ThreadsIdenticalAndRoundSafeChecked) {
  tritri_test::TempDir dir;
  const TriangleSoup s = uv_sphere({0, 0, 0}, 1, 10, 14);
  const TriangleSoup t = turned(s, {0, 0, 0}, {0, 0.6, 0.8}, 0.4, {0.5, 0.1, 0});
  OutputMesh m;
  for (const TriangleSoup* x : {&s, &t}) {
    m = OutputMesh{};
    for (const Vec3& p : x->vertices) m.vertices.push_back(tritri::ImplicitPoint::explicit_point(p));
    m.triangles = x->triangles;
    m.source = x->source;
    m.label_set.assign(x->triangles.size(), 0);
    m.label_sets = {{0}};
    write_mesh((dir.path() / (x == &s ? "s.obj" : "t.obj")).string(), m);
  }
  const std::string in_s = (dir.path() / "s.obj").string(), in_t = (dir.path() / "t.obj").string();
  const std::string one = (dir.path() / "one.obj").string(), two = (dir.path() / "two.obj").string();
  ASSERT_EQ(run({in_s, in_t, "--boolean", "union", "--threads", "1", "-o", one}, dir.path()).code, 0);
  ASSERT_EQ(run({in_s, in_t, "--boolean", "union", "--threads", "2", "-o", two}, dir.path()).code, 0);
  EXPECT_EQ(slurp(one), slurp(two));
  const std::string safe = (dir.path() / "safe.obj").string();
  const Exit e = run({in_s, in_t, "--boolean", "intersection", "--round", "safe", "--check", "-o", safe}, dir.path());
  ASSERT_EQ(e.code, 0) << e.err;
  const TriangleSoup rounded = load_triangle_soup(safe);
  EXPECT_EQ(tritri_test::unbalanced_edges(rounded), 0u);
  EXPECT_GT(volume(rounded), 0);
}

TEST(BooleanCli, OpenOperandNamedAndUsageErrors) {
  tritri_test::TempDir dir;
  const std::string a = box_file(dir.path(), "a.off", {0, 0, 0}, {2, 2, 2});
  const fs::path open = dir.path() / "open.off";
  std::ofstream(open) << "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n";
  const Exit e = run({a, open.string(), "--boolean", "union"}, dir.path());
  EXPECT_EQ(e.code, 1);
  EXPECT_NE(e.err.find("open.off: operand 1 is not closed"), std::string::npos) << e.err;
  EXPECT_EQ(run({a, a, "--boolean", "unite"}, dir.path()).code, 2);
  EXPECT_EQ(run({a, "--csg", "x.csg"}, dir.path()).code, 2);
  EXPECT_EQ(run({"--csg", "x.csg", "--boolean", "union"}, dir.path()).code, 2);
  std::ofstream(dir.path() / "bad.csg") << "union() {\n  import(file=\"a.off\");\n  cube(1);\n}\n";
  const Exit f = run({"--csg", (dir.path() / "bad.csg").string()}, dir.path());
  EXPECT_EQ(f.code, 1);
  EXPECT_NE(f.err.find("line 3"), std::string::npos) << f.err;
}

// The C++ entry csg(): a scaled (exact) and a plain tree, volumes by hand.
TEST(BooleanCli, CsgFunction) {
  tritri_test::TempDir dir;
  box_file(dir.path(), "a.off", {0, 0, 0}, {2, 2, 2});
  box_file(dir.path(), "b.off", {1, 1, 1}, {3, 3, 3});
  std::ofstream(dir.path() / "plain.csg") << "difference() { import(\"a.off\"); import(\"b.off\"); }\n";
  std::ofstream(dir.path() / "scaled.csg")
      << "multmatrix(m=[[0.1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) union() { import(\"a.off\"); import(\"b.off\"); }\n";
  ArrangeOptions options;
  options.threads = 2;
  const AnyArrangeResult plain = csg((dir.path() / "plain.csg").string(), options);
  ASSERT_TRUE(std::holds_alternative<ArrangeResult>(plain));
  EXPECT_EQ(volume(std::get<ArrangeResult>(plain).mesh), 7);
  const AnyArrangeResult scaled = csg((dir.path() / "scaled.csg").string(), options);
  ASSERT_TRUE(std::holds_alternative<ExactArrangeResult>(scaled));
  EXPECT_EQ(volume(std::get<ExactArrangeResult>(scaled).mesh), tritri_test::Q(15, 10));
  EXPECT_EQ(tritri_test::unbalanced_edges(std::get<ExactArrangeResult>(scaled).mesh), 0u);
}

}  // namespace
