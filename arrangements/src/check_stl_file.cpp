// Validator for STL files (see mesh_file_checks.h).
//
// CGAL::IO::read_STL guesses the encoding from the first word and, when one parse fails,
// runs the other on the same output vectors (a partial ASCII parse followed by a binary
// one gives a wrong mesh), and its binary parser puts NaN corners into a std::map (no
// strict weak order). So the encoding is decided here from the file size, binary corners
// are checked for finiteness, and the loader calls the matching half of CGAL's reader.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "mesh_file_checks.h"

namespace arrangements::detail {
namespace {

constexpr std::size_t kBinaryHeaderBytes = 84;   // 80-byte comment + uint32 triangle count
constexpr std::size_t kBinaryTriangleBytes = 50;  // normal, 3 corners (12 floats), uint16

std::uint32_t read_le_uint32(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

float read_le_float(const std::string& bytes, std::size_t at) {
  const std::uint32_t bits = read_le_uint32(bytes, at);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

bool starts_with_solid(const std::string& bytes) {
  std::size_t i = 0;
  while (i < bytes.size() && is_space(bytes[i])) ++i;
  return bytes.compare(i, 5, "solid") == 0;
}

FileCounts check_binary(const std::string& path, const std::string& bytes) {
  const std::size_t n = read_le_uint32(bytes, 80);
  if (n > kMaxIndexCount)
    refuse(InputErrorKind::too_large, path, std::to_string(n) + " triangles (at most " +
                                                std::to_string(kMaxIndexCount) + " are supported)");
  for (std::size_t t = 0; t < n; ++t) {
    const std::size_t corners = kBinaryHeaderBytes + t * kBinaryTriangleBytes + 12;
    for (int k = 0; k < 9; ++k)
      if (!std::isfinite(read_le_float(bytes, corners + 4 * k)))
        refuse(InputErrorKind::non_finite_coordinate, path,
               "triangle " + std::to_string(t + 1) + ", corner " + std::to_string(k / 3 + 1) +
                   ": a coordinate is not finite (" + std::to_string(read_le_float(bytes, corners + 4 * k)) + ")");
  }
  FileCounts counts;
  counts.faces = n;
  counts.corners = 3 * n;
  return counts;
}

// The token walk of CGAL's parse_ASCII_STL: outside a facet only "solid", "facet" and
// "endsolid" matter; inside, "vertex" is followed by three numbers and "endfacet" ends it.
FileCounts check_ascii(const std::string& path, const std::string& bytes) {
  TextCursor cursor(bytes);
  FileCounts counts;
  bool in_solid = false, solid_seen = false;
  for (std::string_view token = cursor.token(); !token.empty(); token = cursor.token()) {
    if (token == "solid") {
      if (in_solid)
        refuse_at_line(InputErrorKind::malformed, path, cursor.line(), "'solid' before the previous 'endsolid'");
      in_solid = true;
    } else if (token == "endsolid") {
      in_solid = false;
      solid_seen = true;
    } else if (token == "facet") {
      const long facet_line = cursor.line();
      const std::string what = "facet " + std::to_string(counts.faces + 1);
      int corners = 0;
      for (token = cursor.token(); token != "endfacet"; token = cursor.token()) {
        if (token.empty())
          refuse_at_line(InputErrorKind::malformed, path, facet_line, what + " has no 'endfacet'");
        if (token != "vertex") continue;
        if (++corners > 3)
          refuse_at_line(InputErrorKind::malformed, path, cursor.line(), what + " has more than 3 vertices");
        for (int axis = 0; axis < 3; ++axis) {
          const std::string_view number = cursor.token();
          double v;
          switch (parse_real(number, v)) {
            case RealParse::ok: break;
            case RealParse::non_finite:
              refuse_at_line(InputErrorKind::non_finite_coordinate, path, cursor.line(),
                             what + ": coordinate " + quoted(number) + " is not a finite double");
            case RealParse::not_a_number:
              refuse_at_line(InputErrorKind::malformed, path, cursor.line(),
                             what + ": coordinate " + quoted(number) + " is not a number");
          }
        }
      }
      if (corners != 3)
        refuse_at_line(InputErrorKind::too_few_corners, path, cursor.line(),
                       what + " has " + std::to_string(corners) + " vertices (3 are needed)");
      ++counts.faces;
      counts.corners += 3;
    }
  }
  if (in_solid) refuse(InputErrorKind::malformed, path, "the file ends without 'endsolid'");
  if (!solid_seen) refuse(InputErrorKind::malformed, path, "no 'solid' ... 'endsolid' block");
  return counts;
}

}  // namespace

StlEncoding stl_encoding(const std::string& path, const std::string& bytes) {
  // An ASCII STL has no NUL byte; binary headers that begin with "solid" are common.
  const bool ascii = starts_with_solid(bytes) && bytes.find('\0') == std::string::npos;
  if (bytes.size() >= kBinaryHeaderBytes) {
    const std::uint64_t n = read_le_uint32(bytes, 80);
    const std::uint64_t expected = kBinaryHeaderBytes + n * kBinaryTriangleBytes;
    if (expected == bytes.size()) return StlEncoding::binary;
    if (ascii) return StlEncoding::ascii;
    refuse(InputErrorKind::malformed, path,
           "neither an ASCII STL (which begins with 'solid') nor a binary STL of the right size: a binary header "
           "declaring " + std::to_string(n) + " triangles needs " + std::to_string(expected) + " bytes, the file has " +
               std::to_string(bytes.size()));
  }
  if (ascii) return StlEncoding::ascii;
  refuse(InputErrorKind::malformed, path,
         "not an ASCII STL (which begins with 'solid') and too short for a binary STL (" +
             std::to_string(bytes.size()) + " bytes, the binary header alone has 84)");
}

FileCounts check_stl_file(const std::string& path, const std::string& bytes, StlEncoding encoding) {
  return encoding == StlEncoding::binary ? check_binary(path, bytes) : check_ascii(path, bytes);
}

}  // namespace arrangements::detail
