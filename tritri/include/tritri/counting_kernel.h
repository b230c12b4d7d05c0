// tritri/counting_kernel.h
//
// CountingKernel<K>: wraps a kernel and counts its predicate calls, for benchmarks and
// for comparing classifiers. Stateful: pass an instance to classify(k, ...).
//
//   tritri::PredicateCounts counts;
//   tritri::CountingKernel<tritri::DoubleKernel> k(counts);
//   auto r = tritri::classify(k, a0, a1, a2, b0, b1, b2);   // counts.orient3d, ...
//
// Not thread-safe on one PredicateCounts; give each thread its own.
#pragma once

#include <cstdint>

#include "tritri/kernel_concept.h"

namespace tritri {

struct PredicateCounts {
  std::uint64_t orient3d = 0;
  std::uint64_t orient2d = 0;
  std::uint64_t equal = 0;
  std::uint64_t less = 0;
  std::uint64_t total() const noexcept { return orient3d + orient2d + equal + less; }
};

template <Kernel K>
class CountingKernel {
 public:
  using Point = typename K::Point;

  explicit CountingKernel(PredicateCounts& counts, K inner = K{}) : counts_(&counts), inner_(inner) {}

  Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d) const {
    ++counts_->orient3d;
    return inner_.orient3d(a, b, c, d);
  }
  Sign orient2d(const Point& a, const Point& b, const Point& c, Plane plane) const {
    ++counts_->orient2d;
    return inner_.orient2d(a, b, c, plane);
  }
  bool equal(const Point& a, const Point& b) const {
    ++counts_->equal;
    return inner_.equal(a, b);
  }
  bool less(const Point& a, const Point& b) const requires OrderedKernel<K> {
    ++counts_->less;
    return inner_.less(a, b);
  }

 private:
  PredicateCounts* counts_;
  K inner_;
};

}  // namespace tritri
