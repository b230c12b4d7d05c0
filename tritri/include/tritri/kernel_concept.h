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
//   k.orient3d_each(a, b, c, d0, d1, d2, s)   s[j] = orient3d(a, b, c, dj) for j = 0, 1, 2
//                                             (Sign s[3]): a kernel may share the plane's
//                                             normal between the three (DoubleKernel does).
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

// s[j] = orient3d(a, b, c, dj) for j = 0, 1, 2: k.orient3d_each where the kernel has it,
// else three orient3d calls (so a CountingKernel still counts three). The signs go out
// through an array, not returned as one 3-byte value: unpacking that costs a
// store-forwarding stall per call.
template <Kernel K>
void orient3d_each(const K& k, const typename K::Point& a, const typename K::Point& b, const typename K::Point& c,
                   const typename K::Point& d0, const typename K::Point& d1, const typename K::Point& d2,
                   Sign (&s)[3]) {
  if constexpr (requires { k.orient3d_each(a, b, c, d0, d1, d2, s); }) {
    k.orient3d_each(a, b, c, d0, d1, d2, s);
  } else {
    s[0] = k.orient3d(a, b, c, d0);
    s[1] = k.orient3d(a, b, c, d1);
    s[2] = k.orient3d(a, b, c, d2);
  }
}

}  // namespace tritri
