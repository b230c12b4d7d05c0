// arrangements/src/io/mesh_reader.h (internal to load_triangle_soup and read_exact_mesh)
//
// The pieces of the one-pass mesh readers (read_obj.cpp, read_off.cpp, read_stl.cpp,
// read_ply.cpp): each reads its file as a stream and validates and fills a SoupBuilder in
// the same pass, so memory holds the parsed arrays plus one buffer of the file.
//   FileBytes    the file in chunks of 1 MiB (a longer line grows the buffer); the one
//                place where a mesh file is opened and read
//   LineReader   lines ending in LF, CRLF or CR (a UTF-8 BOM at the start is skipped);
//                refuses bytes that are not text: a NUL byte, a line longer than
//                kMaxLineBytes unless the reader allows long lines of numbers there
//   TokenReader  whitespace-separated tokens across lines, with their line numbers
//   SoupBuilder  vertices and faces; polygons are triangulated by finish(); coordinate
//                tokens that are not decimals go to other_coordinate (exact rationals),
//                every coordinate token does for read_exact_mesh (decimals_exact)
// Numbers and messages: parse_real, parse_integer, quoted, refuse (mesh_file_checks.h).
#pragma once

#include <CGAL/Gmpq.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "arrangements/triangle_soup.h"
#include "io/mesh_file_checks.h"

namespace arrangements::detail {

class FileBytes {
 public:
  // Opens path; refuses (unreadable_file) a missing, non-regular or unreadable file.
  explicit FileBytes(const std::string& path);
  ~FileBytes();
  FileBytes(const FileBytes&) = delete;
  FileBytes& operator=(const FileBytes&) = delete;

  const std::string& path() const { return path_; }
  std::uint64_t size() const { return size_; }        // the file's size when it was opened
  std::uint64_t offset() const { return consumed_; }  // bytes consumed so far
  std::uint64_t remaining() const { return size_ > consumed_ ? size_ - consumed_ : 0; }

  // Makes at least n bytes available from the cursor, fewer only at the end of the file;
  // returns how many are. Invalidates unread() and earlier views.
  std::size_t fill(std::size_t n) { return end_ - pos_ >= n ? end_ - pos_ : refill(n); }
  const char* unread() const { return buffer_.data() + pos_; }
  std::size_t available() const { return end_ - pos_; }
  void consume(std::size_t n) {
    pos_ += n;
    consumed_ += n;
  }

 private:
  std::size_t refill(std::size_t n);
  std::string path_;
  std::FILE* file_ = nullptr;
  std::vector<char> buffer_;
  std::size_t pos_ = 0, end_ = 0;
  std::uint64_t size_ = 0, consumed_ = 0;
  bool eof_ = false;
};

inline bool is_line_end(char c) { return c == '\n' || c == '\r'; }

// The longest line a text reader holds (1 MiB), so that a file that is not text (or not the
// format its name says) is refused after its first MiB at most. Longer lines are read only
// where a reader allows them (LineReader::allow_long_lines: vertex and face records, whose
// exact rationals and polygons have no size limit), and then only numbers and blanks may
// follow the first MiB.
inline constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;

// A byte that may follow the first kMaxLineBytes of a long line: numbers (digits, signs,
// '.', '/', 'e', 'E') and blanks.
inline bool is_number_or_blank(char c) {
  return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.' || c == '/' || c == 'e' || c == 'E' || c == ' ' ||
         c == '\t' || c == '\v' || c == '\f';
}

class LineReader {
 public:
  // not_text: what a file with bytes that are not text is not, for messages ("PATH: line
  // L: a NUL byte: " + not_text).
  explicit LineReader(FileBytes& in, std::string not_text = "not a text mesh file")
      : in_(in), not_text_(std::move(not_text)) {
    if (in_.fill(3) >= 3 && std::string_view(in_.unread(), 3) == "\xEF\xBB\xBF") in_.consume(3);
  }
  // Whether a line may be longer than kMaxLineBytes, given its first kMaxLineBytes bytes
  // (the rest must then be numbers and blanks). nullptr, the default: no line may.
  using LongLineRule = bool (*)(std::string_view head);
  void allow_long_lines(LongLineRule rule) { long_lines_ = rule; }

