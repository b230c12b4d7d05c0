// Specification of write_mesh (arrangements/write_mesh.h) and read_exact_mesh
// (arrangements/read_exact_mesh.h):
// - exact OBJ / OFF files give back every coordinate exactly (to_exact), explicit, LPI and
//   TPI vertices alike, and the triangles in order;
// - default OBJ / OFF / PLY files load (load_triangle_soup) as the correctly rounded
//   doubles (to_double) and the same triangles;
// - provenance (source and label set per triangle) is in the side file (OBJ, OFF) or the
//   PLY face properties, and reads back equal;
// - refused requests and failed writes throw before or without leaving any file behind;
// - read_exact_mesh reads decimals as their exact decimal value and refuses malformed
//   files with InputError, never anything else.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>

#include <arrangements/load_triangle_soup.h>
#include <arrangements/read_exact_mesh.h>
#include <arrangements/write_mesh.h>
#include <tritri/implicit_point.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using arrangements::ExactMesh;
using arrangements::InputError;
using arrangements::InputErrorKind;
using arrangements::LabelSet;
using arrangements::OutputMesh;
using arrangements::read_exact_mesh;
using arrangements::Tri;
using arrangements::write_mesh;
using arrangements::WriteOptions;
using CGAL::Gmpq;
using tritri::ImplicitPoint;
using P = std::array<double, 3>;

using tritri_test::TempDir;

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::vector<std::string> file_lines(const std::string& path) {
  std::vector<std::string> lines;
  std::istringstream in(file_bytes(path));
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

Gmpq q(long n, long d = 1) { return Gmpq(n) / Gmpq(d); }

// Explicit points (one a non-dyadic decimal, one tiny, one huge, one negative zero),
// LPIs and TPIs with non-dyadic rational coordinates (1/3, 1/6, 1/5, ...), and an LPI from
// irregular doubles whose coordinates are rationals with large denominators.
std::vector<ImplicitPoint> sample_points() {
  const P o{0, 0, 0}, ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
  return {
      ImplicitPoint::explicit_point(0, 0, 0),
      ImplicitPoint::explicit_point(1, 0, 0),
      ImplicitPoint::explicit_point(0, 1, 0),
      ImplicitPoint::explicit_point(0.1, -2.5, 1e-300),
      ImplicitPoint::explicit_point(-0.0, 3e250, 5e-324),
      // (0,0,0)-(1,1,1) meets x + y + z = 1 at (1/3, 1/3, 1/3).
      ImplicitPoint::lpi(o, P{1, 1, 1}, ex, ey, ez),
      // (0,0,0)-(1,2,3) meets x + y + z = 1 at (1/6, 1/3, 1/2).
      ImplicitPoint::lpi(o, P{1, 2, 3}, ex, ey, ez),
      // x + y + z = 1, x = y, z = 3x meet at (1/5, 1/5, 3/5).
      ImplicitPoint::tpi(ex, ey, ez, o, P{1, 1, 0}, ez, o, ey, P{1, 0, 3}),
      ImplicitPoint::lpi(P{0.1, 0.2, 0.3}, P{1.7, -2.3, 0.9}, P{0.3, 0.1, -0.5}, P{-1.1, 0.4, 0.2}, P{0.6, -0.8, 1.3}),
      ImplicitPoint::tpi(P{0.1, 0.7, 0.3}, P{1.3, -0.2, 0.9}, P{-0.4, 0.5, 1.1}, P{0.2, 0.2, -0.7}, P{1.9, 0.3, 0.1},
                         P{-0.6, 1.4, 0.8}, P{0.9, -1.2, 0.3}, P{0.5, 0.5, 2.1}, P{-1.3, 0.7, -0.2}),
  };
}

OutputMesh sample_mesh(std::int64_t big_source = 7) {
  OutputMesh m;
  m.vertices = sample_points();
  m.triangles = {{0, 1, 2}, {5, 6, 7}, {1, 8, 9}, {3, 4, 5}, {9, 0, 6}};
  m.source = {0, 3, 2, big_source, 2147483647};
  m.label_sets = {{0}, {0, 1, 7}, {}, {4294967295u}};
  m.label_set = {0, 1, 2, 3, 1};
  return m;
}

void expect_exact_round_trip(const OutputMesh& m, const ExactMesh& r) {
  ASSERT_EQ(r.vertices.size(), m.vertices.size());
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const std::array<Gmpq, 3> expected = tritri::to_exact(m.vertices[i]);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(r.vertices[i][k], expected[k]) << "vertex " << i << " coordinate " << k;
  }
  EXPECT_EQ(r.triangles, m.triangles);
}

