// Exact OBJ / OFF reader (see read_exact_mesh.h): every number is parsed into a rational
// from its text, never through a double.
#include "arrangements/read_exact_mesh.h"

#include <gmp.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/mesh_format.h"
#include "io/mesh_reader.h"
#include "io/rational_token.h"

namespace arrangements {
namespace {

using detail::quoted;
using detail::read_whole_file;
using detail::refuse;
using detail::refuse_at_line;

constexpr long kMaxDecimalExponent = 4096;

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (c < '0' || c > '9') return false;
  return true;
}

// An mpq_t that clears itself, so that no path leaks it.
struct Rational {
  mpq_t q;
  Rational() { mpq_init(q); }
  ~Rational() { mpq_clear(q); }
  Rational(const Rational&) = delete;
  Rational& operator=(const Rational&) = delete;
};

// Parses the grammar of read_exact_mesh.h; nullopt when the token does not follow it.
// Rationals N/D: parse_rational (rational_token.h), shared with load_mesh_files; decimals:
// their exact decimal value (load_mesh_files reads them as doubles instead).
std::optional<CGAL::Gmpq> parse_number(std::string_view token) {
  if (token.find('/') != std::string_view::npos) {  // N/D, as load_mesh_files reads it (no digit limit)
    CGAL::Gmpq q;
    if (detail::parse_rational(token, q, std::numeric_limits<std::size_t>::max()) != detail::RationalParse::ok)
      return std::nullopt;
    return q;
  }
  bool negative = false;
  if (!token.empty() && (token.front() == '+' || token.front() == '-')) {
    negative = token.front() == '-';
    token.remove_prefix(1);
  }
  Rational r;
  mpz_ptr num = mpq_numref(r.q);
  mpz_ptr den = mpq_denref(r.q);
  const std::size_t e_pos = token.find_first_of("eE");
  const std::string_view mantissa = token.substr(0, e_pos);
  long exponent = 0;
  if (e_pos != std::string_view::npos) {
    std::string_view e = token.substr(e_pos + 1);
    bool e_negative = false;
    if (!e.empty() && (e.front() == '+' || e.front() == '-')) {
      e_negative = e.front() == '-';
      e.remove_prefix(1);
    }
    if (!all_digits(e)) return std::nullopt;
    for (char c : e) {
      exponent = exponent * 10 + (c - '0');
      if (exponent > kMaxDecimalExponent) return std::nullopt;
    }
    if (e_negative) exponent = -exponent;
  }
  const std::size_t point = mantissa.find('.');
  const std::string_view whole = mantissa.substr(0, point);
  const std::string_view fraction = point == std::string_view::npos ? std::string_view() : mantissa.substr(point + 1);
  if (whole.empty() && fraction.empty()) return std::nullopt;
  if ((!whole.empty() && !all_digits(whole)) || (!fraction.empty() && !all_digits(fraction))) return std::nullopt;
  // value = (whole fraction as one integer) * 10^(exponent - #fraction digits)
  mpz_set_str(num, (std::string(whole) + std::string(fraction)).c_str(), 10);
  const long scale = exponent - static_cast<long>(fraction.size());
  if (scale >= 0) {
    mpz_ui_pow_ui(den, 10, static_cast<unsigned long>(scale));
    mpz_mul(num, num, den);
    mpz_set_ui(den, 1);
  } else {
    mpz_ui_pow_ui(den, 10, static_cast<unsigned long>(-scale));
  }
  mpq_canonicalize(r.q);
  if (negative) mpq_neg(r.q, r.q);
  return CGAL::Gmpq(r.q);
}

// The file's lines, numbered from 1, without '\n' or a trailing '\r', comments removed.
class Lines {
 public:
  explicit Lines(std::string_view text) : cursor_(text) {}
  // The next line that is not blank (after removing its comment); false at the end.
  bool next(std::string_view& line) {
    while (!cursor_.at_end()) {
      number_ = cursor_.line();
      line = detail::strip_comment(cursor_.rest_of_line());
      if (!detail::LineTokens(line).next().empty()) return true;
    }
    return false;
  }
  long number() const { return number_; }

