// Rational coordinate tokens (see rational_token.h).
#include "io/rational_token.h"

#include <gmp.h>

#include <cmath>
#include <limits>
#include <string>

namespace arrangements::detail {
namespace {

// The number of leading decimal digits of s.
std::size_t digit_run(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
  return i;
}

// An mpq_t that clears itself, so that no path leaks it.
struct ScopedMpq {
  mpq_t q;
  ScopedMpq() { mpq_init(q); }
  ~ScopedMpq() { mpq_clear(q); }
  ScopedMpq(const ScopedMpq&) = delete;
  ScopedMpq& operator=(const ScopedMpq&) = delete;
};

}  // namespace

RationalParse parse_rational(std::string_view token, CGAL::Gmpq& value) {
  bool negative = false;
  if (!token.empty() && (token.front() == '+' || token.front() == '-')) {
    negative = token.front() == '-';
    token.remove_prefix(1);
  }
  const std::size_t n = digit_run(token);
  if (n == 0 || n == token.size() || token[n] != '/') return RationalParse::not_rational;
  const std::string_view numerator = token.substr(0, n), denominator = token.substr(n + 1);
  const std::size_t d = digit_run(denominator);
  if (d == 0 || d != denominator.size()) return RationalParse::not_rational;
  if (denominator.find_first_not_of('0') == std::string_view::npos) return RationalParse::zero_denominator;
  ScopedMpq r;
  // Both parts are non-empty strings of decimal digits: mpz_set_str accepts them.
  mpz_set_str(mpq_numref(r.q), std::string(numerator).c_str(), 10);
  mpz_set_str(mpq_denref(r.q), std::string(denominator).c_str(), 10);
  mpq_canonicalize(r.q);
  if (negative) mpq_neg(r.q, r.q);
  value = CGAL::Gmpq(r.q);
  return RationalParse::ok;
}

RationalParse parse_exact_decimal(std::string_view token, CGAL::Gmpq& value, std::size_t max_digits) {
  bool negative = false;
  if (!token.empty() && (token.front() == '+' || token.front() == '-')) {
    negative = token.front() == '-';
    token.remove_prefix(1);
  }
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
    if (e.empty() || digit_run(e) != e.size()) return RationalParse::not_rational;
    for (char c : e) {
      exponent = exponent * 10 + (c - '0');
      if (exponent > kMaxDecimalExponent) return RationalParse::huge;
    }
    if (e_negative) exponent = -exponent;
  }
  const std::size_t point = mantissa.find('.');
  const std::string_view whole = mantissa.substr(0, point);
  const std::string_view fraction = point == std::string_view::npos ? std::string_view() : mantissa.substr(point + 1);
  if (whole.empty() && fraction.empty()) return RationalParse::not_rational;
  if (digit_run(whole) != whole.size() || digit_run(fraction) != fraction.size()) return RationalParse::not_rational;
  if (whole.size() + fraction.size() > max_digits) return RationalParse::huge;
  // value = (the digits of whole and fraction as one integer) * 10^(exponent - #fraction digits)
  ScopedMpq r;
  mpz_ptr num = mpq_numref(r.q);
  mpz_ptr den = mpq_denref(r.q);
  mpz_set_str(num, (std::string(whole) + std::string(fraction)).c_str(), 10);
  const long scale = exponent - static_cast<long>(fraction.size());
  mpz_ui_pow_ui(den, 10, static_cast<unsigned long>(scale >= 0 ? scale : -scale));
  if (scale >= 0) {
    mpz_mul(num, num, den);
    mpz_set_ui(den, 1);
  }
  mpq_canonicalize(r.q);
  if (negative) mpq_neg(r.q, r.q);
  value = CGAL::Gmpq(r.q);
  return RationalParse::ok;
}

bool beyond_double_range(const CGAL::Gmpq& q) {
  static const CGAL::Gmpq largest(std::numeric_limits<double>::max());  // exact: a double is a rational
  return q > largest || q < -largest;
}

bool exact_double(const CGAL::Gmpq& q, double& d) {
  mpz_srcptr num = mpq_numref(q.mpq());
  mpz_srcptr den = mpq_denref(q.mpq());
  if (mpz_sgn(num) == 0) {
    d = 0.0;
    return true;
  }
  // Lowest terms: q = num / 2^k with num odd when k > 0, or an integer (k = 0).
  const long k = static_cast<long>(mpz_scan1(den, 0));
  if (mpz_sizeinbase(den, 2) != static_cast<std::size_t>(k) + 1) return false;  // not a power of two
  const long low = static_cast<long>(mpz_scan1(num, 0)) - k;                    // exponent of the lowest bit
  const long bits = static_cast<long>(mpz_sizeinbase(num, 2));
  const long high = bits - 1 - k;                                                  // exponent of the highest bit
  constexpr int kDigits = std::numeric_limits<double>::digits;                     // 53
  constexpr int kMaxExponent = std::numeric_limits<double>::max_exponent - 1;      // 1023
  constexpr int kLowestBit = std::numeric_limits<double>::min_exponent - kDigits;  // -1074
  if (high - low + 1 > kDigits || low < kLowestBit || high > kMaxExponent) return false;
  // num has at most 53 significant bits and |num| < 2^1024: mpz_get_d is exact, and so is
  // the scaling, whose result keeps every bit (its lowest at 2^-1074 or above).
  d = std::ldexp(mpz_get_d(num), static_cast<int>(-k));
  return true;
}

}  // namespace arrangements::detail
