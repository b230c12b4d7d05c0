// arrangements/src/support/union_find.h
//
// UnionFind(n): disjoint sets over 0..n-1 with path halving and union by index (the
// smaller root wins, so the roots do not depend on the order of unions of one set).
// find and unite: amortised near O(1). Not thread-safe.
#pragma once

#include <numeric>
#include <vector>

namespace arrangements {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a < b) parent_[b] = a;
    else if (b < a) parent_[a] = b;
  }

 private:
  std::vector<int> parent_;
};

}  // namespace arrangements
