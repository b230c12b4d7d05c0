// tests/test_double_predicates_properties.cpp
//
// Exact properties of tritri::orient3d / tritri::orient2d on doubles, without the oracle,
// on a mixture of the generated families (support/orient_cases.h): the sign follows the
// permutation parity of the points; negating one axis flips it, negating all multiplies
// it by (-1)^N, swapping two axes flips it; exact power-of-two scalings per axis and
// exact translations keep it.
// Case counts scale with TRITRI_TEST_SCALE; TRITRI_TEST_SEED changes the seeds.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "support/orient_cases.h"
#include "support/test_scale.h"

namespace {

using namespace tritri_test::orient;

// ---------------------------------------------------------------------------------------
// Exact properties, without the oracle.

TEST(Orient3dProperties, SignFollowsPermutationParity) {
  Rng r(orient_seed(300));
  std::array<int, 4> perm0 = {0, 1, 2, 3};
  for (long i = 0, n = tritri_test::scaled_count(20000); i < n; ++i) {
    const Case<3> p = mixed_case<3>(r);
    const int s = sign_of(tritri_sign(p));
    std::array<int, 4> perm = perm0;
    do {
      int inversions = 0;
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b) inversions += perm[a] > perm[b];
      const Case<3> q = {p[perm[0]], p[perm[1]], p[perm[2]], p[perm[3]]};
      const int parity = inversions % 2 ? -1 : 1;
      ASSERT_EQ(sign_of(tritri_sign(q)), parity * s)
          << describe(p) << " permuted " << perm[0] << perm[1] << perm[2] << perm[3];
    } while (std::next_permutation(perm.begin(), perm.end()));
  }
}

TEST(Orient2dProperties, SignFollowsPermutationParity) {
  Rng r(orient_seed(301));
  for (long i = 0, n = tritri_test::scaled_count(50000); i < n; ++i) {
    const Case<2> p = mixed_case<2>(r);
    const int s = sign_of(tritri_sign(p));
    // Cyclic rotations keep the sign, transpositions flip it.
    ASSERT_EQ(sign_of(tritri_sign(Case<2>{p[1], p[2], p[0]})), s) << describe(p);
    ASSERT_EQ(sign_of(tritri_sign(Case<2>{p[2], p[0], p[1]})), s) << describe(p);
    ASSERT_EQ(sign_of(tritri_sign(Case<2>{p[1], p[0], p[2]})), -s) << describe(p);
    ASSERT_EQ(sign_of(tritri_sign(Case<2>{p[0], p[2], p[1]})), -s) << describe(p);
    ASSERT_EQ(sign_of(tritri_sign(Case<2>{p[2], p[1], p[0]})), -s) << describe(p);
  }
}

// Applies f to every coordinate and reports whether every result is exact (as checked
// by the rational f_exact) so the transformed case has a predictable sign.
template <std::size_t N, class F, class FExact>
bool transform_exactly(const Case<N>& p, Case<N>& out, F f, FExact f_exact) {
  for (std::size_t i = 0; i <= N; ++i)
    for (std::size_t k = 0; k < N; ++k) {
      out[i][k] = f(p[i][k], k);
      if (!std::isfinite(out[i][k]) || mpq_class(out[i][k]) != f_exact(mpq_class(p[i][k]), k)) return false;
    }
  return true;
}

mpq_class times_power_of_two(const mpq_class& x, int e) {
  mpq_class y = x;
  if (e >= 0)
    mpq_mul_2exp(y.get_mpq_t(), y.get_mpq_t(), static_cast<unsigned long>(e));
  else
    mpq_div_2exp(y.get_mpq_t(), y.get_mpq_t(), static_cast<unsigned long>(-e));
  return y;
}

template <std::size_t N>
void check_exact_transformations(Rng& r, long n) {
  const int odd = N == 3 ? -1 : 1;  // sign factor of negating all N coordinates
  long scaled_checked = 0, translated_checked = 0;
  for (long i = 0; i < n; ++i) {
    const Case<N> p = mixed_case<N>(r);
    const int s = sign_of(tritri_sign(p));
    Case<N> q{};

    // Negating one axis flips the sign; negating all multiplies it by (-1)^N.
    const int axis = static_cast<int>(r.integer(0, N - 1));
    for (std::size_t j = 0; j <= N; ++j) {
      q[j] = p[j];
      q[j][axis] = -q[j][axis];
    }
    ASSERT_EQ(sign_of(tritri_sign(q)), -s) << describe(p) << " axis " << axis << " negated";
    for (std::size_t j = 0; j <= N; ++j)
      for (std::size_t k = 0; k < N; ++k) q[j][k] = -p[j][k];
    ASSERT_EQ(sign_of(tritri_sign(q)), odd * s) << describe(p) << " negated";

    // Swapping two axes flips the sign.
    for (std::size_t j = 0; j <= N; ++j) {
      q[j] = p[j];
      std::swap(q[j][0], q[j][N - 1]);
    }
    ASSERT_EQ(sign_of(tritri_sign(q)), -s) << describe(p) << " axes swapped";

    // Positive power-of-two scaling per axis keeps the sign (when it is exact).
    int e[N];
    for (std::size_t k = 0; k < N; ++k) e[k] = static_cast<int>(r.integer(-300, 300));
    if (transform_exactly<N>(
            p, q, [&](double x, int k) { return std::ldexp(x, e[k]); },
            [&](const mpq_class& x, int k) { return times_power_of_two(x, e[k]); })) {
      ++scaled_checked;
      ASSERT_EQ(sign_of(tritri_sign(q)), s) << describe(p) << " scaled to " << describe(q);
    }

    // Translation keeps the sign (when every translated coordinate is exact).
    double t[N];
    for (std::size_t k = 0; k < N; ++k) {
      const int shift = std::min(1000, axis_exponent(p, k) - static_cast<int>(r.integer(-8, 30)));
      t[k] = r.sign() * std::ldexp(static_cast<double>(r.integer(1, 255)), shift);
    }
    if (transform_exactly<N>(
            p, q, [&](double x, int k) { return x + t[k]; },
            [&](const mpq_class& x, int k) { return mpq_class(x + mpq_class(t[k])); })) {
      ++translated_checked;
      ASSERT_EQ(sign_of(tritri_sign(q)), s) << describe(p) << " translated to " << describe(q);
    }
  }
  // The generators must leave enough exact cases for the last two checks to mean something.
  EXPECT_GT(scaled_checked, n / 10);
  EXPECT_GT(translated_checked, n / 20);
  std::printf("[ stats    ] exact scalings checked %ld, exact translations checked %ld of %ld\n", scaled_checked,
              translated_checked, n);
}

TEST(Orient3dProperties, ExactNegationsAxisSwapsScalingsAndTranslationsActAsExpected) {
  Rng r(orient_seed(302));
  check_exact_transformations<3>(r, tritri_test::scaled_count(20000));
}

TEST(Orient2dProperties, ExactNegationsAxisSwapsScalingsAndTranslationsActAsExpected) {
  Rng r(orient_seed(303));
  check_exact_transformations<2>(r, tritri_test::scaled_count(20000));
}

}  // namespace