 private:
  detail::TextCursor cursor_;
  long number_ = 0;
};

std::array<CGAL::Gmpq, 3> parse_vertex(const std::string& path, long line, detail::LineTokens& tokens) {
  std::array<CGAL::Gmpq, 3> v;
  for (int k = 0; k < 3; ++k) {
    const std::string_view token = tokens.next();
    if (token.empty())
      refuse_at_line(InputErrorKind::malformed, path, line,
                     "a vertex needs three coordinates, found " + std::to_string(k));
    std::optional<CGAL::Gmpq> q = parse_number(token);
    if (!q)
      refuse_at_line(InputErrorKind::malformed, path, line,
                     "coordinate " + quoted(token) + " is not a rational (N/D) or decimal number" +
                         " (decimal exponents up to " + std::to_string(kMaxDecimalExponent) + ")");
    v[k] = *q;
  }
  if (!tokens.next().empty())
    refuse_at_line(InputErrorKind::malformed, path, line, "a vertex needs exactly three coordinates, found more");
  return v;
}

void refuse_if_too_large(const std::string& path, std::size_t count, const char* what) {
  if (count > detail::kMaxIndexCount)
    refuse(InputErrorKind::too_large, path,
           std::string("more than ") + std::to_string(detail::kMaxIndexCount) + " " + what);
}

// The fan of a polygon, as load_triangle_soup makes it.
void add_fan(const std::string& path, const std::vector<int>& corners, std::vector<Tri>& triangles) {
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) triangles.push_back({corners[0], corners[i], corners[i + 1]});
  refuse_if_too_large(path, triangles.size(), "triangles");
}

// "i", "i/t", "i/t/n", "i//n": the vertex index i.
std::optional<long long> obj_corner_index(std::string_view corner) {
  const std::size_t s1 = corner.find('/');
  long long index = 0;
  if (!detail::parse_integer(corner.substr(0, s1), index)) return std::nullopt;
  if (s1 == std::string_view::npos) return index;
  const std::string_view rest = corner.substr(s1 + 1);
  const std::size_t s2 = rest.find('/');
  const std::string_view t = rest.substr(0, s2);
  long long unused = 0;
  if (s2 == std::string_view::npos) {
    if (!detail::parse_integer(t, unused)) return std::nullopt;
  } else {
    if (!t.empty() && !detail::parse_integer(t, unused)) return std::nullopt;
    if (!detail::parse_integer(rest.substr(s2 + 1), unused)) return std::nullopt;
  }
  return index;
}

ExactMesh read_obj(const std::string& path, std::string_view text) {
  ExactMesh mesh;
  Lines lines(text);
  std::string_view line;
  // Positive indices may name vertices defined later: the largest one is checked at the end.
  long long largest_index = 0;
  long largest_index_line = 0;
  std::vector<int> corners;
  while (lines.next(line)) {
    detail::LineTokens tokens(line);
    const std::string_view keyword = tokens.next();
    if (keyword == "v") {
      mesh.vertices.push_back(parse_vertex(path, lines.number(), tokens));
      refuse_if_too_large(path, mesh.vertices.size(), "vertices");
    } else if (keyword == "f") {
      corners.clear();
      for (std::string_view corner = tokens.next(); !corner.empty(); corner = tokens.next()) {
        const std::optional<long long> index = obj_corner_index(corner);
        if (!index)
          refuse_at_line(InputErrorKind::malformed, path, lines.number(),
                         "face corner " + quoted(corner) + " is not i, i/t, i/t/n or i//n");
        const long long defined = static_cast<long long>(mesh.vertices.size());
        if (*index == 0 || *index < -defined || *index > static_cast<long long>(detail::kMaxIndexCount))
          refuse_at_line(InputErrorKind::index_out_of_range, path, lines.number(),
                         "vertex index " + std::to_string(*index) + " out of range (" + std::to_string(defined) +
                             " vertices defined so far)");
        if (*index > largest_index) {
          largest_index = *index;
          largest_index_line = lines.number();
        }
        corners.push_back(static_cast<int>(*index > 0 ? *index - 1 : defined + *index));
      }
      if (corners.size() < 3)
        refuse_at_line(InputErrorKind::too_few_corners, path, lines.number(),
                       "a face has " + std::to_string(corners.size()) + " corners (at least 3 are needed)");
      add_fan(path, corners, mesh.triangles);
    } else if (keyword != "vt" && keyword != "vn" && keyword != "vp" && keyword != "g" && keyword != "o" &&
               keyword != "s" && keyword != "usemtl" && keyword != "mtllib") {
      refuse_at_line(InputErrorKind::malformed, path, lines.number(), "unsupported OBJ statement " + quoted(keyword));
    }
  }
  if (largest_index > static_cast<long long>(mesh.vertices.size()))
    refuse_at_line(InputErrorKind::index_out_of_range, path, largest_index_line,
                   "vertex index " + std::to_string(largest_index) + " out of range (the file has " +
                       std::to_string(mesh.vertices.size()) + " vertices)");
  return mesh;
}