TEST(WriteMesh, SamplePointsHaveTheIntendedRationalCoordinates) {
  // Guards the test data: the implicit points really are non-dyadic rationals.
  const auto pts = sample_points();
  EXPECT_EQ(tritri::to_exact(pts[5]), (std::array<Gmpq, 3>{q(1, 3), q(1, 3), q(1, 3)}));
  EXPECT_EQ(tritri::to_exact(pts[6]), (std::array<Gmpq, 3>{q(1, 6), q(1, 3), q(1, 2)}));
  EXPECT_EQ(tritri::to_exact(pts[7]), (std::array<Gmpq, 3>{q(1, 5), q(1, 5), q(3, 5)}));
  for (int i : {8, 9}) {
    const auto e = tritri::to_exact(pts[i]);
    const auto d = tritri::to_double(pts[i]);
    for (int k = 0; k < 3; ++k) EXPECT_NE(e[k], Gmpq(d[k])) << "point " << i << " is not rounded by to_double";
  }
}

TEST(WriteMesh, ExactObjAndOffReadBackExactly) {
  TempDir dir;
  const OutputMesh m = sample_mesh();
  for (const char* name : {"m.obj", "m.off", "m.OBJ", "m.Off"}) {
    SCOPED_TRACE(name);
    write_mesh(dir.path(name), m, WriteOptions{.exact = true});
    expect_exact_round_trip(m, read_exact_mesh(dir.path(name)));
  }
}

TEST(WriteMesh, ExactCoordinatesAreReducedRationals) {
  TempDir dir;
  const OutputMesh m = sample_mesh();
  write_mesh(dir.path("m.obj"), m, WriteOptions{.exact = true});
  const auto obj = file_lines(dir.path("m.obj"));
  ASSERT_EQ(obj.size(), m.vertices.size() + m.triangles.size());
  EXPECT_EQ(obj[1], "v 1 0 0");
  // 0.1 is the double 3602879701896397 / 2^55; 1e-300 and 5e-324 are written whole too.
  EXPECT_EQ(obj[3].substr(0, 41), "v 3602879701896397/36028797018963968 -5/2");
  EXPECT_EQ(obj[5], "v 1/3 1/3 1/3");
  EXPECT_EQ(obj[6], "v 1/6 1/3 1/2");
  EXPECT_EQ(obj[7], "v 1/5 1/5 3/5");
  EXPECT_EQ(obj[10], "f 1 2 3");
  write_mesh(dir.path("m.off"), m, WriteOptions{.exact = true});
  const auto off = file_lines(dir.path("m.off"));
  ASSERT_EQ(off.size(), 2 + m.vertices.size() + m.triangles.size());
  EXPECT_EQ(off[0], "OFF");
  EXPECT_EQ(off[1], "10 5 0");
  EXPECT_EQ(off[2 + 6], "1/6 1/3 1/2");
  EXPECT_EQ(off[2 + 10], "3 0 1 2");
}

TEST(WriteMesh, DefaultFilesLoadAsCorrectlyRoundedDoubles) {
  TempDir dir;
  const OutputMesh m = sample_mesh();
  for (const char* name : {"m.obj", "m.off", "m.ply", "m.PLY"}) {
    SCOPED_TRACE(name);
    write_mesh(dir.path(name), m);
    const arrangements::TriangleSoup soup = arrangements::load_triangle_soup(dir.path(name));
    ASSERT_EQ(soup.vertices.size(), m.vertices.size());
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
      const std::array<double, 3> expected = tritri::to_double(m.vertices[i]);
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(soup.vertices[i][k], expected[k]) << "vertex " << i;
        EXPECT_EQ(std::signbit(soup.vertices[i][k]), std::signbit(expected[k])) << "vertex " << i;
      }
    }
    EXPECT_EQ(soup.triangles, m.triangles);
  }
}

