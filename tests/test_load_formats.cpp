// Specification of the format details of load_triangle_soup (arrangements/load_triangle_soup.h)
// beyond test_load_triangle_soup.cpp:
// - text files: LF, CRLF and CR line ends, a UTF-8 byte order mark, OBJ line continuation,
//   ASCII STL keywords in any case, lines across the reader's 1 MiB buffer;
// - numbers: correctly rounded like strtod, also subnormals and underflow to zero;
// - PLY: every integer index and count type, both byte orders, elements in any order,
//   unknown elements skipped;
// - messages: bytes that are not printable ASCII are escaped, the line is the file's line.
// Expected values are written by hand from the file contents (or computed by strtod).
#include <gtest/gtest.h>

#include <arrangements/load_triangle_soup.h>
#include "io/triangulate_polygon.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "support/temp_dir.h"

namespace {

using arrangements::InputError;
using arrangements::InputErrorKind;
using arrangements::load_triangle_soup;
using arrangements::Tri;
using arrangements::TriangleSoup;
using arrangements::Vec3;
using tritri_test::bytes_of;
using tritri_test::TempDir;

// Replaces every "\n" of text by eol.
std::string with_line_ends(const std::string& text, const std::string& eol) {
  std::string out;
  for (char c : text) out += c == '\n' ? eol : std::string(1, c);
  return out;
}

// The InputError of loading path (fails the test if it loads).
InputError refusal(const std::string& path) {
  try {
    load_triangle_soup(path);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << path << ": loaded, but must be refused";
  return InputError(InputErrorKind::malformed, "");
}

const std::vector<Vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

const char* kObj = "# c\nv 0 0 0\nv 1 0 0\n\nv 0 1 0\nf 1 2 3\n";
const char* kOff = "OFF\n# c\n3 1 0\n0 0 0\n1 0 0\n\n0 1 0\n3 0 1 2\n";
const char* kStl =
    "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
    "endfacet\nendsolid s\n";
const char* kPly =
    "ply\nformat ascii 1.0\ncomment c\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

TEST(LoadFormats, TextFormatsAcceptLfCrlfAndCrLineEndsAndAByteOrderMark) {
  TempDir dir;
  for (const char* name : {"t.obj", "t.off", "t.stl", "t.ply"}) {
    const std::string ext = std::string(name).substr(2);
    const std::string text = ext == "obj" ? kObj : ext == "off" ? kOff : ext == "stl" ? kStl : kPly;
    for (const std::string eol : {"\n", "\r\n", "\r"})
      for (const std::string bom : {"", "\xEF\xBB\xBF"}) {
        const TriangleSoup s = load_triangle_soup(dir.write(name, bom + with_line_ends(text, eol)));
        EXPECT_EQ(s.vertices, kTriangle) << name;
        EXPECT_EQ(s.triangles, (std::vector<Tri>{{0, 1, 2}})) << name;
      }
  }
}

TEST(LoadFormats, LineNumbersInMessagesCountEveryKindOfLineEnd) {
  TempDir dir;
  // Lines 1-5 end in LF, CRLF, CR, LF CR (two ends: an empty line), then line 6 is bad.
  const std::string path = dir.write("l.obj", "v 0 0 0\nv 1 0 0\r\nv 0 1 0\rf 1 2 3\n\rv 0 x 0\n");
  const InputError e = refusal(path);
  EXPECT_EQ(e.kind, InputErrorKind::malformed);
  EXPECT_NE(std::string(e.what()).find("line 6: vertex 4: coordinate 'x'"), std::string::npos) << e.what();
}

TEST(LoadFormats, ObjBackslashBeforeTheLineEndJoinsTheNextLine) {
  TempDir dir;
  for (const std::string eol : {"\n", "\r\n", "\r"}) {
    const std::string path = dir.write(
        "j.obj", with_line_ends("v 0 0 0\nv 1 \\\n 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 \\\n 3\nf 2 \\\n4\\\n 3\n", eol));
    const TriangleSoup s = load_triangle_soup(path);
    EXPECT_EQ(s.vertices, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}));
    EXPECT_EQ(s.triangles, (std::vector<Tri>{{0, 1, 2}, {1, 3, 2}}));
  }
  // A backslash inside a comment does not join; a joined statement is named by its first
  // line, and the lines after it keep their numbers.
  const std::string comment = dir.write("c.obj", "v 0 0 0 # a \\\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(load_triangle_soup(comment).vertices, kTriangle);
  const InputError joined = refusal(dir.write("e.obj", "v 0 0 0\nv 1 0 \\\n0\nf 1 2 \\\n 3 \\\n 0\nf 1 2 x\n"));
  EXPECT_NE(std::string(joined.what()).find("line 4: vertex index 0"), std::string::npos) << joined.what();
  const InputError after = refusal(dir.write("f.obj", "v 0 0 0\nv 1 0 \\\n0\nv 0 1 0\nf 1 2 3\nf 1 2 x\n"));
  EXPECT_NE(std::string(after.what()).find("line 6: face corner 'x'"), std::string::npos) << after.what();
}

TEST(LoadFormats, AsciiStlKeywordsInAnyCase) {
  TempDir dir;
  const std::string path = dir.write("u.stl",
                                     "SOLID Upper\n FACET NORMAL 0 0 1\n  OUTER LOOP\n   VERTEX 0 0 0\n"
                                     "   Vertex 1 0 0\n   vertex 0 1 0\n  ENDLOOP\n EndFacet\n"
                                     " facet normal 0 0 1\n  outer loop\n   vertex 1 0 0\n   VeRtEx 1 1 0\n"
                                     "   vertex 0 1 0\n  endloop\n endfacet\nEndSolid Upper\n");
  const TriangleSoup s = load_triangle_soup(path);
  EXPECT_EQ(s.vertices, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}));
  EXPECT_EQ(s.triangles, (std::vector<Tri>{{0, 1, 2}, {1, 3, 2}}));
}

