// The grids round_safe rounds to (round_mesh.h) and the displacement bound it reports:
// shared by the passes of rounding and arranging (round_to_grid.h, round_ladder.h) and the
// last resorts.
#pragma once

#include <CGAL/Gmpq.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <vector>

#include <cmath>
#include <limits>

#include "arrangements/triangle_soup.h"

namespace arrangements {

// The uniform grid of spacing 2^k units in the last place of `largest` (the largest
// coordinate magnitude; 1 when it is 0). For k < 53 every multiple of it below 2^53
// spacings is a double.
inline double grid_spacing(double largest, int k) {
  int exponent = 0;
  std::frexp(largest > 0 ? largest : 1.0, &exponent);  // largest < 2^exponent
  return std::ldexp(1.0, exponent - std::numeric_limits<double>::digits + k);
}

// Every coordinate of `nearest` to the nearest multiple of h (h = 0: unchanged). The
// quotient by a power of two and its rounding to an integer are exact.
inline Vec3 round_point(const Vec3& nearest, double h) {
  if (h == 0) return nearest;
  Vec3 out;
  for (int k = 0; k < 3; ++k) out[k] = std::nearbyint(nearest[k] / h) * h;
  return out;
}

// An upper bound of the distance between rational q and double point p (the coordinate
// differences are exact rationals; the factor and one ulp cover to_double, the scaling, the
// squares, the sum, the root and the product). The differences are divided by the largest
// one, m, before squaring: unscaled, squares overflow for moves above 2^512 (models beyond
// about 2^564) and lose digits or vanish below 2^-511, so the bound holds at any magnitude.
inline double distance_bound(const ExactVec3& q, const Vec3& p) {
  double d[3];
  for (int k = 0; k < 3; ++k) d[k] = std::abs(CGAL::to_double(q[k] - CGAL::Gmpq(p[k])));
  const double m = std::max({d[0], d[1], d[2]});
  if (m == 0) return 0.0;
  if (!std::isfinite(m)) return std::numeric_limits<double>::infinity();  // beyond the double range
  double sum = 0;  // in [1, 3]
  for (double dk : d) sum += (dk / m) * (dk / m);
  return std::nextafter(m * std::sqrt(sum) * (1 + 8 * std::numeric_limits<double>::epsilon()),
                        std::numeric_limits<double>::infinity());
}

// The largest coordinate magnitude of V (0 for none): the L whose ulps the grids count.
inline double largest_magnitude(const std::vector<Vec3>& V) {
  double largest = 0;
  for (const Vec3& p : V)
    for (double c : p) largest = std::max(largest, std::abs(c));
  return largest;
}

// The largest distance_bound between exact[v] and position[v] over all v (0 for none).
inline double largest_distance(const std::vector<ExactVec3>& exact, const std::vector<Vec3>& position) {
  std::vector<double> move(exact.size());
  tbb::parallel_for(std::size_t{0}, exact.size(),
                    [&](std::size_t v) { move[v] = distance_bound(exact[v], position[v]); });
  return move.empty() ? 0.0 : *std::max_element(move.begin(), move.end());
}

}  // namespace arrangements