TEST(WriteMesh, DefaultCoordinatesHaveSeventeenSignificantDigits) {
  TempDir dir;
  write_mesh(dir.path("m.obj"), sample_mesh());
  const auto obj = file_lines(dir.path("m.obj"));
  // As printf's %.17g: trailing zeros dropped.
  EXPECT_EQ(obj[3], "v 0.10000000000000001 -2.5 1e-300");
  EXPECT_EQ(obj[4], "v -0 2.9999999999999998e+250 4.9406564584124654e-324");
  EXPECT_EQ(obj[5], "v 0.33333333333333331 0.33333333333333331 0.33333333333333331");
}

// The rows of a provenance side file, after checking its header.
struct ProvenanceRow {
  std::int64_t source;
  LabelSet labels;
  bool operator==(const ProvenanceRow&) const = default;
};

std::vector<ProvenanceRow> read_provenance(const std::string& path) {
  const auto lines = file_lines(path);
  EXPECT_FALSE(lines.empty());
  if (lines.empty()) return {};
  EXPECT_EQ(lines[0], "triangle,source,labels");
  std::vector<ProvenanceRow> rows;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    const std::size_t c1 = line.find(','), c2 = line.find(',', c1 + 1);
    EXPECT_NE(c2, std::string::npos) << line;
    EXPECT_EQ(std::stoll(line.substr(0, c1)), static_cast<long long>(i - 1)) << line;
    ProvenanceRow row{std::stoll(line.substr(c1 + 1, c2 - c1 - 1)), {}};
    std::istringstream labels(line.substr(c2 + 1));
    for (unsigned long l; labels >> l;) row.labels.push_back(static_cast<std::uint32_t>(l));
    rows.push_back(row);
  }
  return rows;
}

std::vector<ProvenanceRow> expected_provenance(const OutputMesh& m) {
  std::vector<ProvenanceRow> rows;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) rows.push_back({m.source[t], m.label_sets[m.label_set[t]]});
  return rows;
}

TEST(WriteMesh, ObjAndOffProvenanceSideFileListsSourceAndLabels) {
  TempDir dir;
  const OutputMesh m = sample_mesh(int64_t{1} << 40);
  for (const char* name : {"m.obj", "m.off"})
    for (bool exact : {false, true}) {
      SCOPED_TRACE(std::string(name) + (exact ? " exact" : ""));
      write_mesh(dir.path(name), m, WriteOptions{.exact = exact});
      EXPECT_EQ(read_provenance(dir.path(name) + ".provenance.csv"), expected_provenance(m));
    }
  const auto lines = file_lines(dir.path("m.obj.provenance.csv"));
  EXPECT_EQ(lines[2], "1,3,0 1 7");
  EXPECT_EQ(lines[3], "2,2,");  // the empty label set
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"m.obj", "m.obj.provenance.csv", "m.off", "m.off.provenance.csv"}));
}

// Reads the body of a PLY file as write_mesh.h describes it.
struct PlyContents {
  std::vector<std::array<double, 3>> vertices;
  std::vector<Tri> triangles;
  std::vector<ProvenanceRow> provenance;
};

template <class T>
T take(const std::string& bytes, std::size_t& pos) {
  // Little-endian host assumed by this reader (x86, ARM); the writer does not assume it.
  T v;
  if (pos + sizeof v > bytes.size()) throw std::runtime_error("PLY body too short");
  std::memcpy(&v, bytes.data() + pos, sizeof v);
  pos += sizeof v;
  return v;
}