// The solid's name is free text to the end of its line (the "solid" and the "endsolid"
// line): keywords in it are not keywords.
TEST(LoadFormats, AsciiStlSolidNamesAreFreeText) {
  TempDir dir;
  const std::string facet =
      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
  for (const std::string begin : {"solid facet", "solid Solid", "solid", "solid solid facet endfacet vertex 1",
                                   "SOLID endsolid", "solid  facet normal 0 0 1 "})
    for (const std::string end : {"endsolid", "endsolid facet", "endsolid Solid", "endsolid solid facet vertex",
                                   "ENDSOLID endsolid"}) {
      const TriangleSoup s = load_triangle_soup(dir.write("n.stl", begin + "\n" + facet + end + "\n"));
      EXPECT_EQ(s.vertices, kTriangle) << begin << " / " << end;
      EXPECT_EQ(s.triangles, (std::vector<Tri>{{0, 1, 2}})) << begin << " / " << end;
    }
  // Two solids, each named on both lines.
  const TriangleSoup two = load_triangle_soup(
      dir.write("t.stl", "solid facet\n" + facet + "endsolid facet\nsolid a\n" + facet + "endsolid a\n"));
  EXPECT_EQ(two.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 1, 2}}));
  // Still refused: a second 'solid' line inside a solid, no 'endsolid'.
  EXPECT_NE(std::string(refusal(dir.write("s.stl", "solid a\n" + facet + "solid b\n")).what())
                .find("line 9: 'solid' before the previous 'endsolid'"),
            std::string::npos);
  EXPECT_NE(std::string(refusal(dir.write("e.stl", "solid endsolid\n" + facet)).what()).find("without 'endsolid'"),
            std::string::npos);
}

