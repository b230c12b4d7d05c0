// write_mesh (arrangements/write_mesh.h) formats the lines of large meshes in chunks, in
// parallel, and appends them in order. Specification checked here on meshes of many chunks
// (tens of thousands of lines, with an odd last chunk):
// - the default OBJ and OFF files and their provenance side files are byte for byte the
//   text a plain loop of printf's "%.17g" and "%d" makes (the oracle, written here apart
//   from the writer);
// - every file, exact OBJ / OFF included, is byte-identical at 1, 2 and 4 worker threads;
// - exact files read back exactly (read_exact_mesh) in the right order.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <arrangements/read_exact_mesh.h>
#include <arrangements/write_mesh.h>
#include <tritri/implicit_point.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "support/temp_dir.h"

namespace {

using arrangements::OutputMesh;
using arrangements::write_mesh;
using arrangements::WriteOptions;
using tritri::ImplicitPoint;
using P = std::array<double, 3>;

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Explicit vertices of every magnitude and sign (negative zero, subnormals, 1e300), every
// 97th an LPI (a rational vertex, so the exact files hold fractions); triangles over them in
// a scrambled order, sources up to 2^40, label sets of 0 to 3 labels.
OutputMesh large_mesh(std::size_t vertex_count, std::size_t triangle_count) {
  std::mt19937_64 rng(20261203);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-1074, 1000);
  OutputMesh m;
  for (std::size_t i = 0; i < vertex_count; ++i) {
    if (i % 97 == 5) {
      const P a{unit(rng), unit(rng), unit(rng)}, b{unit(rng) + 3, unit(rng), unit(rng)};
      m.vertices.push_back(ImplicitPoint::lpi(a, b, P{2, 0, 0}, P{2, 1, 0}, P{2, 0, 1}));  // meets x = 2
      continue;
    }
    P p;
    for (double& c : p) c = i % 11 == 0 ? std::ldexp(unit(rng), exponent(rng)) : unit(rng) * 1e3;
    if (i % 13 == 0) p[1] = -0.0;
    m.vertices.push_back(ImplicitPoint::explicit_point(p[0], p[1], p[2]));
  }
  m.label_sets = {{}, {0}, {1, 2}, {0, 7, 4294967295u}};
  std::uniform_int_distribution<int> vertex(0, static_cast<int>(vertex_count) - 1);
  for (std::size_t t = 0; t < triangle_count; ++t) {
    m.triangles.push_back({vertex(rng), vertex(rng), vertex(rng)});
    m.source.push_back(static_cast<std::int64_t>(rng() % (std::uint64_t{1} << 40)));
    m.label_set.push_back(static_cast<int>(t % m.label_sets.size()));
  }
  return m;
}

std::string g17(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string coordinates_line(const char* prefix, const ImplicitPoint& p) {
  const std::array<double, 3> d = tritri::to_double(p);
  return prefix + g17(d[0]) + " " + g17(d[1]) + " " + g17(d[2]) + "\n";
}

std::string expected_obj(const OutputMesh& m) {
  std::string s;
  for (const ImplicitPoint& p : m.vertices) s += coordinates_line("v ", p);
  for (const auto& t : m.triangles)
    s += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + "\n";
  return s;
}

std::string expected_off(const OutputMesh& m) {
  std::string s = "OFF\n" + std::to_string(m.vertices.size()) + " " + std::to_string(m.triangles.size()) + " 0\n";
  for (const ImplicitPoint& p : m.vertices) s += coordinates_line("", p);
  for (const auto& t : m.triangles)
    s += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
  return s;
}

std::string expected_provenance(const OutputMesh& m) {
  std::string s = "triangle,source,labels\n";
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    s += std::to_string(t) + "," + std::to_string(m.source[t]) + ",";
    const auto& labels = m.label_sets[m.label_set[t]];
    for (std::size_t k = 0; k < labels.size(); ++k) s += (k ? " " : "") + std::to_string(labels[k]);
    s += "\n";
  }
  return s;
}

// 3 chunks of vertex lines and 5 of triangle lines and more, none of them full at the end.
const OutputMesh& mesh() {
  static const OutputMesh m = large_mesh(20011, 41017);
  return m;
}

TEST(WriteMeshChunks, DefaultFilesAreThoseOfAPlainLoop) {
  tritri_test::TempDir dir;
  for (const char* name : {"m.obj", "m.off"}) {
    SCOPED_TRACE(name);
    write_mesh(dir.path(name), mesh());
    EXPECT_TRUE(file_bytes(dir.path(name)) == (std::string(name) == "m.obj" ? expected_obj(mesh()) : expected_off(mesh())));
    EXPECT_TRUE(file_bytes(dir.path(name) + ".provenance.csv") == expected_provenance(mesh()));
  }
}

TEST(WriteMeshChunks, FilesAreByteIdenticalAtAnyThreadCount) {
  tritri_test::TempDir dir;
  for (const char* name : {"m.obj", "m.off", "m.ply"})
    for (bool exact : {false, true}) {
      if (exact && std::string(name) == "m.ply") continue;
      SCOPED_TRACE(std::string(name) + (exact ? " exact" : ""));
      std::vector<std::string> bytes;
      for (int threads : {1, 2, 4}) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        write_mesh(dir.path(name), mesh(), WriteOptions{.exact = exact});
        bytes.push_back(file_bytes(dir.path(name)) + "|" +
                        (std::string(name) == "m.ply" ? "" : file_bytes(dir.path(name) + ".provenance.csv")));
      }
      EXPECT_GT(bytes[0].size(), 1000000u);
      EXPECT_TRUE(bytes[0] == bytes[1]);
      EXPECT_TRUE(bytes[0] == bytes[2]);
    }
}

TEST(WriteMeshChunks, ExactFilesReadBackExactlyInOrder) {
  tritri_test::TempDir dir;
  for (const char* name : {"m.obj", "m.off"}) {
    SCOPED_TRACE(name);
    write_mesh(dir.path(name), mesh(), WriteOptions{.exact = true});
    const arrangements::ExactMesh r = arrangements::read_exact_mesh(dir.path(name));
    ASSERT_EQ(r.vertices.size(), mesh().vertices.size());
    for (std::size_t i = 0; i < r.vertices.size(); i += 7)
      ASSERT_EQ(r.vertices[i], tritri::to_exact(mesh().vertices[i])) << "vertex " << i;
    EXPECT_EQ(r.triangles, mesh().triangles);
  }
}

}  // namespace
