// arrangements/src/io/mesh_file_checks.h (internal to the mesh readers and writers)
//
// Helpers shared by the mesh readers (the streaming LineReader and TokenReader, for
// load_triangle_soup and read_exact_mesh) and by mesh_format.h and write_mesh: refusing
// with InputError ("PATH: what"), quoting tokens for messages (the one place where bytes
// that are not printable are escaped), strict number parsing, tokens of a line.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>

#include "arrangements/input_error.h"

namespace arrangements::detail {

// ---- shared helpers --------------------------------------------------------------------

[[noreturn]] inline void refuse(InputErrorKind kind, const std::string& path, const std::string& what) {
  throw InputError(kind, path + ": " + what);
}
[[noreturn]] inline void refuse_at_line(InputErrorKind kind, const std::string& path, long line,
                                        const std::string& what) {
  refuse(kind, path, "line " + std::to_string(line) + ": " + what);
}

// A token for a message: quoted, shortened; bytes that are not printable ASCII (and the
// backslash) escaped as \xHH (\\), so a message names the token as it is in the file.
inline std::string quoted(std::string_view token) {
  constexpr std::size_t kMax = 40;
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string s = "'";
  for (std::size_t i = 0; i < token.size() && i < kMax; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    if (c == '\\') {
      s += "\\\\";
    } else if (c >= 32 && c < 127) {
      s += static_cast<char>(c);
    } else {
      s += "\\x";
      s += kHex[c >> 4];
      s += kHex[c & 15];
    }
  }
  if (token.size() > kMax) s += "...";
  return s + "'";
}

enum class RealParse { ok, not_a_number, non_finite };

// Strict decimal number (one optional sign, digits, '.', exponent) that must fill the whole
// token, rounded correctly to F (float or double) by std::from_chars (libstdc++'s fast
// path, fast_float's algorithm); NaN, infinities and decimals beyond F's range are
// non_finite; decimals that underflow become the correctly rounded subnormal or zero.
template <class F>
RealParse parse_real(std::string_view token, F& value) {
  // One sign at most: from_chars takes a '-' but no '+', so after a '+' is taken here no
  // sign may follow ("+-1" is not -1).
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token.front() == '-') return RealParse::not_a_number;
  }
  if (token.empty() || token.front() == '+') return RealParse::not_a_number;
  // from_chars also reads "inf" and "nan": they come out non-finite below.
  const char* first = token.data();
  const char* last = token.data() + token.size();
  const auto r = std::from_chars(first, last, value, std::chars_format::general);
  if (r.ptr != last) return RealParse::not_a_number;
  if (r.ec == std::errc::result_out_of_range) {
    // Overflow is refused; underflow rounds to a subnormal or zero, as strtod / strtof
    // round it (a rare path: from_chars reports results that round to zero this way).
    const std::string copy(token);
    F v;
    if constexpr (std::is_same_v<F, float>)
      v = std::strtof(copy.c_str(), nullptr);
    else
      v = std::strtod(copy.c_str(), nullptr);
    if (!std::isfinite(v)) return RealParse::non_finite;
    value = v;
    return RealParse::ok;
  }
  if (r.ec != std::errc()) return RealParse::not_a_number;
  return std::isfinite(value) ? RealParse::ok : RealParse::non_finite;
}

// Strict integer (optional '-', digits) that fills the whole token and fits in T.
template <class T>
bool parse_integer(std::string_view token, T& value) {
  if (token.empty()) return false;
  const auto r = std::from_chars(token.data(), token.data() + token.size(), value);
  return r.ec == std::errc() && r.ptr == token.data() + token.size();
}

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

// Whitespace-separated tokens of one line.
class LineTokens {
 public:
  explicit LineTokens(std::string_view line) : line_(line) {}
  std::string_view next() {
    while (pos_ < line_.size() && is_space(line_[pos_])) ++pos_;
    const std::size_t begin = pos_;
    while (pos_ < line_.size() && !is_space(line_[pos_])) ++pos_;
    return line_.substr(begin, pos_ - begin);
  }

 private:
  std::string_view line_;
  std::size_t pos_ = 0;
};

// The text before the first '#'.
inline std::string_view strip_comment(std::string_view line) {
  const std::size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

inline constexpr std::size_t kMaxIndexCount = static_cast<std::size_t>(std::numeric_limits<int>::max());

}  // namespace arrangements::detail
