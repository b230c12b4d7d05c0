// tests/support/test_scale.h
//
// The two environment knobs of the generated tests, read in this one place:
//   test_scale()        TRITRI_TEST_SCALE, a positive factor for case counts and sizes
//                       (default 1.0; the sanitizer CI uses 0.1); unset, empty, not a
//                       number, not positive or not finite: 1.0
//   scaled_count(n)     n times the scale, rounded, at least 1
//   scaled_down()       the scale is below 1 (the sanitizer stage): the longest tests
//                       drop their largest inputs
//   seed_for(salt)      a seed per test: TRITRI_TEST_SEED (an integer) or the default
//                       base, mixed with the test's salt, so that one variable changes
//                       every seed while runs stay reproducible
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace tritri_test {

inline double test_scale() {
  const char* s = std::getenv("TRITRI_TEST_SCALE");
  if (s == nullptr || *s == '\0') return 1.0;
  char* end = nullptr;
  const double v = std::strtod(s, &end);
  return (end != s && v > 0 && std::isfinite(v)) ? v : 1.0;
}

inline long long scaled_count(long long n) {
  return std::max<long long>(1, std::llround(static_cast<double>(n) * test_scale()));
}

inline bool scaled_down() { return test_scale() < 1; }

// The default base is the one the implicit-point tests were written with; a test whose
// cases were tuned with another base passes it (so its inputs stay what they were).
inline std::uint64_t seed_for(std::uint64_t salt, std::uint64_t default_base = 20240917u) {
  const char* s = std::getenv("TRITRI_TEST_SEED");
  const std::uint64_t base = (s != nullptr && *s != '\0') ? std::strtoull(s, nullptr, 10) : default_base;
  return base * 0x9E3779B97F4A7C15ull + salt;
}

}  // namespace tritri_test
