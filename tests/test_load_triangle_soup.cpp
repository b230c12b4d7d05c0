// Specification of load_triangle_soup / load_triangle_soups (arrangements/load_triangle_soup.h):
// - each format reads the file's coordinates exactly and its faces in file order, polygons
//   triangulated by arrangements::triangulate_polygon (n - 2 triangles of its corners),
//   `source` counting the triangles;
// - several files: file i has label i, vertex indices and `source` continue across files;
// - bad input is refused with InputError of the right kind and a message that names the
//   file and the place; corrupted files never crash and never throw anything else;
// - every mesh of the shared collection loads or is refused, and loaded ones have the
//   triangle (and declared vertex) counts of its manifest.
// Expected values are written by hand from the file contents.
#include <gtest/gtest.h>
#include <unistd.h>

#include <arrangements/load_triangle_soup.h>
#include "io/triangulate_polygon.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "support/shared_meshes.h"
#include "support/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using arrangements::InputError;
using arrangements::InputErrorKind;
using arrangements::LabelSet;
using arrangements::load_triangle_soup;
using arrangements::load_triangle_soups;
using arrangements::Tri;
using arrangements::TriangleSoup;
using arrangements::Vec3;

using tritri_test::bytes_of;
using tritri_test::TempDir;

std::string binary_stl(const std::string& header, const std::vector<std::array<float, 9>>& triangles) {
  std::string s = header;
  s.resize(80, ' ');
  s += bytes_of<std::uint32_t>(static_cast<std::uint32_t>(triangles.size()));
  for (const auto& t : triangles) {
    for (int i = 0; i < 3; ++i) s += bytes_of<float>(0.0f);  // normal
    for (float c : t) s += bytes_of<float>(c);
    s += std::string(2, '\0');
  }
  return s;
}

// The faces (corner lists) of a file over its vertices V, triangulated as the loader must:
// each face by triangulate_polygon, in file order.
std::vector<Tri> triangulated(const std::vector<Vec3>& V, const std::vector<std::vector<int>>& faces) {
  std::vector<Tri> out;
  for (const std::vector<int>& f : faces) {
    const std::size_t before = out.size();
    arrangements::triangulate_polygon(V, f, out);
    EXPECT_EQ(out.size() - before, f.size() - 2);
    for (std::size_t t = before; t < out.size(); ++t)
      for (int c : out[t]) EXPECT_NE(std::find(f.begin(), f.end(), c), f.end());
  }
  return out;
}

void expect_well_formed(const TriangleSoup& s) {
  ASSERT_EQ(s.label_set.size(), s.triangles.size());
  ASSERT_EQ(s.source.size(), s.triangles.size());
  for (const Vec3& v : s.vertices)
    for (double c : v) ASSERT_TRUE(std::isfinite(c));
  for (const Tri& t : s.triangles)
    for (int i : t) ASSERT_TRUE(i >= 0 && i < static_cast<int>(s.vertices.size()));
  for (int l : s.label_set) ASSERT_TRUE(l >= 0 && l < static_cast<int>(s.label_sets.size()));
}

// ---- good input -----------------------------------------------------------------------

TEST(LoadTriangleSoup, ReadsObjCoordinatesExactlyWithTheGivenLabel) {
  TempDir dir;
  const std::string path = dir.write("t.obj", "v 0 0 0\nv 0.1 2 3\nv -1e-300 4e-320 5e300\nf 1 2 3\n");
  const TriangleSoup s = load_triangle_soup(path, 7);
  EXPECT_EQ(s.vertices, (std::vector<Vec3>{{0, 0, 0}, {0.1, 2, 3}, {-1e-300, 4e-320, 5e300}}));
  EXPECT_EQ(s.triangles, (std::vector<Tri>{{0, 1, 2}}));
  EXPECT_EQ(s.label_set, (std::vector<int>{0}));
  EXPECT_EQ(s.label_sets, (std::vector<LabelSet>{{7}}));
  EXPECT_EQ(s.source, (std::vector<std::int64_t>{0}));
}