  // The next line without its end (LF, CRLF or CR; the last line may have none); false at
  // the end of the file. The view lives until the next call on this reader or its file.
  // Refuses (malformed) a NUL byte and a line that is too long (above).
  bool next(std::string_view& line) {
    std::size_t n = in_.available();
    if (n == 0 && (n = in_.fill(1)) == 0) return false;
    std::size_t i = 0;
    for (;;) {
      i = find_line_end(in_.unread(), i, n);
      if (i < n) break;
      const std::size_t more = in_.fill(n + 1);
      if (more == n) {  // the last line, without an end
        line = std::string_view(in_.unread(), n);
        in_.consume(n);
        ++line_;
        return true;
      }
      n = more;
    }
    std::size_t end_length = 1;
    if (in_.unread()[i] == '\r') {
      if (i + 1 >= n) n = in_.fill(i + 2);
      if (i + 1 < n && in_.unread()[i + 1] == '\n') end_length = 2;
    }
    line = std::string_view(in_.unread(), i);
    in_.consume(i + end_length);
    ++line_;
    return true;
  }
  long line_number() const { return line_; }  // of the last line returned (1-based)

 private:
  // The first line end in p[i, n) (p: the current line), or n; refuses what is not text.
  std::size_t find_line_end(const char* p, std::size_t i, std::size_t n) const {
    const std::size_t short_end = n < kMaxLineBytes ? n : kMaxLineBytes;
    for (; i < short_end; ++i) {
      const unsigned char c = static_cast<unsigned char>(p[i]);
      if (c > '\r') continue;  // the common case: no line end, no NUL
      if (c == '\n' || c == '\r') return i;
      if (c == '\0') refuse_not_text("a NUL byte");
    }
    return i < n ? find_long_line_end(p, i, n) : n;
  }
  std::size_t find_long_line_end(const char* p, std::size_t i, std::size_t n) const;
  [[noreturn]] void refuse_not_text(const std::string& problem) const;

  FileBytes& in_;
  std::string not_text_;
  LongLineRule long_lines_ = nullptr;
  long line_ = 0;
};

class TokenReader {
 public:
  explicit TokenReader(LineReader& lines) : lines_(lines) {}
  // The next token, empty at the end of the file; line() is then its line. The view lives
  // until the next call.
  std::string_view next() {
    for (;;) {
      std::size_t i = 0;
      while (i < rest_.size() && is_space(rest_[i])) ++i;
      if (i < rest_.size()) {
        std::size_t j = i;
        while (j < rest_.size() && !is_space(rest_[j])) ++j;
        const std::string_view token = rest_.substr(i, j - i);
        rest_.remove_prefix(j);
        return token;
      }
      if (!lines_.next(rest_)) {
        rest_ = {};
        return {};
      }
    }
  }
  long line() const { return lines_.line_number(); }
  // Drops the rest of the current line: the next token comes from the next line.
  void skip_rest_of_line() { rest_ = {}; }
  std::size_t pending() const { return rest_.size(); }  // bytes of the current line not read yet

 private:
  LineReader& lines_;
  std::string_view rest_;
};

// The faces and vertices of one file, as its reader finds them.
//   exact = false (load_triangle_soup): every coordinate must be a double; a rational that
//           is not one is refused (unsupported_variant, naming load_mesh_files).
//   exact = true (load_mesh_files): such rationals are kept exactly; after finish(),
//           exact_vertices then holds every vertex (see below).
//   decimals_exact = true (read_exact_mesh; implies exact): decimals too are read as their
//           exact value (rational_token.h's parse_exact_decimal), so the readers hand every
//           coordinate to other_coordinate.
class SoupBuilder {
 public:
  explicit SoupBuilder(const std::string& path, bool exact = false, bool decimals_exact = false)
      : path_(path), exact_allowed_(exact || decimals_exact), decimals_exact_(decimals_exact) {}

  bool decimals_exact() const { return decimals_exact_; }

