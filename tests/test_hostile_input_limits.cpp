// Hostile input with bounded cost (issue 36), for the loaders (load_triangle_soup.h) and
// the `arrange` command line (run as a separate process, under an address-space limit):
// - a file that is not the format its name says (NUL bytes, an 8 GB sparse file, binary
//   data without a line end) is refused with exit status 1 and a message naming the file,
//   in under 1 s and 100 MB whatever its size, for every format;
// - text lines: a NUL byte is refused at its line; a line longer than 1 MiB is refused,
//   except vertex and face records (OBJ v / f, OFF records, the ASCII PLY body) that go on
//   with numbers and blanks only;
// - what `arrange --exact` writes, `arrange` reads: rationals of 200000 digits (and the
//   longer ones their arrangement makes), integers that are not doubles;
// - worker threads the system refuses (an address-space limit): exit status 1 with
//   "cannot start N worker threads", never SIGABRT inside oneTBB.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "arrangements/load_triangle_soup.h"
#include "arrangements/read_exact_mesh.h"
#include "io/write_off.h"
#include "support/mesh_generators.h"
#include "support/run_program.h"
#include "support/temp_dir.h"

namespace {

using arrangements::ExactMesh;
using arrangements::ExactTriangleSoup;
using arrangements::InputError;
using arrangements::InputErrorKind;
using arrangements::load_mesh_files;
using arrangements::load_triangle_soup;
using arrangements::read_exact_mesh;
using CGAL::Gmpq;
using tritri_test::LimitedExit;
using tritri_test::spawn_limited;
using tritri_test::TempDir;
using namespace std::string_literals;  // "...\0..."s keeps its NUL bytes

constexpr std::size_t kMiB = std::size_t{1} << 20;
constexpr rlim_t kGiB = rlim_t{1} << 30;

// AddressSanitizer reserves terabytes of address space for its shadow memory: a program
// built with it cannot start under an address-space cap, and its time and memory are not
// the program's. There the runs go without the cap and only their outcome is checked (the
// Release run checks the bounds).
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
rlim_t cap(rlim_t bytes) { return kSanitized ? RLIM_INFINITY : bytes; }

// ---- files that are not their format: refused at once, whatever their size -------------

// A file of `size` bytes that takes no disk space (ftruncate): all NUL bytes.
std::string sparse_file(const TempDir& dir, const std::string& name, off_t size) {
  const std::string path = dir.path(name);
  const int fd = open(path.c_str(), O_CREAT | O_WRONLY | O_TRUNC, 0644);
  EXPECT_GE(fd, 0) << path;
  EXPECT_EQ(ftruncate(fd, size), 0) << path;
  close(fd);
  return path;
}

// Binary data without NUL bytes and line ends (bytes 1 to 255 but '\n' and '\r').
std::string binary_junk(std::size_t size) {
  std::string s(size, '\0');
  unsigned char b = 1;
  for (char& c : s) {
    c = static_cast<char>(b);
    do b = static_cast<unsigned char>(b * 7 + 3); while (b == 0 || b == '\n' || b == '\r');
  }
  return s;
}

// arrange on `path`, under 2 GB of address space (so that a reader that holds the whole
// file fails quickly instead of taking the machine's memory).
void expect_refused_at_once(const TempDir& dir, const std::string& path, const std::string& reason) {
  SCOPED_TRACE(path);
  const std::string out = dir.path("out.off");
  const LimitedExit r = spawn_limited(ARRANGE_BIN, {path, "-o", out}, dir.path(), cap(2 * kGiB));
  ASSERT_TRUE(r.exit.exited) << "signal " << r.exit.signal;
  EXPECT_EQ(r.exit.code, 1) << r.exit.err;
  EXPECT_EQ(r.exit.err.rfind("arrange: " + path + ": line 1: ", 0), 0u) << r.exit.err;  // an InputError
  EXPECT_NE(r.exit.err.find(reason), std::string::npos) << r.exit.err;
  if (!kSanitized) {
    EXPECT_LT(r.seconds, 1.0);
    EXPECT_LT(r.peak_rss_kb, 100 * 1024) << "KB";
  }
  EXPECT_FALSE(std::filesystem::exists(out));
  std::printf("  %s: %.3f s, %ld KB\n", std::filesystem::path(path).filename().c_str(), r.seconds, r.peak_rss_kb);
}

TEST(NotItsFormat, NulFilesOfAnySizeAreRefusedInUnderASecondAnd100MB) {
  TempDir dir;
  for (const std::string ext : {"stl", "obj", "off", "ply"}) {
    const std::string reason = ext == "stl" ? "a NUL byte: neither an ASCII STL" : "a NUL byte";
    expect_refused_at_once(dir, dir.write("nul." + ext, std::string(4 * kMiB, '\0')), reason);
    expect_refused_at_once(dir, sparse_file(dir, "sparse." + ext, off_t{8} << 30), reason);
  }
  // The binary STL explanation names the mismatch (a header count of 0 needs 84 bytes).
  const LimitedExit r = spawn_limited(ARRANGE_BIN, {dir.path("sparse.stl")}, dir.path(), cap(2 * kGiB));
  EXPECT_NE(r.exit.err.find("the binary STL size does not match its triangle count (a header declaring 0 triangles "
                            "needs 84 bytes, the file has 8589934592)"),
            std::string::npos)
      << r.exit.err;
}

TEST(NotItsFormat, BinaryDataWithoutLineEndsIsRefusedAfterItsFirstMebibyte) {
  TempDir dir;
  const std::vector<std::string> exts{"stl", "obj", "off", "ply"};
  {  // written, then freed: a child's peak memory counts what this process holds at fork
    const std::string junk = binary_junk(64 * kMiB);
    for (const std::string& ext : exts) dir.write("junk." + ext, junk);
  }
  for (const std::string& ext : exts)
    expect_refused_at_once(dir, dir.path("junk." + ext), "longer than 1048576 bytes (1 MiB)");
}

// ---- text lines: NUL bytes, and 1 MiB unless a record of numbers -------------------------

InputError refusal(const std::string& path) {
  try {
    load_mesh_files({path});
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << path << " loaded, but must be refused";
  return InputError(InputErrorKind::malformed, "");
}

struct Refused {
  std::string name, text;
  std::string message;  // in the message, after "PATH: " (the line, as far as it is named)
};

TEST(TextLines, NulBytesAndLongLinesOtherThanRecordsOfNumbersAreRefusedAtTheirLine) {
  const std::string long_text(kMiB + 1, 'c');  // one byte beyond the limit
  const std::string digits(kMiB + 10, '7');
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const std::string ply_head = "ply\nformat ascii 1.0\n";
  const std::string ply_rest =
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  std::string joined = "g a";  // a group name over many lines joined by backslashes
  for (std::size_t i = 0; i <= kMiB; ++i) joined += "b\\\n";
  const std::vector<Refused> cases{
      {"comment.obj", "#" + long_text + "\n" + triangle, "line 1: longer than 1048576 bytes (1 MiB)"},
      {"nul.obj", triangle + "# a\0b\n"s, "line 5: a NUL byte: not a text mesh file"},
      {"v_then_text.obj", "v 0 0 " + digits + " # comment\n" + triangle,
       "line 1: longer than 1048576 bytes (1 MiB) with '#' after them (only numbers and blanks may follow)"},
      {"joined.obj", joined + "\n" + triangle,
       "the lines joined by backslashes are longer than 1048576 bytes (1 MiB) and not a v or f statement"},
      {"header.off", "OFF" + std::string(kMiB, ' ') + "\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       "line 1: longer than 1048576 bytes"},
      {"nul.off", "OFF\n3 1 0\n0 0 0\n1 0\0 0\n0 1 0\n3 0 1 2\n"s, "line 4: a NUL byte"},
      {"name.stl", "solid " + long_text + "\nendsolid\n",
       "line 1: longer than 1048576 bytes (1 MiB): neither an ASCII STL"},
      {"nul.stl", "solid s\nfacet normal 0 0 1\n\0"s, "line 3: a NUL byte: not an ASCII STL"},
      {"comment.ply", ply_head + "comment " + long_text + "\n" + ply_rest, "line 3: longer than 1048576 bytes"},
      {"nul.ply", ply_head + "comment \0\n"s + ply_rest, "line 3: a NUL byte: not a PLY file"},
  };
  TempDir dir;
  for (const Refused& c : cases) {
    const std::string path = dir.write(c.name, c.text);
    const InputError e = refusal(path);
    EXPECT_EQ(e.kind, InputErrorKind::malformed) << c.name << ": " << e.what();
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(path + ": line ", 0), 0u) << c.name << ": " << what;
    EXPECT_NE(what.find(": " + c.message), std::string::npos) << c.name << ": " << what;
  }
}

// (10^k + 1) / 10^k: within the double range, not a double, 2 (k + 1) digits as written.
std::string long_rational(std::size_t k) {
  return "1" + std::string(k - 1, '0') + "1/1" + std::string(k, '0');
}

TEST(TextLines, RecordsOfNumbersMayBeLongerThanAMebibyte) {
  TempDir dir;
  const std::string q = long_rational(700000);  // a line of 1.4 MB
  const Gmpq value(q);
  const std::string obj = dir.write("long.obj", "v " + q + " 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n");
  const std::string off = dir.write("long.off", "OFF\n3 1 0\n0 1 0\n0 0 1\n" + q + " 0 0\n3 0 1 2\n");
  const ExactTriangleSoup a = std::get<ExactTriangleSoup>(load_mesh_files({obj}));
  EXPECT_EQ(a.vertices[0][0], value);
  const ExactTriangleSoup b = std::get<ExactTriangleSoup>(load_mesh_files({off}));
  EXPECT_EQ(b.vertices[2][0], value);
  EXPECT_EQ(read_exact_mesh(obj).vertices[0][0], value);
  // An ASCII PLY item of 1.6 MB: a list of 400000 entries in an element that is skipped.
  std::string list = "400000";
  for (int i = 0; i < 400000; ++i) list += " 333";
  const std::string ply = dir.write(
      "long.ply",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element extra 1\nproperty list int int values\nelement face 1\nproperty list uchar int vertex_indices\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n" +
          list + "\n3 0 1 2\n");
  EXPECT_EQ(load_triangle_soup(ply).triangles.size(), 1u);
}

// ---- what arrange writes, arrange reads ------------------------------------------------

std::vector<std::array<Gmpq, 3>> sorted_vertices(const ExactMesh& m) {
  std::vector<std::array<Gmpq, 3>> v = m.vertices;
  std::sort(v.begin(), v.end());
  return v;
}

// arrange in -o a.obj --exact, then arrange a.obj -o b.obj --exact: both succeed, and b
// holds a's vertices exactly (an arrangement is its own arrangement).
ExactMesh arrange_twice(const TempDir& dir, const std::string& in) {
  const std::string a = dir.path("a.obj"), b = dir.path("b.obj");
  for (const auto& [from, to] : {std::pair{in, a}, std::pair{a, b}}) {
    const LimitedExit r = spawn_limited(ARRANGE_BIN, {from, "-o", to, "--exact"}, dir.path(), cap(8 * kGiB));
    EXPECT_TRUE(r.exit.exited && r.exit.code == 0) << from << ": " << r.exit.err;
  }
  const ExactMesh first = read_exact_mesh(a), second = read_exact_mesh(b);
  EXPECT_EQ(sorted_vertices(first), sorted_vertices(second));
  EXPECT_EQ(first.triangles.size(), second.triangles.size());
  return first;
}

TEST(ArrangeReadsWhatItWrites, RationalsOf200000DigitsAndTheLongerOnesOfTheirArrangement) {
  TempDir dir;
  const std::string q = long_rational(200000);
  // A triangle with the long coordinate, crossed by an ordinary one: the crossing points
  // have longer rationals still.
  const std::string in = dir.write(
      "in.obj", "v " + q + " 0 0\nv 0 1 0\nv 0 0 1\nv 0.25 0.25 -1\nv 0.3 0.2 2\nv 0.2 0.3 2\nf 1 2 3\nf 4 5 6\n");
  const ExactMesh m = arrange_twice(dir, in);
  const Gmpq value(q);
  EXPECT_TRUE(std::any_of(m.vertices.begin(), m.vertices.end(), [&](const auto& v) { return v[0] == value; }));
  EXPECT_GT(m.triangles.size(), 2u);  // the triangles were split where they cross
}

TEST(ArrangeReadsWhatItWrites, IntegersThatAreNotDoubles) {
  TempDir dir;
  const Gmpq big(std::string("1152921504606847105"));  // 2^60 + 1
  const std::string in = dir.write("in.obj", "v 1152921504606847105/1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n");
  const ExactMesh m = arrange_twice(dir, in);
  EXPECT_TRUE(std::any_of(m.vertices.begin(), m.vertices.end(), [&](const auto& v) { return v[0] == big; }));
}

// ---- worker threads the system refuses -------------------------------------------------

TEST(WorkerThreads, RefusedThreadsAreExitStatusOneWithAMessage) {
  if (kSanitized) GTEST_SKIP() << "needs an address-space cap, which AddressSanitizer cannot run under";
  TempDir dir;
  const auto soup = arrangements::rotated_copies(arrangements::uv_sphere({0.1, 0.2, 0.3}, 1.0, 12, 24), 3);
  const std::string in = dir.path("spheres.off");
  arrangements::write_off(in, soup.vertices, soup.triangles);
  // 1 GB of address space holds neither 511 nor 1023 stacks of oneTBB's 4 MB: the system
  // refuses threads, as under ulimit -u.
  for (const std::string threads : {"512", "1024"}) {
    const LimitedExit r = spawn_limited(ARRANGE_BIN, {in, "--threads", threads}, dir.path(), kGiB);
    ASSERT_TRUE(r.exit.exited) << threads << ": signal " << r.exit.signal << ": " << r.exit.err;
    EXPECT_EQ(r.exit.code, 1) << r.exit.err;
    EXPECT_EQ(r.exit.err.rfind("arrange: cannot start " + threads + " worker threads: ", 0), 0u) << r.exit.err;
    EXPECT_EQ(r.exit.out, "");
  }
  // Without the limit the same run succeeds.
  const LimitedExit ok = spawn_limited(ARRANGE_BIN, {in, "--threads", "64"}, dir.path(), RLIM_INFINITY);
  EXPECT_TRUE(ok.exit.exited && ok.exit.code == 0) << ok.exit.err;
}

}  // namespace
