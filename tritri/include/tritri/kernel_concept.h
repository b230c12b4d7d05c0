// tritri/kernel_concept.h
//
// The kernel concept: everything tritri::classify asks of a number representation.
//
// A kernel K provides
//   K::Point                                  a point type (copyable)
//   k.orient3d(a, b, c, d) -> Sign            sign of det[b-a; c-a; d-a]: Positive when d
//                                             lies on the side of plane abc that the normal
//                                             (b-a) x (c-a) points to (CGAL's convention;
//                                             Shewchuk's orient3d returns the opposite).
//   k.orient2d(a, b, c, plane) -> Sign        sign of det[b-a; c-a] in the projection onto
//                                             `plane` (see Plane): Positive when a, b, c turn
//                                             counter-clockwise there.
//   k.equal(a, b) -> bool                     exact coincidence.
// and optionally
//   k.less(a, b) -> bool                      exact lexicographic (x, y, z) order.
//
// All of them must be exact for every input the kernel accepts. The functions may be
// static (called through a default-constructed K) or members (stateful kernels such as
// CountingKernel).
#pragma once

#include <concepts>

#include "tritri/sign.h"

namespace tritri {

template <class K>
concept Kernel = std::copy_constructible<typename K::Point> &&
    requires(const K& k, const typename K::Point& p, Plane plane) {
  { k.orient3d(p, p, p, p) } -> std::same_as<Sign>;
  { k.orient2d(p, p, p, plane) } -> std::same_as<Sign>;
  { k.equal(p, p) } -> std::convertible_to<bool>;
};

template <class K>
concept OrderedKernel = Kernel<K> && requires(const K& k, const typename K::Point& p) {
  { k.less(p, p) } -> std::convertible_to<bool>;
};

}  // namespace tritri
