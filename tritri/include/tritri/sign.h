// tritri/sign.h
//
// Small enums returned and taken by the exact predicates: an orientation sign and
// the axis-aligned plane an orient2d projects onto.
#pragma once

#include <array>
#include <cstdint>

namespace tritri {

// Sign of an exact determinant. Predicates return this, never a raw number, so that
// callers cannot compare against a tolerance by accident.
enum class Sign : std::int8_t { Negative = -1, Zero = 0, Positive = 1 };

// The projection used by orient2d: the plane the points are projected onto.
// The 2D coordinates are cyclic so every projection keeps the orientation seen from
// the positive side of the dropped axis:
//   XY -> (x, y) seen from +z,  YZ -> (y, z) seen from +x,  ZX -> (z, x) seen from +y.
enum class Plane : std::int8_t { XY = 0, YZ = 1, ZX = 2 };

// The two axes of a projection, in its order (XY -> {0, 1}, YZ -> {1, 2}, ZX -> {2, 0}).
constexpr std::array<int, 2> plane_axes(Plane plane) noexcept {
  const int i = static_cast<int>(plane);
  return {i, (i + 1) % 3};
}

constexpr int to_int(Sign s) noexcept { return static_cast<int>(s); }
constexpr Sign operator-(Sign s) noexcept { return static_cast<Sign>(-static_cast<int>(s)); }
constexpr Sign operator*(Sign a, Sign b) noexcept {
  return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b));
}

}  // namespace tritri
