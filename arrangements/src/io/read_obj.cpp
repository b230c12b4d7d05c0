// OBJ reader (see mesh_reader.h; what it accepts: load_triangle_soup.h): one statement per
// line, the first token names it; a backslash right before a line's end joins the next
// line (not inside a comment).
#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "io/mesh_reader.h"

namespace arrangements::detail {
namespace {

// Statements that are accepted and ignored (the free-form geometry and grouping statements
// of the format); any other but v and f (e.g. "l") is refused.
constexpr std::array<std::string_view, 45> kIgnoredStatements = {
    "vt",     "vn",       "vp",     "bevel",      "lod",       "ctech",  "c_interp", "usemap", "usemtl",
    "stech",  "d_interp", "mtllib", "shadow_obj", "trace_obj", "o",      "g",        "s",      "p",
    "cstype", "deg",      "step",   "bmat",       "con",       "curv",   "curv2",    "surf",   "parm",
    "trim",   "hole",     "scrv",   "sp",         "end",       "surf_1", "q0_1",     "q1_1",   "curv2d_1",
    "surf_2", "q0_2",     "q1_2",   "curv2d_2",   "bsp",       "bzp",    "cdc",      "cdp",    "res"};

bool is_ignored_statement(std::string_view keyword) {
  return std::find(kIgnoredStatements.begin(), kIgnoredStatements.end(), keyword) != kIgnoredStatements.end();
}

// A line that continues on the next: it ends in a backslash outside a comment.
bool continues(std::string_view line) {
  return !line.empty() && line.back() == '\\' && line.find('#') == std::string_view::npos;
}

// Long lines (beyond kMaxLineBytes) are v and f statements: exact rationals and polygons
// have no size limit.
bool may_be_long(std::string_view head) {
  const std::string_view keyword = LineTokens(head).next();
  return keyword == "v" || keyword == "f";
}

// Faces may name vertices defined later in the file; those indices are checked at the end.
// `forward` keeps, in file order, the faces whose largest forward index exceeds every
// earlier one: the first face with an index beyond the file's vertices is among them.
struct ForwardReference {
  long line;
  long long index;  // 1-based, as written
};

class ObjReader {
 public:
  ObjReader(FileBytes& in, SoupBuilder& out) : path_(in.path()), lines_(in), out_(out) {
    lines_.allow_long_lines(may_be_long);
  }

  void read() {
    std::string_view line;
    while (lines_.next(line)) {
      const long number = lines_.line_number();
      if (continues(line)) line = join_continued(line);
      statement(number, line);
    }
    for (const ForwardReference& f : forward_)
      if (static_cast<unsigned long long>(f.index) > out_.vertices.size())
        refuse_at_line(InputErrorKind::index_out_of_range, path_, f.line,
                       "vertex index " + std::to_string(f.index) + " out of range (the file has " +
                           std::to_string(out_.vertices.size()) + " vertices)");
  }

 private:
  // The joined line, held to the rule of a physical one (LineReader): beyond kMaxLineBytes
  // only a v or f statement, and only numbers and blanks there.
  std::string_view join_continued(std::string_view line) {
    joined_.assign(line.data(), line.size() - 1);
    std::string_view next;
    while (lines_.next(next)) {
      const bool more = continues(next);
      const std::size_t before = joined_.size();
      joined_.append(next.data(), next.size() - (more ? 1 : 0));
      if (joined_.size() > kMaxLineBytes) check_long_join(std::max(before, kMaxLineBytes));
      if (!more) break;
    }
    return joined_;
  }
  void check_long_join(std::size_t from) const {
    const bool numbers = std::all_of(joined_.begin() + static_cast<std::ptrdiff_t>(from), joined_.end(),
                                     [](char c) { return is_number_or_blank(c); });
    if (!numbers || !may_be_long(std::string_view(joined_).substr(0, kMaxLineBytes)))
      refuse_at_line(InputErrorKind::malformed, path_, lines_.line_number(),
                     "the lines joined by backslashes are longer than " + std::to_string(kMaxLineBytes) +
                         " bytes (1 MiB) and not a v or f statement of numbers");
  }

  void statement(long line, std::string_view text) {
    LineTokens tokens(strip_comment(text));
    const std::string_view keyword = tokens.next();
    if (keyword == "v") {
      vertex(line, tokens);
    } else if (keyword == "f") {
      face(line, tokens);
    } else if (!keyword.empty() && !is_ignored_statement(keyword)) {
      refuse_at_line(InputErrorKind::unsupported_variant, path_, line,
                     "OBJ statement " + quoted(keyword) + " is not supported");
    }
  }

  // x y z (decimals, or rationals: SoupBuilder::other_coordinate); more numbers (w,
  // colours) are ignored.
  void vertex(long line, LineTokens& tokens) {
    Vec3 v;
    for (int axis = 0; axis < 3; ++axis) {
      const std::string_view token = tokens.next();
      if (token.empty())
        refuse_at_line(InputErrorKind::malformed, path_, line,
                       "vertex " + std::to_string(out_.vertices.size() + 1) + " has fewer than 3 coordinates");
      const RealParse r = parse_real(token, v[axis]);
      if (r != RealParse::ok || out_.decimals_exact())  // a rational, an exact decimal, or refused
        out_.other_coordinate(line, "vertex " + std::to_string(out_.vertices.size() + 1) + ": coordinate ", axis, token,
                              r, v[axis]);
    }
    out_.add_vertex(v);
  }

  // Corners v, v/t, v/t/n or v//n: only v matters (1-based; negative: relative to the
  // vertices defined so far).
  void face(long line, LineTokens& tokens) {
    corners_.clear();
    const long long defined = static_cast<long long>(out_.vertices.size());
    long long largest_forward = 0;
    for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
      const std::string_view index_text = token.substr(0, token.find('/'));
      long long index;
      if (!parse_integer(index_text, index))
        refuse_at_line(InputErrorKind::malformed, path_, line,
                       "face corner " + quoted(token) + " does not start with an integer vertex index");
      if (index == 0)
        refuse_at_line(InputErrorKind::index_out_of_range, path_, line,
                       "vertex index 0 is invalid (OBJ indices start at 1)");
      if (index < 0) {
        if (-(index + 1) >= defined)
          refuse_at_line(InputErrorKind::index_out_of_range, path_, line,
                         "relative vertex index " + std::to_string(index) + " out of range (" +
                             std::to_string(defined) + " vertices defined before this line)");
        corners_.push_back(static_cast<int>(defined + index));
      } else {
        if (index > defined) largest_forward = std::max(largest_forward, index);
        // An index beyond int is out of range (checked at the end); keep the slot valid int.
        corners_.push_back(static_cast<int>(std::min<long long>(index, static_cast<long long>(kMaxIndexCount)) - 1));
      }
    }
    if (corners_.size() < 3)
      refuse_at_line(InputErrorKind::too_few_corners, path_, line,
                     "face " + std::to_string(faces_ + 1) + " has " + std::to_string(corners_.size()) +
                         " corners (at least 3 are needed)");
    if (largest_forward > (forward_.empty() ? 0 : forward_.back().index)) forward_.push_back({line, largest_forward});
    ++faces_;
    out_.add_face(corners_);
  }

  const std::string& path_;
  LineReader lines_;
  SoupBuilder& out_;
  std::string joined_;
  std::vector<int> corners_;
  std::vector<ForwardReference> forward_;
  unsigned long long faces_ = 0;
};

}  // namespace

void read_obj(FileBytes& in, SoupBuilder& out) { ObjReader(in, out).read(); }

}  // namespace arrangements::detail
