// arrangements/src/booleans/fan_order.h (internal to the Boolean stage)
//
// order_around_axis(a, b, r, c, items, reference_item, orient, opposite): sorts `items` (indices
// into c) by the angle of c[i] around the line through a and b, measured from the
// half-plane of r, increasing in the direction in which orient(a, b, c[i], c[j]) is
// Positive for c[j] just after c[i]. Angle 0 is the item reference_item (whose point is
// r; -1 when r is not an item), then the open half-turn where orient(a, b, r, c) > 0, the
// half-plane opposite r (orient 0), then the other half-turn. opposite (optional, per
// index of c): items known to lie in the half-plane opposite r (e.g. pieces of the
// reference's own input triangle), placed there without an orient call: an exact zero is
// the costliest case of a filtered predicate.
// Precondition: no two items in one half-plane bounded by the line (the triangles of an
// arrangement around an edge never overlap), none on the line.
// Exact as orient is; O(k log k) orient calls for k items.
#pragma once

#include <algorithm>
#include <vector>

#include <tritri/sign.h>

namespace arrangements {

template <class P, class Orient>
void order_around_axis(const P& a, const P& b, const P& r, const std::vector<const P*>& c, std::vector<int>& items,
                       int reference_item, Orient orient, const std::vector<char>* opposite = nullptr) {
  // 0: the reference, 1: (0, pi), 2: pi, 3: (pi, 2 pi)
  std::vector<std::pair<int, int>> keyed;  // (class, item)
  keyed.reserve(items.size());
  for (int i : items) {
    int cls = 0;
    if (opposite && (*opposite)[i]) {
      cls = 2;
    } else if (i != reference_item) {
      const tritri::Sign s = orient(a, b, r, *c[i]);
      cls = s == tritri::Sign::Positive ? 1 : s == tritri::Sign::Zero ? 2 : 3;
    }
    keyed.emplace_back(cls, i);
  }
  std::sort(keyed.begin(), keyed.end(), [&](const std::pair<int, int>& x, const std::pair<int, int>& y) {
    if (x.first != y.first) return x.first < y.first;
    if (x.second == y.second || x.first == 0 || x.first == 2) return false;
    return orient(a, b, *c[x.second], *c[y.second]) == tritri::Sign::Positive;
  });
  for (std::size_t k = 0; k < items.size(); ++k) items[k] = keyed[k].second;
}

}  // namespace arrangements