TEST(LoadFormats, StlMergesMinusZeroWithZeroKeepingTheFirstAppearance) {
  TempDir dir;
  const std::string path = dir.write("z.stl",
                                     "solid z\nfacet\nvertex -0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendfacet\n"
                                     "facet\nvertex 0 -0.0 0\nvertex 0 1 0\nvertex 1 0 0\nendfacet\nendsolid\n");
  const TriangleSoup s = load_triangle_soup(path);
  ASSERT_EQ(s.vertices.size(), 3u);
  EXPECT_TRUE(std::signbit(s.vertices[0][0]));
  EXPECT_FALSE(std::signbit(s.vertices[0][1]));
  EXPECT_EQ(s.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 2, 1}}));
}

TEST(LoadFormats, DecimalsAreRoundedLikeStrtodAlsoSubnormalsAndUnderflowToZero) {
  TempDir dir;
  const std::vector<std::string> tokens = {"0.1",
                                           "-1e-300",
                                           "4e-320",
                                           "1e-400",
                                           "-1e-400",
                                           "2.4703282292062327e-324",
                                           "2.4703282292062328e-324",
                                           "2.2250738585072011e-308",
                                           "2.2250738585072012e-308",
                                           "1.7976931348623157e308",
                                           "+7",
                                           ".5",
                                           "5.",
                                           "9007199254740993",
                                           "1E2",
                                           "0.30000000000000004441"};
  std::string obj;
  for (const std::string& t : tokens) obj += "v " + t + " 0 0\n";
  obj += "f 1 2 3\n";
  const TriangleSoup s = load_triangle_soup(dir.write("n.obj", obj));
  ASSERT_EQ(s.vertices.size(), tokens.size());
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const double expected = std::strtod(tokens[i].c_str(), nullptr);
    EXPECT_EQ(std::memcmp(&s.vertices[i][0], &expected, sizeof expected), 0)
        << tokens[i] << ": " << s.vertices[i][0] << " vs " << expected;
  }
  // Float coordinates (ASCII PLY) are rounded to float, as strtof does.
  const std::vector<std::string> floats = {"0.1", "1e-45", "7e-46", "1e-50", "3.4028234e38", "1.17549435e-38"};
  std::string ply = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(floats.size()) +
                    "\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
                    "property list uchar int vertex_indices\nend_header\n";
  for (const std::string& t : floats) ply += t + " 0 0\n";
  ply += "3 0 1 2\n";
  const TriangleSoup p = load_triangle_soup(dir.write("f.ply", ply));
  ASSERT_EQ(p.vertices.size(), floats.size());
  for (std::size_t i = 0; i < floats.size(); ++i)
    EXPECT_EQ(p.vertices[i][0], static_cast<double>(std::strtof(floats[i].c_str(), nullptr))) << floats[i];
  // Beyond the range, NaN and infinities are refused.
  for (const char* bad : {"1e309", "-2e308", "nan", "inf", "-Infinity"}) {
    const InputError e = refusal(dir.write("b.obj", std::string("v 0 0 0\nv 1 0 0\nv 0 ") + bad + " 0\nf 1 2 3\n"));
    EXPECT_EQ(e.kind, InputErrorKind::non_finite_coordinate) << bad << ": " << e.what();
  }
}

