// arrangements/src/io/rational_token.h (internal to the mesh readers: SoupBuilder, for
// load_mesh_files and read_exact_mesh)
//
// The rational coordinate tokens that write_mesh writes with exact = true, and the tests a
// loader makes on their values.
//
// RationalParse parse_rational(token, value)
//   token       one whitespace-free token, of any length
//   value       receives the rational, in lowest terms (only when ok is returned)
// returns ok for [+-]? digits "/" digits with a denominator that is not zero ("2/6" is
// 1/3, "-0/5" is 0); not_rational for any other token (decimals too: "1", "1.5/2", "1/",
// "/2", "1/2/3", "0x1/3"); zero_denominator for "N/0". No limit on the digits: the value's
// size is that of its text (what write_mesh writes can always be read back).
// Cost: linear in the token's length for the checks; GMP's conversion of the digits
// and its reduction to lowest terms (both subquadratic) for ok.
//
// RationalParse parse_exact_decimal(token, value, max_digits = no limit)
//   The exact value of a decimal token, [+-]? ( digits ( "." digits? )? | "." digits )
//   ( [eE] [+-]? digits )? ("0.1" is 1/10, not the double nearest to it): ok; not_rational
//   for any other token; huge when it has more than max_digits digits (leading zeros
//   count) or an exponent beyond +-kMaxDecimalExponent (larger ones make numbers far
//   larger than their text; no double needs one).
//
// bool beyond_double_range(q): |q| > the largest finite double (DBL_MAX), exactly.
//
// bool exact_double(q, d): true, with d = q, when the rational q is exactly a double
// (a dyadic rational n / 2^k with at most 53 significant bits, its lowest bit at 2^-1074
// or above, and |q| <= DBL_MAX); false otherwise (d untouched). Zero gives +0.0.
// Cost: O(size of q) bit scans; no rounding anywhere.
#pragma once

#include <CGAL/Gmpq.h>

#include <cstddef>
#include <limits>
#include <string_view>

namespace arrangements::detail {

enum class RationalParse { ok, not_rational, huge, zero_denominator };

inline constexpr long kMaxDecimalExponent = 4096;

RationalParse parse_rational(std::string_view token, CGAL::Gmpq& value);

RationalParse parse_exact_decimal(std::string_view token, CGAL::Gmpq& value,
                                  std::size_t max_digits = std::numeric_limits<std::size_t>::max());

bool beyond_double_range(const CGAL::Gmpq& q);

bool exact_double(const CGAL::Gmpq& q, double& d);

}  // namespace arrangements::detail