TEST(LoadTriangleSoup, TriangulatesPolygonsWithTriangulatePolygonInFileOrder) {
  TempDir dir;
  const std::string path =
      dir.write("p.obj", "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nf 1 2 3 4 5\nf 5 4 3\nf 2 3 4 1\n");
  const TriangleSoup s = load_triangle_soup(path);
  EXPECT_EQ(s.triangles, triangulated(s.vertices, {{0, 1, 2, 3, 4}, {4, 3, 2}, {1, 2, 3, 0}}));
  EXPECT_EQ(s.triangles[3], (Tri{4, 3, 2}));  // a triangle stays as it is
  EXPECT_EQ(s.source, (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(s.label_set, (std::vector<int>(6, 0)));
}

TEST(LoadTriangleSoup, ObjAcceptsSlashCornersRelativeIndicesTabsCommentsAndIgnoredStatements) {
  TempDir dir;
  const std::string path = dir.write("c.obj",
                                     "# comment\r\n"
                                     "mtllib x.mtl\n"
                                     "o thing\n"
                                     "f 1 2 3\n"  // forward references are allowed
                                     "v 0 0 0\n"
                                     "vt 0 0\n"
                                     "vn 0 0 1\n"
                                     "v 1 0 0\r\n"
                                     "v\t0\t1\t0\n"
                                     "g group\n"
                                     "usemtl m\n"
                                     "s 1\n"
                                     "f 1/1/1 2/1/1 3/1/1\n"
                                     "f\t-3//1\t-2//1\t-1//1  # relative to the 3 vertices so far\n"
                                     "v 1 1 0\n"
                                     "f 3/1 2/1 4/1 # another\n");
  const TriangleSoup s = load_triangle_soup(path);
  EXPECT_EQ(s.vertices, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}));
  EXPECT_EQ(s.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 1, 2}, {0, 1, 2}, {2, 1, 3}}));
}

TEST(LoadTriangleSoup, ReadsOffWithCommentsBlankLinesAndPolygons) {
  TempDir dir;
  const std::string path = dir.write("q.off",
                                     "OFF\n# comment\n4 2 0\n"
                                     "0 0 0\n1 0 0 # trailing comment\n\n1 1 0\n0 1 0\n"
                                     "4 0 1 2 3\n3 3 2 1\n");
  const TriangleSoup s = load_triangle_soup(path);
  EXPECT_EQ(s.vertices, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
  EXPECT_EQ(s.triangles, triangulated(s.vertices, {{0, 1, 2, 3}, {3, 2, 1}}));
  EXPECT_EQ(s.source, (std::vector<std::int64_t>{0, 1, 2}));
}

TEST(LoadTriangleSoup, ReadsColouredAndNormalOffVariants) {
  TempDir dir;
  // COFF: RGB or RGBA, integers or fractions; records without colours only before the first
  // record with colours.
  const std::string coff = dir.write("c.off",
                                     "COFF\n4 2 0\n0 0 0\n1 0 0 0 255 0 255\n0 1 0 0 0 255\n1 1 0 1 2 3\n"
                                     "3 0 1 2 0.5 0.25 1\n3 3 2 1 9 9 9\n");
  EXPECT_EQ(load_triangle_soup(coff).triangles, (std::vector<Tri>{{0, 1, 2}, {3, 2, 1}}));
  const std::string colours_stop = dir.write("d.off", "COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0\n0 1 0 0 0 255\n3 0 1 2\n");
  EXPECT_THROW(load_triangle_soup(colours_stop), InputError);
  const std::string noff = dir.write("n.off", "NOFF 3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 2 1 0\n");
  const TriangleSoup s = load_triangle_soup(noff);
  EXPECT_EQ(s.vertices, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  EXPECT_EQ(s.triangles, (std::vector<Tri>{{2, 1, 0}}));
}

TEST(LoadTriangleSoup, ReadsAsciiStlMergingEqualCornersInFirstAppearanceOrder) {
  TempDir dir;
  const std::string path = dir.write("a.stl",
                                     "solid two\n"
                                     " facet normal 0 0 1\n  outer loop\n"
                                     "   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n"
                                     "  endloop\n endfacet\n"
                                     " facet normal 0 0 1\n  outer loop\n"
                                     "   vertex 1 0 0\n   vertex 1 1 0.5\n   vertex 0 1 0\n"
                                     "  endloop\n endfacet\n"
                                     "endsolid two\n");
  const TriangleSoup s = load_triangle_soup(path);
  EXPECT_EQ(s.vertices, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.5}}));
  EXPECT_EQ(s.triangles, (std::vector<Tri>{{0, 1, 2}, {1, 3, 2}}));
  EXPECT_EQ(s.source, (std::vector<std::int64_t>{0, 1}));
}

