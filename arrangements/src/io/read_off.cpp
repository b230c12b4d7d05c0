// OFF reader (see mesh_reader.h; what it accepts: load_triangle_soup.h): a header (keyword,
// then "V F E"), then one vertex and one face per record, where a record is a line that
// has something before its '#' comment (blank and comment lines are skipped).
#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "io/mesh_reader.h"

namespace arrangements::detail {
namespace {

struct OffHeader {
  bool colors = false;   // C: colours may follow a vertex's coordinates / a face's indices
  bool normals = false;  // N: three normal coordinates follow each vertex's coordinates
  long long vertices = 0;
  long long faces = 0;
};

bool is_alnum(char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

class OffReader {
 public:
  OffReader(FileBytes& in, SoupBuilder& out) : in_(in), path_(in.path()), lines_(in), out_(out) {}

  void read() {
    read_header();
    lines_.allow_long_lines([](std::string_view) { return true; });  // records of numbers: no size limit
    const std::size_t numbers_per_vertex = h_.normals ? 6 : 3;
    // Each record takes a few bytes: reserve no more than the file can hold.
    out_.vertices.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(h_.vertices, in_.remaining() / 6)));
    for (long long k = 0; k < h_.vertices; ++k) {
      const auto what = [k] { return "vertex " + std::to_string(k + 1); };
      if (!next_record())
        refuse(InputErrorKind::malformed, path_,
               "the file ends after " + std::to_string(k) + " of " + std::to_string(h_.vertices) + " vertices");
      if (entries_.size() < numbers_per_vertex)
        refuse_at_line(InputErrorKind::malformed, path_, line_,
                       what() + " has " + std::to_string(entries_.size()) + " numbers, " +
                           std::to_string(numbers_per_vertex) + " are needed");
      Vec3 v;
      for (std::size_t i = 0; i < numbers_per_vertex; ++i) {
        double value;
        const RealParse r = parse_real(entries_[i], value);
        if ((r != RealParse::ok || out_.decimals_exact()) && i < 3)  // a rational, an exact decimal, or refused
          out_.other_coordinate(line_, what() + ": coordinate ", static_cast<int>(i), entries_[i], r, value);
        else if (r != RealParse::ok)
          refuse_coordinate(path_, line_, r, what() + ": normal coordinate ", entries_[i]);
        if (i < 3) v[i] = value;
      }
      if (h_.colors) check_colors(numbers_per_vertex, vertex_colors_, what());
      out_.add_vertex(v);
    }
    out_.triangles.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(h_.faces, in_.remaining() / 8)));
    for (long long k = 0; k < h_.faces; ++k) read_face(k);
  }

 private:
  // The next record's tokens (comment removed) into entries_, its line into line_; false at
  // the end of the file.
  bool next_record() {
    std::string_view line;
    while (lines_.next(line)) {
      split(line);
      if (!entries_.empty()) {
        line_ = lines_.line_number();
        return true;
      }
    }
    return false;
  }
  void split(std::string_view text) {
    entries_.clear();
    LineTokens tokens(strip_comment(text));
    for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next()) entries_.push_back(t);
  }

  void read_header() {
    std::string_view line;
    do {
      if (!lines_.next(line))
        refuse_at_line(InputErrorKind::malformed, path_, lines_.line_number() + 1, "no OFF header keyword");
    } while (LineTokens(strip_comment(line)).next().empty());
    line_ = lines_.line_number();
    std::size_t start = 0;
    while (start < line.size() && is_space(line[start])) ++start;
    std::size_t end = start;
    while (end < line.size() && is_alnum(line[end])) ++end;
    const std::string_view keyword = line.substr(start, end - start);
    if (keyword.empty() || (end < line.size() && !is_space(line[end])))
      refuse_at_line(InputErrorKind::malformed, path_, line_, "no OFF header keyword");
    // The keyword grammar: [ST][C][N][4][n](OFF|SKEL).
    std::string_view rest = keyword;
    auto take = [&rest](std::string_view prefix) {
      if (rest.substr(0, prefix.size()) != prefix || rest.size() == prefix.size()) return false;
      rest.remove_prefix(prefix.size());
      return true;
    };
    const bool textures = take("ST");
    h_.colors = take("C");
    h_.normals = take("N");
    const bool homogeneous = take("4");
    const bool dimension = take("n");
    if (rest != "OFF" && rest != "SKEL")
      refuse_at_line(InputErrorKind::malformed, path_, line_,
                     "not an OFF file (header keyword " + quoted(keyword) + ")");
    if (rest == "SKEL" || textures || homogeneous || dimension)
      refuse_at_line(InputErrorKind::unsupported_variant, path_, line_,
                     quoted(keyword) + " files are not supported (only OFF, COFF, NOFF, CNOFF)");
    // The counts: after the keyword on its line, or the next record.
    split(line.substr(end));
    if (entries_.empty() && !next_record())
      refuse(InputErrorKind::malformed, path_, "the file ends before the vertex, face and edge counts");
    if (entries_[0] == "BINARY")
      refuse_at_line(InputErrorKind::unsupported_variant, path_, line_, "binary OFF files are not supported");
    if (entries_.size() < 3)
      refuse_at_line(InputErrorKind::malformed, path_, line_,
                     "the OFF header needs the vertex, face and edge counts on one line");
    if (entries_.size() > 3)
      refuse_at_line(InputErrorKind::malformed, path_, line_,
                     "unexpected " + quoted(entries_[3]) + " after the vertex, face and edge counts");
    long long edges;
    if (!parse_integer(entries_[0], h_.vertices) || h_.vertices < 0 || !parse_integer(entries_[1], h_.faces) ||
        h_.faces < 0 || !parse_integer(entries_[2], edges))
      refuse_at_line(InputErrorKind::malformed, path_, line_,
                     "the vertex, face and edge counts must be integers (vertex and face counts >= 0)");
    if (static_cast<unsigned long long>(h_.vertices) > kMaxIndexCount ||
        static_cast<unsigned long long>(h_.faces) > kMaxIndexCount)
      refuse_at_line(InputErrorKind::too_large, path_, line_,
                     "more than " + std::to_string(kMaxIndexCount) + " vertices or faces");
  }

  void read_face(long long k) {
    const auto what = [k] { return "face " + std::to_string(k + 1); };
    if (!next_record())
      refuse(InputErrorKind::malformed, path_,
             "the file ends after " + std::to_string(k) + " of " + std::to_string(h_.faces) + " faces");
    long long n = -1;
    if (!parse_integer(entries_[0], n) || n < 0)
      refuse_at_line(InputErrorKind::malformed, path_, line_,
                     what() + ": the corner count is not a non-negative integer");
    if (n < 3)
      refuse_at_line(InputErrorKind::too_few_corners, path_, line_,
                     what() + " has " + std::to_string(n) + " corners (at least 3 are needed)");
    if (static_cast<unsigned long long>(n) > entries_.size() - 1)
      refuse_at_line(InputErrorKind::malformed, path_, line_,
                     what() + " declares " + std::to_string(n) + " corners but lists " +
                         std::to_string(entries_.size() - 1) + " numbers");
    corners_.clear();
    for (long long i = 1; i <= n; ++i) {
      long long index;
      if (!parse_integer(entries_[i], index))
        refuse_at_line(InputErrorKind::malformed, path_, line_,
                       what() + ": vertex index " + quoted(entries_[i]) + " is not an integer");
      if (index < 0 || index >= h_.vertices)
        refuse_at_line(InputErrorKind::index_out_of_range, path_, line_,
                       what() + ": vertex index " + std::to_string(index) + " out of range (the file has " +
                           std::to_string(h_.vertices) + " vertices)");
      corners_.push_back(static_cast<int>(index));
    }
    if (h_.colors) check_colors(static_cast<std::size_t>(n) + 1, face_colors_, what());
    out_.add_face(corners_);
  }

  // Colour entries of one record: none, RGB or RGBA, as integers in [0, 255] or as reals
  // in [0, 1]. Once a record of a kind (vertex or face) has colours, every later record of
  // that kind needs them too.
  void check_colors(std::size_t first, bool& colors_seen, const std::string& what) {
    const int n = static_cast<int>(entries_.size() - first);
    if (n != 0 && n != 3 && n != 4)
      refuse_at_line(InputErrorKind::unsupported_variant, path_, line_,
                     what + " has " + std::to_string(n) + " colour entries (supported: 0, 3 or 4)");
    if (colors_seen && n == 0)
      refuse_at_line(InputErrorKind::unsupported_variant, path_, line_,
                     what + " has no colour entries, but an earlier record has (they are needed from then on)");
    colors_seen = colors_seen || n > 0;
    bool all_integers = true;
    double rgb[3] = {0, 0, 0};
    for (int i = 0; i < n; ++i) {
      double v;
      if (parse_real(entries_[first + i], v) != RealParse::ok || v < 0 || v > 255)
        refuse_at_line(InputErrorKind::malformed, path_, line_,
                       what + ": colour entry " + quoted(entries_[first + i]) + " is not a number in [0, 255]");
      if (i < 3) {
        rgb[i] = v;
        all_integers = all_integers && v == static_cast<double>(static_cast<int>(v));
      }
    }
    if (!all_integers && (rgb[0] > 1 || rgb[1] > 1 || rgb[2] > 1))
      refuse_at_line(InputErrorKind::malformed, path_, line_, what + ": fractional colour entries must be in [0, 1]");
  }

  FileBytes& in_;
  const std::string& path_;
  LineReader lines_;
  SoupBuilder& out_;
  OffHeader h_;
  std::vector<std::string_view> entries_;  // the current record's tokens
  long line_ = 0;                          // the current record's line
  std::vector<int> corners_;
  bool vertex_colors_ = false, face_colors_ = false;
};

}  // namespace

void read_off(FileBytes& in, SoupBuilder& out) { OffReader(in, out).read(); }

}  // namespace arrangements::detail