PlyContents read_ply(const std::string& path, bool int_source) {
  const std::string bytes = file_bytes(path);
  const std::size_t end = bytes.find("end_header\n");
  EXPECT_NE(end, std::string::npos);
  std::istringstream header(bytes.substr(0, end));
  std::vector<std::string> lines;
  for (std::string line; std::getline(header, line);)
    if (line.rfind("comment", 0) != 0) lines.push_back(line);
  std::size_t nv = 0, nf = 0;
  EXPECT_EQ(lines.size(), 10u);
  EXPECT_EQ(lines[0], "ply");
  EXPECT_EQ(lines[1], "format binary_little_endian 1.0");
  EXPECT_EQ(std::sscanf(lines[2].c_str(), "element vertex %zu", &nv), 1);
  EXPECT_EQ(lines[3], "property double x");
  EXPECT_EQ(lines[4], "property double y");
  EXPECT_EQ(lines[5], "property double z");
  EXPECT_EQ(std::sscanf(lines[6].c_str(), "element face %zu", &nf), 1);
  EXPECT_EQ(lines[7], "property list uchar int vertex_indices");
  EXPECT_EQ(lines[8], int_source ? "property int source" : "property double source");
  EXPECT_EQ(lines[9], "property list uint uint labels");
  PlyContents c;
  std::size_t pos = end + std::strlen("end_header\n");
  for (std::size_t i = 0; i < nv; ++i)
    c.vertices.push_back({take<double>(bytes, pos), take<double>(bytes, pos), take<double>(bytes, pos)});
  for (std::size_t f = 0; f < nf; ++f) {
    EXPECT_EQ(take<std::uint8_t>(bytes, pos), 3);
    c.triangles.push_back(
        {take<std::int32_t>(bytes, pos), take<std::int32_t>(bytes, pos), take<std::int32_t>(bytes, pos)});
    ProvenanceRow row{};
    row.source = int_source ? take<std::int32_t>(bytes, pos) : static_cast<std::int64_t>(take<double>(bytes, pos));
    const std::uint32_t n = take<std::uint32_t>(bytes, pos);
    for (std::uint32_t k = 0; k < n; ++k) row.labels.push_back(take<std::uint32_t>(bytes, pos));
    c.provenance.push_back(row);
  }
  EXPECT_EQ(pos, bytes.size()) << "bytes after the last face";
  return c;
}

