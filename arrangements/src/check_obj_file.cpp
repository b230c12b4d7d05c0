// Validator for OBJ files (see mesh_file_checks.h), mirroring CGAL::IO::read_OBJ: one
// statement per line, the first token names it.
#include <algorithm>
#include <array>
#include <string>
#include <string_view>

#include "mesh_file_checks.h"

namespace arrangements::detail {
namespace {

// Statements CGAL's OBJ reader accepts and ignores; any other (e.g. "l") makes it fail.
constexpr std::array<std::string_view, 45> kIgnoredStatements = {
    "vt", "vn", "vp", "bevel", "lod", "ctech", "c_interp", "usemap", "usemtl", "stech",
    "d_interp", "mtllib", "shadow_obj", "trace_obj", "o", "g", "s", "p", "cstype", "deg",
    "step", "bmat", "con", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp",
    "end", "surf_1", "q0_1", "q1_1", "curv2d_1", "surf_2", "q0_2", "q1_2", "curv2d_2",
    "bsp", "bzp", "cdc", "cdp", "res"};

bool is_ignored_statement(std::string_view keyword) {
  return std::find(kIgnoredStatements.begin(), kIgnoredStatements.end(), keyword) != kIgnoredStatements.end();
}

std::size_t count_vertex_statements(std::string_view text) {
  std::size_t n = 0;
  TextCursor cursor(text);
  while (!cursor.at_end())
    if (LineTokens(cursor.rest_of_line()).next() == "v") ++n;
  return n;
}

}  // namespace

FileCounts check_obj_file(const std::string& path, const std::string& bytes) {
  const std::size_t total_vertices = count_vertex_statements(bytes);
  if (total_vertices > kMaxIndexCount)
    refuse(InputErrorKind::too_large, path, std::to_string(total_vertices) + " vertices (at most " +
                                                std::to_string(kMaxIndexCount) + " are supported)");
  FileCounts counts;
  TextCursor cursor(bytes);
  while (!cursor.at_end()) {
    const long line = cursor.line();
    LineTokens tokens(strip_comment(cursor.rest_of_line()));
    const std::string_view keyword = tokens.next();
    if (keyword.empty() || is_ignored_statement(keyword)) continue;
    if (keyword == "v") {
      for (int axis = 0; axis < 3; ++axis) {
        const std::string_view token = tokens.next();
        double value;
        if (token.empty())
          refuse_at_line(InputErrorKind::malformed, path, line, "vertex " + std::to_string(counts.vertices + 1) +
                                                                    " has fewer than 3 coordinates");
        switch (parse_real(token, value)) {
          case RealParse::ok: break;
          case RealParse::non_finite:
            refuse_at_line(InputErrorKind::non_finite_coordinate, path, line,
                           "vertex " + std::to_string(counts.vertices + 1) + ": coordinate " + quoted(token) +
                               " is not a finite double");
          case RealParse::not_a_number:
            refuse_at_line(InputErrorKind::malformed, path, line,
                           "vertex " + std::to_string(counts.vertices + 1) + ": coordinate " + quoted(token) +
                               " is not a number");
        }
      }
      ++counts.vertices;
    } else if (keyword == "f") {
      std::size_t corners = 0;
      for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
        // A corner is v, v/t, v/t/n or v//n; only v matters.
        const std::string_view index_text = token.substr(0, token.find('/'));
        long long index;
        if (!parse_integer(index_text, index))
          refuse_at_line(InputErrorKind::malformed, path, line, "face corner " + quoted(token) +
                                                                    " does not start with an integer vertex index");
        if (index == 0)
          refuse_at_line(InputErrorKind::index_out_of_range, path, line,
                         "vertex index 0 is invalid (OBJ indices start at 1)");
        if (index > 0 && static_cast<unsigned long long>(index) > total_vertices)
          refuse_at_line(InputErrorKind::index_out_of_range, path, line,
                         "vertex index " + std::to_string(index) + " out of range (the file has " +
                             std::to_string(total_vertices) + " vertices)");
        if (index < 0 && static_cast<unsigned long long>(-(index + 1)) >= counts.vertices)
          refuse_at_line(InputErrorKind::index_out_of_range, path, line,
                         "relative vertex index " + std::to_string(index) + " out of range (" +
                             std::to_string(counts.vertices) + " vertices defined before this line)");
        ++corners;
      }
      if (corners < 3)
        refuse_at_line(InputErrorKind::too_few_corners, path, line,
                       "face " + std::to_string(counts.faces + 1) + " has " + std::to_string(corners) +
                           " corners (at least 3 are needed)");
      ++counts.faces;
      counts.corners += corners;
    } else if (keyword.front() != '#') {
      refuse_at_line(InputErrorKind::unsupported_variant, path, line,
                     "OBJ statement " + quoted(keyword) + " is not supported (CGAL's OBJ reader refuses it)");
    }
  }
  return counts;
}

}  // namespace arrangements::detail
