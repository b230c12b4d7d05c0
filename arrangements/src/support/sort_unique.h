// arrangements/src/support/sort_unique.h
//
// sort_unique(v): sorts v and removes repeated elements (the graph's lists are kept sorted
// and unique, so that the result does not depend on the order they were filled in).
// Cost: O(n log n).
#pragma once

#include <algorithm>
#include <vector>

namespace arrangements {

template <class T>
void sort_unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace arrangements