TEST(WriteMesh, PlyFacePropertiesHoldSourceAndLabels) {
  TempDir dir;
  // Sources that fit in int are written as int; a larger one makes the column double.
  for (std::int64_t big : {std::int64_t{7}, std::int64_t{5'000'000'000}, (std::int64_t{1} << 53) - 1}) {
    SCOPED_TRACE(big);
    const OutputMesh m = sample_mesh(big);
    write_mesh(dir.path("m.ply"), m);
    const PlyContents c = read_ply(dir.path("m.ply"), big == 7);
    ASSERT_EQ(c.vertices.size(), m.vertices.size());
    for (std::size_t i = 0; i < m.vertices.size(); ++i) EXPECT_EQ(c.vertices[i], tritri::to_double(m.vertices[i]));
    EXPECT_EQ(c.triangles, m.triangles);
    EXPECT_EQ(c.provenance, expected_provenance(m));
    // The repository's loader accepts the extra face properties.
    EXPECT_EQ(arrangements::load_triangle_soup(dir.path("m.ply")).triangles, m.triangles);
  }
  EXPECT_EQ(dir.entries(), std::set<std::string>{"m.ply"});  // no side file for PLY
}

TEST(WriteMesh, EmptyMeshRoundTrips) {
  TempDir dir;
  const OutputMesh empty;
  for (const char* name : {"e.obj", "e.off"}) {
    write_mesh(dir.path(name), empty, WriteOptions{.exact = true});
    const ExactMesh r = read_exact_mesh(dir.path(name));
    EXPECT_TRUE(r.vertices.empty());
    EXPECT_TRUE(r.triangles.empty());
    EXPECT_EQ(file_lines(dir.path(name) + ".provenance.csv"), std::vector<std::string>{"triangle,source,labels"});
  }
  write_mesh(dir.path("e.ply"), empty);
  EXPECT_TRUE(read_ply(dir.path("e.ply"), true).triangles.empty());
}

TEST(WriteMesh, RewritingReplacesTheFileAndLeavesNoTemporaryFile) {
  TempDir dir;
  OutputMesh m = sample_mesh();
  write_mesh(dir.path("m.obj"), m, WriteOptions{.exact = true});
  m.triangles.resize(2);
  m.source.resize(2);
  m.label_set.resize(2);
  write_mesh(dir.path("m.obj"), m, WriteOptions{.exact = true});
  expect_exact_round_trip(m, read_exact_mesh(dir.path("m.obj")));
  EXPECT_EQ(read_provenance(dir.path("m.obj.provenance.csv")), expected_provenance(m));
  EXPECT_EQ(dir.entries(), (std::set<std::string>{"m.obj", "m.obj.provenance.csv"}));
}

TEST(WriteMesh, UnknownExtensionThrowsBeforeCreatingAnyFile) {
  TempDir dir;
  for (const char* name : {"m.stl", "m.txt", "m", "m.obj.bak", "obj"}) {
    SCOPED_TRACE(name);
    try {
      write_mesh(dir.path(name), sample_mesh());
      ADD_FAILURE() << "no exception";
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind, InputErrorKind::unknown_format);
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(WriteMesh, ExactPlyIsRefusedBeforeCreatingAnyFile) {
  TempDir dir;
  try {
    write_mesh(dir.path("m.ply"), sample_mesh(), WriteOptions{.exact = true});
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.kind, InputErrorKind::unsupported_variant);
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(WriteMesh, InconsistentMeshThrowsInvalidArgumentAndKeepsTheOldFile) {
  TempDir dir;
  const std::string old = dir.write("m.obj", "old contents\n");
  auto bad = [] {
    std::vector<OutputMesh> meshes(4, sample_mesh());
    meshes[0].triangles[1][2] = 10;  // vertex index out of range
    meshes[1].triangles[0][0] = -1;
    meshes[2].label_set[4] = 4;  // label set out of range
    meshes[3].source.pop_back();
    return meshes;
  }();
  for (const OutputMesh& m : bad) {
    EXPECT_THROW(write_mesh(old, m), std::invalid_argument);
    EXPECT_THROW(write_mesh(dir.path("m.ply"), m), std::invalid_argument);
  }
  // A PLY source must be exact as a double.
  EXPECT_THROW(write_mesh(dir.path("m.ply"), sample_mesh((std::int64_t{1} << 53) + 1)), std::invalid_argument);
  EXPECT_EQ(file_bytes(old), "old contents\n");
  EXPECT_EQ(dir.entries(), std::set<std::string>{"m.obj"});
}

TEST(WriteMesh, UnwritablePathThrowsRuntimeErrorAndLeavesNoFile) {
  TempDir dir;
  dir.write("plain_file", "x");
  fs::create_directory(dir.path("folder.obj"));
  fs::create_directory(dir.path("m.off.provenance.csv"));
  const std::set<std::string> before = dir.entries();
  for (const std::string& path :
       {dir.path("missing_folder/m.obj"), dir.path("plain_file/m.ply"), dir.path("folder.obj"), dir.path("m.off")}) {
    SCOPED_TRACE(path);
    try {
      write_mesh(path, sample_mesh());
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(dynamic_cast<const InputError*>(&e), nullptr) << e.what();
      EXPECT_NE(std::string(e.what()).find(fs::path(path).filename().string()), std::string::npos) << e.what();
    }
    EXPECT_EQ(dir.entries(), before);
    EXPECT_TRUE(fs::is_empty(dir.path("folder.obj")));
  }
  // A folder without write permission (root may write anywhere: then nothing to check).
  fs::create_directory(dir.path("read_only"));
  fs::permissions(dir.path("read_only"), fs::perms::owner_read | fs::perms::owner_exec);
  if (::access(dir.path("read_only").c_str(), W_OK) != 0) {
    EXPECT_THROW(write_mesh(dir.path("read_only/m.obj"), sample_mesh()), std::runtime_error);
    EXPECT_TRUE(fs::is_empty(dir.path("read_only")));
  }
  fs::permissions(dir.path("read_only"), fs::perms::owner_all);
}

TEST(WriteMesh, WriteFailureMidwayRemovesTheTemporaryFileAndKeepsTheOldFile) {
  TempDir dir;
  const std::string old = dir.write("m.obj", "old contents\n");
  // A file size limit makes write() fail after the temporary file exists (EFBIG; the
  // signal it would raise is ignored).
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto saved_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = saved;
  small.rlim_cur = 100;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  bool threw = false;
  try {
    write_mesh(old, sample_mesh(), WriteOptions{.exact = true});
  } catch (const std::runtime_error& e) {
    threw = true;
    EXPECT_NE(std::string(e.what()).find("m.obj"), std::string::npos) << e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, saved_handler);
  EXPECT_TRUE(threw);
  EXPECT_EQ(file_bytes(old), "old contents\n");
  EXPECT_EQ(dir.entries(), std::set<std::string>{"m.obj"});
}

TEST(WriteMesh, CoordinateBeyondTheDoubleRangeNeedsExactOutput) {
  TempDir dir;
  OutputMesh m;
  // The line (0,0,0)-(1e300,0,1e-300) meets the plane z = 1 at x = 1e600.
  m.vertices = {ImplicitPoint::lpi(P{0, 0, 0}, P{1e300, 0, 1e-300}, P{0, 0, 1}, P{1, 0, 1}, P{0, 1, 1}),
                ImplicitPoint::explicit_point(0, 0, 0), ImplicitPoint::explicit_point(0, 1, 0)};
  m.triangles = {{0, 1, 2}};
  m.source = {0};
  m.label_set = {0};
  m.label_sets = {{0}};
  EXPECT_THROW(write_mesh(dir.path("m.obj"), m), std::runtime_error);
  EXPECT_TRUE(dir.entries().empty());
  write_mesh(dir.path("m.obj"), m, WriteOptions{.exact = true});
  expect_exact_round_trip(m, read_exact_mesh(dir.path("m.obj")));
}

TEST(ReadExactMesh, ReadsDecimalsAsTheirExactValue) {
  TempDir dir;
  const ExactMesh obj =
      read_exact_mesh(dir.write("d.obj",
                                "# comment\nv 0.1 -2.5e-3 7\r\nv +1/3 -4/6 .5\nvn 0 0 1\nv 1E2 0.0e+0 -0\n"
                                "g group\nv 00012.50 3e-0 -0.000\nf 1/1/1 2//1 -2 4 # quad\n"));
  EXPECT_EQ(
      obj.vertices,
      (std::vector<std::array<Gmpq, 3>>{
          {q(1, 10), q(-1, 400), q(7)}, {q(1, 3), q(-2, 3), q(1, 2)}, {q(100), q(0), q(0)}, {q(25, 2), q(3), q(0)}}));
  EXPECT_EQ(obj.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}}));  // the quad, as load_mesh_files splits it
  const ExactMesh off =
      read_exact_mesh(dir.write("d.off", "OFF 4 1 0\n# c\n0.1 0 0\n0 1/7 0\n\n0 0 1e-3\n1 1 1\n4 0 1 2 3\n"));
  EXPECT_EQ(off.vertices[0][0], q(1, 10));
  EXPECT_EQ(off.vertices[1][1], q(1, 7));
  EXPECT_EQ(off.vertices[2][2], q(1, 1000));
  EXPECT_EQ(off.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}}));
}