  // The vertices as doubles. Before finish(): a vertex with an exact coordinate has an
  // unspecified double there. After finish(): empty when exact_vertices is not.
  std::vector<Vec3> vertices;
  // After finish(): every vertex exactly (doubles converted exactly) when some coordinate
  // of the file is not a double; empty otherwise.
  std::vector<ExactVec3> exact_vertices;
  // Triangles in file order; a polygon of n corners holds n - 2 slots here, filled by
  // finish().
  std::vector<Tri> triangles;
  // After finish(): TriangleSoup::polygon (empty when no polygon was split without overlap).
  std::vector<std::int64_t> polygon;

  void add_vertex(const Vec3& v) {
    if (vertices.size() >= kMaxIndexCount) refuse_too_large("vertices");
    if (pending_axes_ != 0) [[unlikely]]
      keep_exact(v);
    vertices.push_back(v);
  }
  // The slow path of coordinate `axis` (0, 1, 2) of the vertex being read (the next
  // add_vertex), for a token that parse_real did not accept (r), or for every token when
  // decimals_exact (a decimal then taken exactly, as a rational): a rational N/D
  // (rational_token.h) that is exactly a double becomes `value` ("-0/N" is -0.0, as the
  // decimal "-0" is); another rational is kept for that vertex (exact) or refused (not
  // exact). Anything else is refused as refuse_coordinate refuses it, and so are a zero
  // denominator, a decimal exponent beyond kMaxDecimalExponent (decimals_exact) and
  // |value| > DBL_MAX (not decimals_exact). Any number of digits is read: a token is no
  // larger than its file. `what` names the coordinate for messages ("vertex 7: coordinate ").
  void other_coordinate(long line, const std::string& what, int axis, std::string_view token, RealParse r,
                        double& value);
  // corners: at least 3 (the reader checks it and the indices, before finish()).
  void add_face(std::span<const int> corners) {
    if (corners.size() == 3) {
      if (triangles.size() >= kMaxIndexCount) refuse_too_large("triangles");
      triangles.push_back({corners[0], corners[1], corners[2]});
    } else {
      add_polygon(corners);
    }
  }
  // Gathers the exact vertices (if any) and triangulates the polygons
  // (triangulate_polygon.h, on the exact coordinates when there are any); every index must
  // be valid.
  void finish();

 private:
  [[noreturn]] void refuse_too_large(const char* what) const;
  void add_polygon(std::span<const int> corners);
  void keep_exact(const Vec3& v);
  template <class Coordinates>
  void triangulate_polygons(const std::vector<Coordinates>& V);
  const std::string& path_;
  bool exact_allowed_;
  bool decimals_exact_;
  std::vector<int> polygon_corners_;
  std::vector<std::size_t> polygon_start_;     // into polygon_corners_, per polygon
  std::vector<std::size_t> polygon_triangle_;  // its first slot in triangles, per polygon
  // The vertices with a coordinate that is not a double, in index order.
  std::vector<std::pair<std::size_t, ExactVec3>> exact_;
  unsigned pending_axes_ = 0;  // bit k: the vertex being read has exact coordinate k
  ExactVec3 pending_;
};

// The readers: the whole file, validated, into out (out.finish() is the caller's).
void read_obj(FileBytes& in, SoupBuilder& out);
void read_off(FileBytes& in, SoupBuilder& out);
void read_stl(FileBytes& in, SoupBuilder& out);
void read_ply(FileBytes& in, SoupBuilder& out);

// Refuses a coordinate token that parse_real did not accept.
[[noreturn]] inline void refuse_coordinate(const std::string& path, long line, RealParse r, const std::string& what,
                                           std::string_view token) {
  if (r == RealParse::non_finite)
    refuse_at_line(InputErrorKind::non_finite_coordinate, path, line, what + quoted(token) + " is not a finite double");
  refuse_at_line(InputErrorKind::malformed, path, line, what + quoted(token) + " is not a number");
}

// a == b in ASCII letter case.
inline bool equals_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    char c = a[i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != b[i]) return false;  // b is lower case
  }
  return true;
}

}  // namespace arrangements::detail
