// tests/support/random_turns.h
//
// Random turns for the tests that place bodies by rotations rounded to doubles (the safe
// rounding tests): std::mt19937's output is fixed by the standard, its distributions are
// not, so these draw from the raw output and give the same turns on every platform.
//   unit_axis(rng)   a unit vector, uniform in direction (rejection from the unit ball,
//                    away from 0)
//   turn_angle(rng)  an angle in [0, 2 pi)
#pragma once

#include <cmath>
#include <numbers>
#include <random>

#include "arrangements/triangle_soup.h"

namespace tritri_test {

inline arrangements::Vec3 unit_axis(std::mt19937& rng) {
  for (;;) {
    arrangements::Vec3 v;
    for (double& c : v) c = 2.0 * rng() / 4294967296.0 - 1.0;
    const double n = std::hypot(v[0], v[1], v[2]);
    if (n > 0.1 && n <= 1) return {v[0] / n, v[1] / n, v[2] / n};
  }
}

inline double turn_angle(std::mt19937& rng) { return 2 * std::numbers::pi * (rng() / 4294967296.0); }

}  // namespace tritri_test