// A number has at most one sign: "+-1", "-+1", "++1", "--1" are refused in every text
// format, with the file and line, as any other token that is not a number.
TEST(LoadFormats, ANumberHasAtMostOneSign) {
  TempDir dir;
  for (const std::string bad : {"+-1", "-+1", "++1", "--1", "+-0", "+-1e3", "+-inf", "+-nan", "1e+-2"}) {
    const struct {
      const char* name;
      std::string text;
      const char* line;
    } files[] = {
        {"s.obj", "v 0 0 0\nv 1 0 0\nv 0 " + bad + " 0\nf 1 2 3\n", "line 3: vertex 3: coordinate '"},
        {"s.off", "OFF\n3 1 0\n0 0 0\n" + bad + " 0 0\n0 1 0\n3 0 1 2\n", "line 4: vertex 2: coordinate '"},
        {"s.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 " + bad +
                      "\nvertex 0 1 0\nendloop\nendfacet\nendsolid s\n",
         "line 5: facet 1: coordinate '"},
        {"s.ply", std::string("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n") +
                      "property double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n" +
                      "0 0 0\n1 0 0\n0 1 " + bad + "\n3 0 1 2\n",
         "line 12: vertex 3: property 'z' value '"},
    };
    for (const auto& f : files) {
      const InputError e = refusal(dir.write(f.name, f.text));
      EXPECT_EQ(e.kind, InputErrorKind::malformed) << f.name << " " << bad << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find(std::string(f.line) + bad + "' is not a"), std::string::npos)
          << f.name << " " << bad << ": " << e.what();
    }
  }
  // One sign is fine.
  const TriangleSoup s = load_triangle_soup(dir.write("ok.obj", "v +0 -0 +0\nv +1 0 -0\nv 0 +1 0\nf 1 2 3\n"));
  EXPECT_EQ(s.vertices, kTriangle);
}

TEST(LoadFormats, MessagesEscapeBytesThatAreNotPrintableAscii) {
  TempDir dir;
  const InputError statement = refusal(dir.write("s.obj", "v 0 0 0\n\xC3\xA9t\x01 1 2\n"));
  EXPECT_EQ(statement.kind, InputErrorKind::unsupported_variant);
  EXPECT_NE(std::string(statement.what()).find("line 2: OBJ statement '\\xC3\\xA9t\\x01'"), std::string::npos)
      << statement.what();
  const InputError number = refusal(dir.write("n.off", "OFF\n3 1 0\n0 0 0\n1 \xEF\xBB\xBF 0\n0 1 0\n3 0 1 2\n"));
  EXPECT_NE(std::string(number.what()).find("line 4: vertex 2: coordinate '\\xEF\\xBB\\xBF' is not a number"),
            std::string::npos)
      << number.what();
}

TEST(LoadFormats, LinesAcrossTheOneMebibyteBufferAndLongerThanIt) {
  TempDir dir;
  // A CRLF split by the buffer's end must still count as one line end.
  for (const std::size_t pad : {1048576u, 1048577u, 1048578u}) {
    std::string obj = "#" + std::string(pad - 3, 'x') + "\r\n";  // ends at byte pad
    obj += "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\nf 1 2 y\r\n";
    const InputError e = refusal(dir.write("p.obj", obj));
    EXPECT_NE(std::string(e.what()).find("line 6: face corner 'y'"), std::string::npos) << pad << ": " << e.what();
  }
  // A convex face of 200000 corners on one line (about 1.3 MB) and many vertices.
  const int n = 200000;
  std::string obj;
  for (int i = 0; i < n; ++i) obj += "v " + std::to_string(i) + " " + std::to_string(1.0 * i * i) + " 0\n";
  obj += "f";
  for (int i = n; i >= 1; --i) obj += " " + std::to_string(i);
  obj += "\nf 1 2 3\n";
  const TriangleSoup s = load_triangle_soup(dir.write("big.obj", obj));
  EXPECT_EQ(s.vertices.size(), static_cast<std::size_t>(n));
  ASSERT_EQ(s.triangles.size(), static_cast<std::size_t>(n - 2 + 1));
  EXPECT_EQ(s.triangles.back(), (Tri{0, 1, 2}));
  EXPECT_EQ(s.source.back(), n - 2);
}

