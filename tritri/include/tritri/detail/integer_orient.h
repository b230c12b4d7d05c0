// tritri/detail/integer_orient.h
//
// Exact orientation signs with 128-bit integers, for the common case where the coordinate
// differences are exact doubles whose significant bits span a narrow window (integer
// grids, float-valued mesh coordinates, dyadic rationals). Every difference is then an
// integer multiple of one power of two, and the determinant of those integers fits in a
// signed 128-bit integer: orient3d needs at most 41 bits per difference (|det| < 2^126),
// orient2d at most 61 (|det| < 2^123).
#pragma once

#include <cstdint>
#include <cstring>

namespace tritri::detail {

// 2^e as a double, for e in the normal range.
inline double power_of_two(int e) noexcept {
  const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52;
  double d;
  std::memcpy(&d, &bits, sizeof d);
  return d;
}

// Converts the exact differences d[0..N) (normal or zero) to integers m[i] = d[i] * 2^s
// with |m[i]| < 2^max_bits, where s puts the largest magnitude just below 2^max_bits.
// Returns false when some d[i] * 2^s is not an integer (its bits span too wide a window).
template <int N>
bool to_integers(const double (&d)[N], int max_bits, std::int64_t (&m)[N]) noexcept {
  double largest = 0;
  for (int i = 0; i < N; ++i) {
    const double a = d[i] < 0 ? -d[i] : d[i];
    largest = a > largest ? a : largest;
  }
  if (largest == 0) {
    for (auto& x : m) x = 0;
    return true;
  }
  std::uint64_t bits;
  std::memcpy(&bits, &largest, sizeof bits);
  const int top = static_cast<int>((bits >> 52) & 0x7ff) - 1023;  // largest < 2^(top+1)
  const double scale = power_of_two(max_bits - 1 - top);          // exact scaling
  for (int i = 0; i < N; ++i) {
    const double x = d[i] * scale;
    m[i] = static_cast<std::int64_t>(x);  // |x| < 2^max_bits <= 2^62: no overflow
    if (static_cast<double>(m[i]) != x) return false;
  }
  return true;
}

__extension__ typedef __int128 int128;  // GCC / Clang builtin ; __extension__ keeps -Wpedantic quiet

inline int sign128(int128 v) noexcept { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

// Sign of det[u; v; w] for exact differences (u0 u1 u2 v0 v1 v2 w0 w1 w2); returns 2 when
// they do not fit the integer window.
inline int det3_sign_integer(const double (&d)[9]) noexcept {
  std::int64_t m[9];
  if (!to_integers<9>(d, 41, m)) return 2;
  using I = int128;
  const I m0 = I(m[4]) * m[8] - I(m[5]) * m[7];
  const I m1 = I(m[5]) * m[6] - I(m[3]) * m[8];
  const I m2 = I(m[3]) * m[7] - I(m[4]) * m[6];
  return sign128(m0 * m[0] + m1 * m[1] + m2 * m[2]);
}

// Sign of det[u; v] for exact differences (u0 u1 v0 v1); 2 when they do not fit.
inline int det2_sign_integer(const double (&d)[4]) noexcept {
  std::int64_t m[4];
  if (!to_integers<4>(d, 61, m)) return 2;
  return sign128(int128(m[0]) * m[3] - int128(m[1]) * m[2]);
}

}  // namespace tritri::detail