TEST(LoadTriangleSoup, ReadsBinaryStlEvenWhenItsHeaderBeginsWithSolid) {
  TempDir dir;
  const std::vector<std::array<float, 9>> tris = {{0.1f, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 0, 0, 0, 1, 0, 0, 0, -3.5f}};
  for (const std::string header : {"solid but binary", "plain binary header"}) {
    const std::string path = dir.write("b.stl", binary_stl(header, tris));
    const TriangleSoup s = load_triangle_soup(path);
    EXPECT_EQ(s.vertices, (std::vector<Vec3>{{static_cast<double>(0.1f), 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -3.5}}))
        << header;
    EXPECT_EQ(s.triangles, (std::vector<Tri>{{0, 1, 2}, {1, 2, 3}})) << header;
  }
}

TEST(LoadTriangleSoup, ReadsAsciiPlyWithExtraPropertiesAndElements) {
  TempDir dir;
  const std::string path = dir.write("a.ply",
                                     "ply\nformat ascii 1.0\ncomment hand-written\n"
                                     "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                                     "property float nx\nproperty uchar red\n"
                                     "element face 2\nproperty list uchar int vertex_indices\nproperty int flags\n"
                                     "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
                                     "end_header\n"
                                     "0 0 0 1 255\n0.5 0 0 1 0\n0.5 0.5 0 1 7\n0 0.5 -0.25 1 9\n"
                                     "4 0 1 2 3 17\n3 3 2 1 0\n"
                                     "0 1\n");
  const TriangleSoup s = load_triangle_soup(path);
  EXPECT_EQ(s.vertices, (std::vector<Vec3>{{0, 0, 0}, {0.5, 0, 0}, {0.5, 0.5, 0}, {0, 0.5, -0.25}}));
  EXPECT_EQ(s.triangles, triangulated(s.vertices, {{0, 1, 2, 3}, {3, 2, 1}}));
}

TEST(LoadTriangleSoup, ReadsBinaryPlyInBothByteOrders) {
  TempDir dir;
  for (const bool big : {false, true}) {
    std::string f = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
                    "element face 1\nproperty list uchar uint vertex_indices\nend_header\n";
    for (double c : {0.1, 0.0, 0.0, 1.0, 1e-310, 0.0, 0.0, 1.0, -2.0}) f += bytes_of<double>(c, big);
    f += bytes_of<std::uint8_t>(3);
    for (std::uint32_t i : {2u, 0u, 1u}) f += bytes_of<std::uint32_t>(i, big);
    const TriangleSoup s = load_triangle_soup(dir.write("b.ply", f));
    EXPECT_EQ(s.vertices, (std::vector<Vec3>{{0.1, 0, 0}, {1, 1e-310, 0}, {0, 1, -2}})) << big;
    EXPECT_EQ(s.triangles, (std::vector<Tri>{{2, 0, 1}})) << big;
  }
}