TEST(LoadFormats, ObjFacesMayNameLaterVerticesAndTheFirstBadLineIsNamed) {
  TempDir dir;
  const TriangleSoup s = load_triangle_soup(dir.write("f.obj", "f 1 2 3 4\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"));
  std::vector<Tri> expected;
  arrangements::triangulate_polygon(s.vertices, std::vector<int>{0, 1, 2, 3}, expected);
  EXPECT_EQ(s.triangles, expected);
  const InputError e =
      refusal(dir.write("g.obj", "f 1 2 3\nf 1 2 3 5\nf 9 2 3\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 8\n"));
  EXPECT_EQ(e.kind, InputErrorKind::index_out_of_range);
  EXPECT_NE(std::string(e.what()).find("line 2: vertex index 5 out of range (the file has 4 vertices)"),
            std::string::npos)
      << e.what();
}

// A binary PLY with the given index and count types; faces before vertices, an unknown
// element with a list between them.
std::string binary_ply(bool big, const char* count_type, const char* index_type, int count_size, int index_size) {
  std::string f = std::string("ply\r\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\r\nelement face 2\r\nproperty list " + count_type + " " + index_type +
                  " vertex_indices\r\nproperty float quality\r\nelement halfedge 1\r\nproperty int source\r\n"
                  "property list uchar double weights\r\nelement vertex 4\r\nproperty double x\r\n"
                  "property float y\r\nproperty double z\r\nend_header\r\n";
  auto integer = [&](long v, int size) {
    if (size == 1) return bytes_of<std::int8_t>(static_cast<std::int8_t>(v), big);
    if (size == 2) return bytes_of<std::int16_t>(static_cast<std::int16_t>(v), big);
    return bytes_of<std::int32_t>(static_cast<std::int32_t>(v), big);
  };
  for (const std::vector<int>& face : std::vector<std::vector<int>>{{0, 1, 2, 3}, {3, 2, 1}}) {
    f += integer(static_cast<long>(face.size()), count_size);
    for (int i : face) f += integer(i, index_size);
    f += bytes_of<float>(NAN, big);  // not a coordinate: skipped
  }
  f +=
      bytes_of<std::int32_t>(-5, big) + bytes_of<std::uint8_t>(2) + bytes_of<double>(1, big) + bytes_of<double>(2, big);
  for (const Vec3& v : std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, -0.25}})
    f += bytes_of<double>(v[0], big) + bytes_of<float>(static_cast<float>(v[1]), big) + bytes_of<double>(v[2], big);
  return f;
}

TEST(LoadFormats, PlyReadsEveryIntegerIndexTypeInBothByteOrdersAndElementsInAnyOrder) {
  TempDir dir;
  struct Types {
    const char* count;
    const char* index;
    int count_size, index_size;
  };
  for (const Types t : {Types{"uchar", "uchar", 1, 1}, Types{"char", "char", 1, 1}, Types{"ushort", "short", 2, 2},
                        Types{"short", "ushort", 2, 2}, Types{"uint8", "int32", 1, 4}, Types{"int", "uint", 4, 4},
                        Types{"uint16", "uint32", 2, 4}})
    for (const bool big : {false, true}) {
      const TriangleSoup s =
          load_triangle_soup(dir.write("t.ply", binary_ply(big, t.count, t.index, t.count_size, t.index_size)));
      EXPECT_EQ(s.vertices, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, -0.25}}))
          << t.count << " " << t.index << " " << big;
      std::vector<Tri> expected;
      arrangements::triangulate_polygon(s.vertices, std::vector<int>{0, 1, 2, 3}, expected);
      expected.push_back({3, 2, 1});
      EXPECT_EQ(s.triangles, expected) << t.count << " " << t.index << " " << big;
    }
}

TEST(LoadFormats, PlyAsciiSkipsNonFiniteValuesOutsideCoordinatesAndNamesTheFileLine) {
  TempDir dir;
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "property float nx\nelement face 1\nproperty list ushort short vertex_index\nend_header\n";
  const TriangleSoup s = load_triangle_soup(dir.write("a.ply", head + "0 0 0 nan\n1 0 0 inf\n0 1 0 1e999\n3 0 1 2\n"));
  EXPECT_EQ(s.vertices, kTriangle);
  const InputError e = refusal(dir.write("b.ply", head + "0 0 0 0\n1 0 0 0\n0 1 0 0\n3 0 1 -2\n"));
  EXPECT_EQ(e.kind, InputErrorKind::index_out_of_range);
  EXPECT_NE(std::string(e.what()).find("line 14: face 1: vertex index -2"), std::string::npos) << e.what();
}