struct BadFile {
  const char* name;
  const char* contents;
  InputErrorKind kind;
};

TEST(ReadExactMesh, MalformedFilesThrowInputErrorOfTheRightKind) {
  const BadFile bad[] = {
      {"zero_den.obj", "v 1/0 0 0\n", InputErrorKind::malformed},
      {"neg_den.obj", "v 1/-2 0 0\n", InputErrorKind::malformed},
      {"two_slashes.obj", "v 1/2/3 0 0\n", InputErrorKind::malformed},
      {"nan.obj", "v nan 0 0\n", InputErrorKind::non_finite_coordinate},
      {"inf.obj", "v 0 inf 0\n", InputErrorKind::non_finite_coordinate},
      {"hex.obj", "v 0x10 0 0\n", InputErrorKind::malformed},
      {"huge_exponent.obj", "v 1e99999 0 0\n", InputErrorKind::too_large},
      {"bare_point.obj", "v . 0 0\n", InputErrorKind::malformed},
      {"bare_exponent.obj", "v 1e 0 0\n", InputErrorKind::malformed},
      {"two_coords.obj", "v 1 2\n", InputErrorKind::malformed},
      {"two_corners.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", InputErrorKind::too_few_corners},
      {"index_zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", InputErrorKind::index_out_of_range},
      {"index_beyond.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", InputErrorKind::index_out_of_range},
      {"relative_beyond.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", InputErrorKind::index_out_of_range},
      {"index_huge.obj", "v 0 0 0\nf 1 1 99999999999999999999\n", InputErrorKind::malformed},
      {"line_statement.obj", "v 0 0 0\nl 1 1\n", InputErrorKind::unsupported_variant},
      {"binary.obj", "v \x01\xff 0 0\n", InputErrorKind::malformed},
      {"nul.obj", "v 0 0 0\0\n", InputErrorKind::malformed},
      {"empty.off", "", InputErrorKind::malformed},
      {"no_magic.off", "3 1 0\n", InputErrorKind::malformed},
      {"coff_short.off", "COFF\n3 1 0\n", InputErrorKind::malformed},
      {"four_d.off", "4OFF\n3 1 0\n", InputErrorKind::unsupported_variant},
      {"two_counts.off", "OFF\n3 1\n", InputErrorKind::malformed},
      {"negative_count.off", "OFF\n-3 1 0\n", InputErrorKind::malformed},
      {"huge_count.off", "OFF\n99999999999 1 0\n", InputErrorKind::too_large},
      {"few_vertices.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n", InputErrorKind::malformed},
      {"few_faces.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n", InputErrorKind::malformed},
      {"face_short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", InputErrorKind::malformed},
      {"face_huge_n.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n", InputErrorKind::malformed},
      {"face_two.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", InputErrorKind::too_few_corners},
      {"face_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", InputErrorKind::index_out_of_range},
      {"slash_in_off.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1/ 0\n3 0 1 2\n", InputErrorKind::malformed},
      {"mesh.stl", "solid\n", InputErrorKind::unknown_format},
  };
  TempDir dir;
  for (const BadFile& b : bad) {
    SCOPED_TRACE(b.name);
    // nul.obj: the contents go on after the NUL byte.
    const std::size_t size = std::strlen(b.contents) + (std::string(b.name) == "nul.obj" ? 2 : 0);
    const std::string path = dir.write(b.name, std::string(b.contents, size));
    try {
      read_exact_mesh(path);
      ADD_FAILURE() << "no exception";
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind, b.kind) << e.what();
      EXPECT_NE(std::string(e.what()).find(b.name), std::string::npos) << e.what();
    }
  }
  // Any number of digits is read (only a decimal exponent is bounded): the value exactly.
  const std::string digits(100001, '7');
  const ExactMesh long_digits = read_exact_mesh(dir.write("long_digits.obj", "v 0 0 " + digits + "\n"));
  ASSERT_EQ(long_digits.vertices.size(), 1u);
  EXPECT_EQ(long_digits.vertices[0][2], Gmpq(digits));
  try {
    read_exact_mesh(dir.path("missing.obj"));
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.kind, InputErrorKind::unreadable_file);
  }
}

