// Validator for OFF files (see mesh_file_checks.h), mirroring CGAL::IO::read_OFF and its
// File_scanner_OFF: a header (keyword, then "V F E"), then one vertex and one face per
// record, where a record is the rest of a line after blank and '#' comment lines.
//
// CGAL's scanner trusts the file: a negative or huge corner count sizes a vector, colour
// entries are read past the end of a short record, and the texture / homogeneous variants
// index without bounds. So only the variants below pass, each record checked in full.
#include <string>
#include <string_view>
#include <vector>

#include "mesh_file_checks.h"

namespace arrangements::detail {
namespace {

struct OffHeader {
  bool colors = false;   // C: colours may follow a vertex's coordinates / a face's indices
  bool normals = false;  // N: three normal coordinates follow each vertex's coordinates
  long long vertices = 0;
  long long faces = 0;
};

std::vector<std::string_view> split_record(std::string_view record) {
  std::vector<std::string_view> out;
  LineTokens tokens(strip_comment(record));
  for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next()) out.push_back(t);
  return out;
}

bool is_alnum(char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

OffHeader read_header(const std::string& path, TextCursor& cursor) {
  cursor.skip_whitespace_and_comments();
  const long line = cursor.line();
  const std::string_view keyword = cursor.take_while(is_alnum);
  if (keyword.empty() || (!cursor.at_end() && !is_space(cursor.peek())))
    refuse_at_line(InputErrorKind::malformed, path, line, "no OFF header keyword");
  // CGAL's keyword grammar: [ST][C][N][4][n](OFF|SKEL).
  std::string_view rest = keyword;
  auto take = [&rest](std::string_view prefix) {
    if (rest.substr(0, prefix.size()) != prefix || rest.size() == prefix.size()) return false;
    rest.remove_prefix(prefix.size());
    return true;
  };
  const bool textures = take("ST");
  OffHeader h;
  h.colors = take("C");
  h.normals = take("N");
  const bool homogeneous = take("4");
  const bool dimension = take("n");
  if (rest != "OFF" && rest != "SKEL")
    refuse_at_line(InputErrorKind::malformed, path, line, "not an OFF file (header keyword " + quoted(keyword) + ")");
  if (rest == "SKEL" || textures || homogeneous || dimension)
    refuse_at_line(InputErrorKind::unsupported_variant, path, line,
                   quoted(keyword) + " files are not supported (only OFF, COFF, NOFF, CNOFF)");
  cursor.skip_whitespace_and_comments();
  const long counts_line = cursor.line();
  const std::vector<std::string_view> counts = split_record(cursor.rest_of_line());
  if (!counts.empty() && counts[0] == "BINARY")
    refuse_at_line(InputErrorKind::unsupported_variant, path, counts_line, "binary OFF files are not supported");
  int edges;
  if (counts.size() < 3)
    refuse_at_line(InputErrorKind::malformed, path, counts_line,
                   "the OFF header needs the vertex, face and edge counts on one line");
  if (counts.size() > 3)
    refuse_at_line(InputErrorKind::malformed, path, counts_line, "unexpected " + quoted(counts[3]) +
                                                                     " after the vertex, face and edge counts");
  if (!parse_integer(counts[0], h.vertices) || h.vertices < 0 || !parse_integer(counts[1], h.faces) ||
      h.faces < 0 || !parse_integer(counts[2], edges))
    refuse_at_line(InputErrorKind::malformed, path, counts_line,
                   "the vertex, face and edge counts must be integers (vertex and face counts >= 0)");
  if (static_cast<unsigned long long>(h.vertices) > kMaxIndexCount ||
      static_cast<unsigned long long>(h.faces) > kMaxIndexCount)
    refuse_at_line(InputErrorKind::too_large, path, counts_line,
                   "more than " + std::to_string(kMaxIndexCount) + " vertices or faces");
  return h;
}

// Colour entries of one record: none, RGB or RGBA, as integers in [0, 255] or as reals in
// [0, 1] (what CGAL converts to 8 bits without overflow). Once a record of a kind (vertex
// or face) has colours, CGAL reads colours from every later record of that kind.
void check_colors(const std::string& path, long line, const std::vector<std::string_view>& entries,
                  std::size_t first, bool& colors_seen, const std::string& what) {
  const int n = static_cast<int>(entries.size() - first);
  if (n != 0 && n != 3 && n != 4)
    refuse_at_line(InputErrorKind::unsupported_variant, path, line,
                   what + " has " + std::to_string(n) + " colour entries (supported: 0, 3 or 4)");
  if (colors_seen && n == 0)
    refuse_at_line(InputErrorKind::unsupported_variant, path, line,
                   what + " has no colour entries, but an earlier record has (CGAL needs them from then on)");
  colors_seen = colors_seen || n > 0;
  bool all_integers = true;
  double rgb[3] = {0, 0, 0};
  for (int i = 0; i < n; ++i) {
    double v;
    if (parse_real(entries[first + i], v) != RealParse::ok || v < 0 || v > 255)
      refuse_at_line(InputErrorKind::malformed, path, line,
                     what + ": colour entry " + quoted(entries[first + i]) + " is not a number in [0, 255]");
    if (i < 3) {
      rgb[i] = v;
      all_integers = all_integers && v == static_cast<double>(static_cast<int>(v));
    }
  }
  if (!all_integers && (rgb[0] > 1 || rgb[1] > 1 || rgb[2] > 1))
    refuse_at_line(InputErrorKind::malformed, path, line, what + ": fractional colour entries must be in [0, 1]");
}

}  // namespace

FileCounts check_off_file(const std::string& path, const std::string& bytes) {
  TextCursor cursor(bytes);
  const OffHeader h = read_header(path, cursor);
  const std::size_t numbers_per_vertex = h.normals ? 6 : 3;
  bool vertex_colors = false, face_colors = false;

  for (long long k = 0; k < h.vertices; ++k) {
    const std::string what = "vertex " + std::to_string(k + 1);
    cursor.skip_whitespace_and_comments();
    if (cursor.at_end())
      refuse(InputErrorKind::malformed, path, "the file ends after " + std::to_string(k) + " of " +
                                                  std::to_string(h.vertices) + " vertices");
    const long line = cursor.line();
    const std::vector<std::string_view> entries = split_record(cursor.rest_of_line());
    if (entries.size() < numbers_per_vertex)
      refuse_at_line(InputErrorKind::malformed, path, line,
                     what + " has " + std::to_string(entries.size()) + " numbers, " +
                         std::to_string(numbers_per_vertex) + " are needed");
    for (std::size_t i = 0; i < numbers_per_vertex; ++i) {
      double v;
      const char* name = i < 3 ? "coordinate " : "normal coordinate ";
      switch (parse_real(entries[i], v)) {
        case RealParse::ok: break;
        case RealParse::non_finite:
          refuse_at_line(InputErrorKind::non_finite_coordinate, path, line,
                         what + ": " + name + quoted(entries[i]) + " is not a finite double");
        case RealParse::not_a_number:
          refuse_at_line(InputErrorKind::malformed, path, line, what + ": " + name + quoted(entries[i]) +
                                                                    " is not a number");
      }
    }
    if (h.colors) check_colors(path, line, entries, numbers_per_vertex, vertex_colors, what);
  }

  FileCounts counts;
  counts.vertices = static_cast<std::size_t>(h.vertices);
  for (long long k = 0; k < h.faces; ++k) {
    const std::string what = "face " + std::to_string(k + 1);
    cursor.skip_whitespace_and_comments();
    if (cursor.at_end())
      refuse(InputErrorKind::malformed, path, "the file ends after " + std::to_string(k) + " of " +
                                                  std::to_string(h.faces) + " faces");
    const long line = cursor.line();
    const std::vector<std::string_view> entries = split_record(cursor.rest_of_line());
    long long n = -1;
    if (entries.empty() || !parse_integer(entries[0], n) || n < 0)
      refuse_at_line(InputErrorKind::malformed, path, line,
                     what + ": the corner count is not a non-negative integer");
    if (n < 3)
      refuse_at_line(InputErrorKind::too_few_corners, path, line,
                     what + " has " + std::to_string(n) + " corners (at least 3 are needed)");
    if (static_cast<unsigned long long>(n) > entries.size() - 1)
      refuse_at_line(InputErrorKind::malformed, path, line,
                     what + " declares " + std::to_string(n) + " corners but lists " +
                         std::to_string(entries.size() - 1) + " numbers");
    for (long long i = 1; i <= n; ++i) {
      long long index;
      if (!parse_integer(entries[i], index))
        refuse_at_line(InputErrorKind::malformed, path, line,
                       what + ": vertex index " + quoted(entries[i]) + " is not an integer");
      if (index < 0 || index >= h.vertices)
        refuse_at_line(InputErrorKind::index_out_of_range, path, line,
                       what + ": vertex index " + std::to_string(index) + " out of range (the file has " +
                           std::to_string(h.vertices) + " vertices)");
    }
    if (h.colors) check_colors(path, line, entries, static_cast<std::size_t>(n) + 1, face_colors, what);
    ++counts.faces;
    counts.corners += static_cast<std::size_t>(n);
  }
  return counts;
}

}  // namespace arrangements::detail