// A file with neither vertices nor faces is a valid empty mesh in every format (what
// write_mesh writes for an empty arrangement, e.g. of degenerate triangles only); one with
// vertices but no faces is still refused (tests/bad_input/*_no_faces.*), and so is an empty
// file where the format has a header.
TEST(LoadFormats, FilesWithoutVerticesAndFacesAreEmptyMeshes) {
  TempDir dir;
  const std::string ply_head = "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                               "property float z\nelement face 0\nproperty list uchar int vertex_indices\n";
  const std::string binary_ply = "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty double x\n"
                                 "property double y\nproperty double z\nelement face 0\n"
                                 "property list uchar int vertex_indices\nend_header\n";
  const struct {
    const char* name;
    std::string text;
  } files[] = {{"a.obj", ""},
               {"b.obj", "# nothing\n\ng group\n"},
               {"c.off", "OFF\n0 0 0\n"},
               {"d.off", "OFF 0 0 0"},
               {"e.ply", ply_head + "end_header\n"},
               {"f.ply", binary_ply},
               {"g.ply", "ply\nformat ascii 1.0\nend_header\n"},
               {"h.stl", "solid empty\nendsolid empty\n"},
               {"i.stl", std::string(80, ' ') + bytes_of<std::uint32_t>(0)}};
  for (const auto& f : files) {
    const std::string path = dir.write(f.name, f.text);
    const TriangleSoup s = load_triangle_soup(path, 3);
    EXPECT_TRUE(s.vertices.empty() && s.triangles.empty() && s.label_set.empty() && s.source.empty()) << f.name;
    EXPECT_EQ(s.label_sets, (std::vector<arrangements::LabelSet>{{3}})) << f.name;
    // Between other files: the labels stay the files' positions.
    const std::string one = dir.write("one.obj", kObj);
    const TriangleSoup all = arrangements::load_triangle_soups({one, path, one});
    EXPECT_EQ(all.triangles, (std::vector<Tri>{{0, 1, 2}, {3, 4, 5}})) << f.name;
    EXPECT_EQ(all.label_set, (std::vector<int>{0, 2})) << f.name;
    EXPECT_EQ(all.source, (std::vector<std::int64_t>{0, 1})) << f.name;
  }
  for (const char* name : {"z.off", "z.ply", "z.stl"}) {
    const InputError e = refusal(dir.write(name, ""));
    EXPECT_EQ(e.kind, InputErrorKind::empty_mesh) << e.what();
    EXPECT_NE(std::string(e.what()).find("the file is empty"), std::string::npos) << e.what();
  }
  const InputError points = refusal(dir.write("p.obj", "v 0 0 0\n"));
  EXPECT_EQ(points.kind, InputErrorKind::empty_mesh) << points.what();
}

TEST(LoadFormats, CountsBeyondIntAreRefusedAsTooLarge) {
  TempDir dir;
  const InputError off = refusal(dir.write("l.off", "OFF\n3000000000 1 0\n0 0 0\n"));
  EXPECT_EQ(off.kind, InputErrorKind::too_large) << off.what();
  const InputError ply = refusal(dir.write("l.ply",
                                           "ply\nformat ascii 1.0\nelement vertex 3000000000\nproperty float x\n"
                                           "property float y\nproperty float z\nelement face 1\n"
                                           "property list uchar int vertex_indices\nend_header\n0 0 0\n"));
  EXPECT_EQ(ply.kind, InputErrorKind::too_large) << ply.what();
}

}  // namespace