// A count of the OFF header: a non-negative integer.
std::size_t off_count(const std::string& path, long line, std::string_view token) {
  unsigned long long n = 0;
  if (!detail::parse_integer(token, n))
    refuse_at_line(InputErrorKind::malformed, path, line,
                   "expected the counts '#vertices #faces #edges', found " + quoted(token));
  if (n > detail::kMaxIndexCount)
    refuse_at_line(InputErrorKind::too_large, path, line,
                   "count " + std::to_string(n) + " exceeds " + std::to_string(detail::kMaxIndexCount));
  return static_cast<std::size_t>(n);
}

ExactMesh read_off(const std::string& path, std::string_view text) {
  ExactMesh mesh;
  Lines lines(text);
  std::string_view line;
  if (!lines.next(line)) refuse(InputErrorKind::malformed, path, "empty file (no 'OFF' header)");
  detail::LineTokens header(line);
  const std::string_view magic = header.next();
  if (magic != "OFF") {
    if (magic.size() > 3 && magic.substr(magic.size() - 3) == "OFF")
      refuse_at_line(InputErrorKind::unsupported_variant, path, lines.number(),
                     quoted(magic) + " files are not supported (only plain 'OFF')");
    refuse_at_line(InputErrorKind::malformed, path, lines.number(), "not an OFF file (no 'OFF' header)");
  }
  // The counts follow on the same line or on the next non-blank one.
  detail::LineTokens counts_tokens = header;
  std::string_view first = counts_tokens.next();
  if (first.empty()) {
    if (!lines.next(line)) refuse(InputErrorKind::malformed, path, "the file ends before the counts line");
    counts_tokens = detail::LineTokens(line);
    first = counts_tokens.next();
  }
  const long counts_line = lines.number();
  const std::size_t nv = off_count(path, counts_line, first);
  const std::size_t nf = off_count(path, counts_line, counts_tokens.next());
  off_count(path, counts_line, counts_tokens.next());  // edges: ignored, but must be there
  if (!counts_tokens.next().empty())
    refuse_at_line(InputErrorKind::malformed, path, counts_line, "expected exactly three counts");

  // Reserve no more than the file could hold (a count may be absurd).
  mesh.vertices.reserve(std::min(nv, text.size() / 6));
  for (std::size_t i = 0; i < nv; ++i) {
    if (!lines.next(line))
      refuse(InputErrorKind::malformed, path,
             "the file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    detail::LineTokens tokens(line);
    mesh.vertices.push_back(parse_vertex(path, lines.number(), tokens));
  }
  std::vector<int> corners;
  for (std::size_t f = 0; f < nf; ++f) {
    if (!lines.next(line))
      refuse(InputErrorKind::malformed, path,
             "the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    detail::LineTokens tokens(line);
    const std::string_view size_token = tokens.next();
    unsigned long long n = 0;
    if (!detail::parse_integer(size_token, n) || n > line.size())
      refuse_at_line(InputErrorKind::malformed, path, lines.number(),
                     "expected a face 'n i1 ... in', found " + quoted(size_token));
    if (n < 3)
      refuse_at_line(InputErrorKind::too_few_corners, path, lines.number(),
                     "a face has " + std::to_string(n) + " corners (at least 3 are needed)");
    corners.clear();
    for (unsigned long long k = 0; k < n; ++k) {
      const std::string_view token = tokens.next();
      long long index = 0;
      if (!detail::parse_integer(token, index))
        refuse_at_line(InputErrorKind::malformed, path, lines.number(),
                       "face with " + std::to_string(n) + " corners: expected a vertex index, found " +
                           (token.empty() ? std::string("the end of the line") : quoted(token)));
      if (index < 0 || static_cast<unsigned long long>(index) >= nv)
        refuse_at_line(InputErrorKind::index_out_of_range, path, lines.number(),
                       "vertex index " + std::to_string(index) + " out of range (the file has " + std::to_string(nv) +
                           " vertices)");
      corners.push_back(static_cast<int>(index));
    }
    if (!tokens.next().empty())
      refuse_at_line(InputErrorKind::malformed, path, lines.number(),
                     "a face with " + std::to_string(n) + " corners has more numbers (colours are not supported)");
    add_fan(path, corners, mesh.triangles);
  }
  if (lines.next(line))
    refuse_at_line(InputErrorKind::malformed, path, lines.number(),
                   "unexpected content after the " + std::to_string(nf) + " faces");
  return mesh;
}

}  // namespace

ExactMesh read_exact_mesh(const std::string& path) {
  const detail::MeshFormat format = detail::format_of_or_refuse(path, detail::kExactFormats, "read_exact_mesh reads");
  const std::string bytes = read_whole_file(path);
  return format == detail::MeshFormat::obj ? read_obj(path, bytes) : read_off(path, bytes);
}

}  // namespace arrangements