TEST(LoadTriangleSoup, ExtensionDecidesTheFormatInAnyCase) {
  TempDir dir;
  EXPECT_EQ(load_triangle_soup(dir.write("x.OBJ", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")).triangles.size(), 1u);
  EXPECT_EQ(load_triangle_soup(dir.write("x.Off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")).triangles.size(), 1u);
  EXPECT_EQ(load_triangle_soup(dir.write("x.StL", binary_stl("", {{0, 0, 0, 1, 0, 0, 0, 1, 0}}))).triangles.size(), 1u);
  EXPECT_EQ(load_triangle_soup(dir.write("x.PLY",
                                         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                         "property float y\nproperty float z\nelement face 1\n"
                                         "property list uchar int vertex_index\nend_header\n"
                                         "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"))
                .triangles.size(),
            1u);
  // An OBJ file named .off is read as OFF, and refused.
  EXPECT_THROW(load_triangle_soup(dir.write("obj.off", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")), InputError);
}

TEST(LoadTriangleSoups, LabelsFileIWithIAndContinuesIndicesAndSourceAcrossFiles) {
  TempDir dir;
  const std::string a = dir.write("a.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  const std::string b = dir.write("b.off", "OFF\n3 1 0\n0 0 1\n1 0 1\n0 1 1\n3 0 1 2\n");
  const TriangleSoup s = load_triangle_soups({a, b, a});
  EXPECT_EQ(s.vertices.size(), 11u);
  EXPECT_EQ(s.vertices[4], (Vec3{0, 0, 1}));
  const std::vector<Tri> square = triangulated({s.vertices.begin(), s.vertices.begin() + 4}, {{0, 1, 2, 3}});
  ASSERT_EQ(square.size(), 2u);
  const auto shifted = [](Tri t, int k) { return Tri{t[0] + k, t[1] + k, t[2] + k}; };
  EXPECT_EQ(s.triangles,
            (std::vector<Tri>{square[0], square[1], {4, 5, 6}, shifted(square[0], 7), shifted(square[1], 7)}));
  EXPECT_EQ(s.label_set, (std::vector<int>{0, 0, 1, 2, 2}));
  EXPECT_EQ(s.label_sets, (std::vector<LabelSet>{{0}, {1}, {2}}));
  EXPECT_EQ(s.source, (std::vector<std::int64_t>{0, 1, 2, 3, 4}));
}

// ---- bad input ------------------------------------------------------------------------

struct BadFile {
  const char* name;
  InputErrorKind kind;
  const char* message_part;  // must appear in what()
};

// tests/bad_input: one file per way of being wrong (see its README.md).
const BadFile kBadFiles[] = {
    {"unknown_extension.xyz", InputErrorKind::unknown_format, "unknown file extension '.xyz'"},
    {"no_extension", InputErrorKind::unknown_format, "no file extension"},
    {"empty_file.off", InputErrorKind::empty_mesh, "the file is empty"},  // an empty .obj is an empty mesh
    {"obj_nan_coordinate.obj", InputErrorKind::non_finite_coordinate, "line 3: vertex 2: coordinate 'nan'"},
    {"obj_inf_coordinate.obj", InputErrorKind::non_finite_coordinate, "line 3: vertex 3: coordinate '-inf'"},
    {"obj_overflowing_coordinate.obj", InputErrorKind::non_finite_coordinate, "line 2: vertex 2: coordinate '1e400'"},
    {"obj_index_out_of_range.obj", InputErrorKind::index_out_of_range,
     "line 5: vertex index 57 out of range (the file has 3 vertices)"},
    {"obj_index_zero.obj", InputErrorKind::index_out_of_range, "line 4: vertex index 0 is invalid"},
    {"obj_relative_index_out_of_range.obj", InputErrorKind::index_out_of_range,
     "line 3: relative vertex index -3 out of range (2 vertices defined before this line)"},
    {"obj_two_corner_face.obj", InputErrorKind::too_few_corners, "line 5: face 2 has 2 corners"},
    {"obj_no_faces.obj", InputErrorKind::empty_mesh, "no faces"},
    {"obj_line_element.obj", InputErrorKind::unsupported_variant, "line 4: OBJ statement 'l'"},
    {"obj_not_a_number.obj", InputErrorKind::malformed, "line 2: vertex 2: coordinate 'abc' is not a number"},
    {"obj_short_vertex.obj", InputErrorKind::malformed, "line 2: vertex 2 has fewer than 3 coordinates"},
    {"obj_bad_corner.obj", InputErrorKind::malformed, "line 4: face corner 'x3'"},
    {"off_no_header.off", InputErrorKind::malformed, "line 1: not an OFF file"},
    {"off_truncated.off", InputErrorKind::malformed, "the file ends after 3 of 4 vertices"},
    {"off_nan_coordinate.off", InputErrorKind::non_finite_coordinate, "line 4: vertex 2: coordinate 'NaN'"},
    {"off_index_out_of_range.off", InputErrorKind::index_out_of_range,
     "line 6: face 1: vertex index 3 out of range (the file has 3 vertices)"},
    {"off_huge_corner_count.off", InputErrorKind::malformed, "line 6: face 1 declares 1000000000000 corners"},
    {"off_negative_corner_count.off", InputErrorKind::malformed, "line 6: face 1: the corner count"},
    {"off_binary.off", InputErrorKind::unsupported_variant, "binary OFF"},
    {"off_missing_edge_count.off", InputErrorKind::malformed, "line 2: the OFF header needs"},
    {"off_two_colour_entries.off", InputErrorKind::unsupported_variant, "line 3: vertex 1 has 2 colour entries"},
    {"off_no_faces.off", InputErrorKind::empty_mesh, "no faces"},
    {"off_texture_variant.off", InputErrorKind::unsupported_variant, "'STOFF' files are not supported"},
    {"off_two_corner_face.off", InputErrorKind::too_few_corners, "line 6: face 1 has 2 corners"},
    {"stl_ascii_nan.stl", InputErrorKind::non_finite_coordinate, "line 12: facet 2: coordinate 'nan'"},
    {"stl_ascii_four_vertices.stl", InputErrorKind::malformed, "line 7: facet 1 has more than 3 vertices"},
    {"stl_ascii_no_endsolid.stl", InputErrorKind::malformed, "without 'endsolid'"},
    {"stl_ascii_bad_number.stl", InputErrorKind::malformed, "line 6: facet 1: coordinate '1,5' is not a number"},
    {"stl_unknown_content.stl", InputErrorKind::malformed, "neither an ASCII STL"},
    {"stl_too_short.stl", InputErrorKind::malformed, "too short for a binary STL (6 bytes"},
    {"stl_truncated_binary.stl", InputErrorKind::malformed, "declaring 2 triangles needs 184 bytes, the file has 134"},
    {"stl_binary_nan.stl", InputErrorKind::non_finite_coordinate, "triangle 2, corner 2"},
    {"ply_no_end_header.ply", InputErrorKind::malformed, "no 'end_header'"},
    {"ply_int_coordinates.ply", InputErrorKind::unsupported_variant, "needs a float or double property 'x'"},
    {"ply_ascii_nan.ply", InputErrorKind::non_finite_coordinate, "line 12: vertex 3: property 'y' value 'nan'"},
    {"ply_index_out_of_range.ply", InputErrorKind::index_out_of_range, "line 13: face 1: vertex index 3 out of range"},
    {"ply_property_before_element.ply", InputErrorKind::malformed, "line 3: property before any element"},
    {"ply_no_faces.ply", InputErrorKind::empty_mesh, "no faces"},
    {"ply_element_without_properties.ply", InputErrorKind::malformed, "element 'junk' has items but no properties"},
    {"ply_truncated_ascii.ply", InputErrorKind::malformed, "the file ends inside vertex 3"},
    {"ply_huge_list_length.ply", InputErrorKind::malformed, "face 1: list length 4294967295"},
    {"ply_binary_inf.ply", InputErrorKind::non_finite_coordinate, "vertex 2: coordinate 'y' is not finite"},
    {"ply_binary_negative_index.ply", InputErrorKind::index_out_of_range, "face 1: vertex index -1 out of range"},
};

TEST(LoadTriangleSoup, RefusesEachBadInputFileWithItsKindAndAMessageNamingFileAndPlace) {
  std::size_t files_in_dir = 0;
  for (const auto& entry : fs::directory_iterator(tritri_test::bad_input_dir()))
    if (entry.path().filename() != "README.md") ++files_in_dir;
  EXPECT_EQ(files_in_dir, std::size(kBadFiles)) << "every file in tests/bad_input needs a row in kBadFiles";
  for (const BadFile& bad : kBadFiles) {
    const std::string path = (tritri_test::bad_input_dir() / bad.name).string();
    try {
      load_triangle_soup(path);
      ADD_FAILURE() << bad.name << ": loaded, but must be refused";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.kind, bad.kind) << what;
      EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;
      EXPECT_NE(what.find(bad.message_part), std::string::npos) << what << "\n  expected: " << bad.message_part;
    }
  }
}

TEST(LoadTriangleSoup, RefusesMissingFilesAndDirectoriesAsUnreadable) {
  TempDir dir;
  fs::create_directories(dir.path() / "folder.obj");
  for (const fs::path& p : {dir.path() / "missing.obj", dir.path() / "folder.obj"}) {
    try {
      load_triangle_soup(p.string());
      ADD_FAILURE() << p;
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind, InputErrorKind::unreadable_file) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind(p.string() + ": ", 0), 0u) << e.what();
    }
  }
  EXPECT_THROW(load_triangle_soups({(dir.path() / "missing.stl").string()}), InputError);
}

// Loading either succeeds with a well-formed soup or throws InputError.
void expect_loads_or_is_refused(const std::string& path, const std::string& context) {
  try {
    const TriangleSoup s = load_triangle_soup(path);
    expect_well_formed(s);
  } catch (const InputError&) {
  } catch (const std::exception& e) {
    ADD_FAILURE() << context << ": threw a non-InputError: " << e.what();
  }
}

TEST(LoadTriangleSoup, EveryTruncationAndByteCorruptionOfValidFilesLoadsOrIsRefused) {
  TempDir dir;
  std::string ply_binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list int uint vertex_indices\nend_header\n";
  for (float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 1.f, 1.f, 1.f}) ply_binary += bytes_of<float>(c);
  for (std::uint32_t v : {3u, 0u, 1u, 2u, 3u, 1u, 3u, 2u}) ply_binary += bytes_of<std::uint32_t>(v);
  const std::vector<std::pair<std::string, std::string>> valid = {
      {"v.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\nf 1 2 3\nf -1 -3 -2\nf 1/1 2/2 4/4 3/3\n"},
      {"v.off", "COFF\n4 2 0\n0 0 0 1 0 0\n1 0 0 1 0 0\n0 1 0 1 0 0\n1 1 1 1 0 0\n3 0 1 2\n4 0 1 3 2 0 0 1\n"},
      {"v.stl",
       "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
       "endfacet\nendsolid s\n"},
      {"b.stl", binary_stl("solid", {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 1, 1, 1, 0, 0, 0, 1, 0}})},
      {"v.ply",
       "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n"
       "3 0 1 2\n3 3 1 2\n"},
      {"b.ply", ply_binary},
  };
  std::mt19937 rng(12345);
  const char replacements[] = {'\0', '\n', ' ', '-', '9', '#', '/', 'e', '.', 'x', '\xff', 'n'};
  for (const auto& [name, bytes] : valid) {
    ASSERT_NO_THROW(load_triangle_soup(dir.write(name, bytes))) << name;
    for (std::size_t n = 0; n < bytes.size(); ++n)
      expect_loads_or_is_refused(dir.write(name, bytes.substr(0, n)), name + " truncated to " + std::to_string(n));
    for (int trial = 0; trial < 300; ++trial) {
      std::string corrupted = bytes;
      const int edits = 1 + static_cast<int>(rng() % 3);
      for (int e = 0; e < edits; ++e) {
        const std::size_t at = rng() % corrupted.size();
        if (rng() % 2)
          corrupted[at] = replacements[rng() % sizeof replacements];
        else
          corrupted[at] = static_cast<char>(rng() & 0xff);
      }
      expect_loads_or_is_refused(dir.write(name, corrupted), name + " corruption " + std::to_string(trial));
    }
  }
}

// ---- the shared mesh collection ----------------------------------------------------------

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

struct ManifestRow {
  std::string format;
  std::string vertices, triangles;
};

std::map<std::string, ManifestRow> read_manifest(const fs::path& csv) {
  std::map<std::string, ManifestRow> rows;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split_csv_line(line);
  auto column = [&header](const char* name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t file = column("file"), format = column("format"), vertices = column("vertices"),
                    triangles = column("triangles");
  while (std::getline(in, line)) {
    const std::vector<std::string> f = split_csv_line(line);
    if (f.size() < header.size()) continue;
    rows[f[file]] = {f[format], f[vertices], f[triangles]};
  }
  return rows;
}

bool is_mesh_extension(std::string ext) {
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".obj" || ext == ".off" || ext == ".stl" || ext == ".ply";
}

// The manifest's `triangles` is the STL facet count or the OBJ / OFF n - 2 per face count,
// so it is ours for every mesh format; `vertices` is the declared count for OBJ / OFF / PLY
// (for STL it counts distinct positions, which the loader also merges, but -0.0 / 0.0 may
// differ).
TEST(SharedMeshes, EveryMeshFileLoadsOrIsRefusedWithInputErrorAndMatchesTheManifest) {
  const fs::path root = tritri_test::shared_meshes_dir();
  TRITRI_REQUIRE_DATA(root);
  const std::map<std::string, ManifestRow> manifest = read_manifest(root / "manifest.csv");
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.is_regular_file() && is_mesh_extension(entry.path().extension().string())) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty());

  std::map<std::string, std::vector<std::string>> refused;  // by kind
  std::size_t loaded = 0, compared = 0;
  for (const fs::path& file : files) {
    const std::string relative = fs::relative(file, root).generic_string();
    try {
      const TriangleSoup s = load_triangle_soup(file.string());
      expect_well_formed(s);
      ++loaded;
      const auto row = manifest.find(relative);
      if (row == manifest.end()) continue;
      ++compared;
      EXPECT_EQ(std::to_string(s.triangles.size()), row->second.triangles) << relative;
      if (row->second.format.rfind("stl", 0) != 0) {
        EXPECT_EQ(std::to_string(s.vertices.size()), row->second.vertices) << relative;
      }
    } catch (const InputError& e) {
      refused[arrangements::to_string(e.kind)].push_back(e.what());
    } catch (const std::exception& e) {
      ADD_FAILURE() << relative << ": threw a non-InputError: " << e.what();
    }
  }
  std::cout << "[ shared meshes ] " << files.size() << " files: " << loaded << " loaded (" << compared
            << " compared with the manifest), " << files.size() - loaded << " refused\n";
  for (const auto& [kind, messages] : refused) {
    std::cout << "[ refused ] " << kind << ": " << messages.size() << "\n";
    for (const std::string& m : messages) std::cout << "    " << m << "\n";
  }
}

}  // namespace