TEST(ReadExactMesh, CorruptedExactFilesReadOrThrowInputErrorOnly) {
  TempDir dir;
  write_mesh(dir.path("m.obj"), sample_mesh(), WriteOptions{.exact = true});
  write_mesh(dir.path("m.off"), sample_mesh(), WriteOptions{.exact = true});
  std::mt19937 rng(12345);
  std::string alphabet = "0123456789/-+.eE# \n\tfv";
  alphabet += {'\0', '\xff'};
  for (const char* name : {"m.obj", "m.off"}) {
    const std::string original = file_bytes(dir.path(name));
    for (int trial = 0; trial < 400; ++trial) {
      std::string bytes = original;
      const int edits = 1 + static_cast<int>(rng() % 4);
      for (int e = 0; e < edits; ++e) {
        const std::size_t at = rng() % bytes.size();
        switch (rng() % 3) {
          case 0:
            bytes[at] = alphabet[rng() % alphabet.size()];
            break;
          case 1:
            bytes.erase(at, 1 + rng() % 8);
            break;
          case 2:
            bytes.resize(at);
            break;
        }
        if (bytes.empty()) bytes = "v";
      }
      const std::string path = dir.write(std::string("corrupt_") + name, bytes);
      try {
        read_exact_mesh(path);
      } catch (const InputError&) {
      } catch (const std::exception& e) {
        ADD_FAILURE() << "not an InputError: " << e.what() << "\n" << bytes;
      }
    }
  }
}

}  // namespace
