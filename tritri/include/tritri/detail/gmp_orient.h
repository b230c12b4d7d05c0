// tritri/detail/gmp_orient.h
//
// Exact orientation signs on doubles with GMP integers: the last-resort stage of the
// double backend, used when coordinates are so large or so small (subnormal included)
// that expansion arithmetic could overflow or underflow.
//
// Every finite double is m * 2^e with an integer m; shifting all inputs to the smallest
// exponent turns them into integers, and a common positive scale does not change a sign.
// Exact for every finite input. Cost: a few microseconds.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>

namespace tritri::detail {

// Scales a list of doubles to exact GMP integers (all multiplied by one power of two).
template <int N>
void doubles_to_common_integers(const double (&x)[N], mpz_class (&out)[N]) {
  int mant_exp[N];
  std::int64_t mant[N];
  int min_exp = INT_MAX;
  for (int i = 0; i < N; ++i) {
    int e = 0;
    const double m = std::frexp(x[i], &e);  // x = m * 2^e, 0.5 <= |m| < 1
    mant[i] = static_cast<std::int64_t>(std::ldexp(m, 53));
    mant_exp[i] = e - 53;
    if (x[i] != 0) min_exp = std::min(min_exp, mant_exp[i]);
  }
  for (int i = 0; i < N; ++i) {
    out[i] = static_cast<long>(mant[i]);
    if (x[i] != 0) out[i] <<= static_cast<unsigned long>(mant_exp[i] - min_exp);
  }
}

inline int mpz_sign(const mpz_class& v) { return sgn(v); }

// Sign of det[b-a; c-a; d-a] for points given as 12 doubles (ax ay az bx ... dz).
inline int orient3d_gmp(const double (&p)[12]) {
  mpz_class z[12];
  doubles_to_common_integers<12>(p, z);
  const mpz_class ux = z[3] - z[0], uy = z[4] - z[1], uz = z[5] - z[2];
  const mpz_class vx = z[6] - z[0], vy = z[7] - z[1], vz = z[8] - z[2];
  const mpz_class wx = z[9] - z[0], wy = z[10] - z[1], wz = z[11] - z[2];
  const mpz_class det = ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
  return mpz_sign(det);
}

// Sign of det[b-a; c-a] for 2D points given as 6 doubles (ax ay bx by cx cy).
inline int orient2d_gmp(const double (&p)[6]) {
  mpz_class z[6];
  doubles_to_common_integers<6>(p, z);
  const mpz_class det = (z[2] - z[0]) * (z[5] - z[1]) - (z[3] - z[1]) * (z[4] - z[0]);
  return mpz_sign(det);
}

}  // namespace tritri::detail
