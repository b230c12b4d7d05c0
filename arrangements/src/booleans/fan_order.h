// arrangements/src/booleans/fan_order.h (internal to the Boolean stage)
//
// order_around_axis(items, reference_item, side, opposite): sorts `items` (indices of
// half-planes bounded by one oriented line ab) by their angle around the line, measured
// from a reference half-plane, increasing in the direction in which side(i, j) is Positive
// for j just after i. side(i, j) is the sign of orient3d(a, b, p_i, p_j) for points p_i,
// p_j of the half-planes i and j off the line; i is reference_item, an item, or -1 for
// the reference when it is not an item (reference_item == -1). Angle 0 is the reference,
// then the open half-turn where side(reference_item, i) > 0, the half-plane opposite the
// reference (side 0), then the other half-turn. opposite (optional, per item): items known
// to lie in the half-plane opposite the reference (e.g. pieces of the reference's own
// input triangle), placed there without a side call: an exact zero is the costliest case
// of a filtered predicate.
// Precondition: no two items in one half-plane (the triangles of an arrangement around an
// edge never overlap).
// Exact as side is; O(k log k) side calls for k items.
#pragma once

#include <algorithm>
#include <vector>

#include <tritri/sign.h>

namespace arrangements {

template <class Side>
void order_around_axis(std::vector<int>& items, int reference_item, Side side,
                       const std::vector<char>* opposite = nullptr) {
  // 0: the reference, 1: (0, pi), 2: pi, 3: (pi, 2 pi)
  std::vector<std::pair<int, int>> keyed;  // (class, item)
  keyed.reserve(items.size());
  for (int i : items) {
    int cls = 0;
    if (opposite && (*opposite)[i]) {
      cls = 2;
    } else if (i != reference_item) {
      const tritri::Sign s = side(reference_item, i);
      cls = s == tritri::Sign::Positive ? 1 : s == tritri::Sign::Zero ? 2 : 3;
    }
    keyed.emplace_back(cls, i);
  }
  std::sort(keyed.begin(), keyed.end(), [&](const std::pair<int, int>& x, const std::pair<int, int>& y) {
    if (x.first != y.first) return x.first < y.first;
    if (x.second == y.second || x.first == 0 || x.first == 2) return false;
    return side(x.second, y.second) == tritri::Sign::Positive;
  });
  for (std::size_t k = 0; k < items.size(); ++k) items[k] = keyed[k].second;
}

}  // namespace arrangements
