// arrangements/src/support/model_order.h
//
// ids_in_model_order<M>(n, point_at, key): the ids 0 .. n-1 sorted by the model's exact
// total order on points (M::compare, with M::key computed once per point into `key`,
// resized to n), ties (coincident points) by id, so the result does not depend on
// scheduling. point_at(i) returns point i (a const M::Point&). Stages 4 and 5 sort their
// new points (LPIs, TPIs) and the input vertices this way, then find coincident points
// as neighbours in one list and matches between two lists by merge or binary search.
// Exactness: M::compare is exact (DoubleModel: certified bounds along a direction, points
// equal by construction, then exact arithmetic). Cost: n keys and O(n log n) comparisons,
// in parallel (oneTBB, the caller's arena).
#pragma once

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <cstddef>
#include <numeric>
#include <vector>

namespace arrangements {

template <class M, class PointAt>
std::vector<int> ids_in_model_order(std::size_t n, const PointAt& point_at, std::vector<typename M::Key>& key) {
  key.resize(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) { key[i] = M::key(point_at(i)); });
  std::vector<int> ids(n);
  std::iota(ids.begin(), ids.end(), 0);
  tbb::parallel_sort(ids.begin(), ids.end(), [&](int a, int b) {
    const int c = M::compare(point_at(static_cast<std::size_t>(a)), key[static_cast<std::size_t>(a)],
                             point_at(static_cast<std::size_t>(b)), key[static_cast<std::size_t>(b)]);
    return c != 0 ? c < 0 : a < b;
  });
  return ids;
}

}  // namespace arrangements
