// tritri/direction_slabs.h
//
// A broad-phase test for pairs of triangles whose bounding boxes overlap: the triangles'
// extents along the 10 directions (1,1,0), (1,-1,0), (0,1,1), (0,1,-1), (1,0,1), (1,0,-1),
// (1,1,1), (1,1,-1), (1,-1,1), (-1,1,1). With the box, these bound a triangle by a
// 26-sided polytope (a 26-DOP) instead of a box, which matters for long thin triangles
// lying across their boxes' diagonals: on EMBER 79741+65004 (16,206 triangles) the box
// search yields 16.7 M pairs and this test rejects 16.3 M of them.
//   DirectionSlabs s = direction_slabs(p, q, r);   // p, q, r: double corners
//   DirectionSlabs s = direction_slabs(lo, hi);    // corners known by boxes lo[k]..hi[k]
//   slabs_apart(s, t)    // true: apart along one direction, so the triangles do not meet
//   apart_by_slabs(a, b, s, t)   // the same for triangles a, b (corner indices) sharing no corner
//   triangle_slab(Vlo, Vhi, f), triangle_slabs(Vlo, Vhi, F)   // one triangle's, every triangle's (parallel)
//   TriangleSlabsOnDemand slabs(Vlo, Vhi, F); slabs.apart(i, j)   // each computed on first use
// Exactness: a certified filter. Each extent is computed in double arithmetic and widened
// by 2^-50 (|x| + |y| + |z|) + 2^-1074 of its point; this exceeds the rounding of the sum
// of two or three coordinates plus that of the widening subtraction (at most 3 ulps of
// |x| + |y| + |z| together, in any rounding mode); sums of values below 2^-1021 are exact.
// A triangle with a coordinate of magnitude 2^1020 or more gets the whole line (its sums
// could overflow). The extents are then rounded outwards to floats. So each stored slab
// contains the exact extent of the triangle, and slabs_apart is true only when the exact
// extents are apart: a pair that touches, even at one point, is never rejected.
// Cost: about 70 flops per triangle, 96 bytes; slabs_apart is 6 four-wide compares.
#pragma once

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <span>
#include <vector>

namespace tritri {

struct DirectionSlabs {
  static constexpr int kDirections = 10;
  static constexpr int kLanes = 12;  // padded to whole 4-wide vectors: lo -inf, hi +inf
  alignas(16) std::array<float, kLanes> lo;
  alignas(16) std::array<float, kLanes> hi;
};

namespace detail {
// x rounded to a float at or below it (at or above it): the margin 2^-22 |x| + 2^-140
// exceeds a float conversion's error (2^-23 relative, 2^-149 absolute, in any rounding
// mode). Beyond float's range the bound is -inf (+inf), or the largest float on the other
// side (a conversion out of range would be undefined).
inline float float_below(double x) {
  constexpr double largest = std::numeric_limits<float>::max();
  const double v = x - std::abs(x) * 0x1p-22 - 0x1p-140;
  if (!(v >= -largest)) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(std::min(v, largest));
}
inline float float_above(double x) {
  constexpr double largest = std::numeric_limits<float>::max();
  const double v = x + std::abs(x) * 0x1p-22 + 0x1p-140;
  if (!(v <= largest)) return std::numeric_limits<float>::infinity();
  return static_cast<float>(std::max(v, -largest));
}

// The extents along DirectionSlabs' directions in doubles, each widened to contain the
// exact extent (the header's comment gives the bound).
struct DirectionExtents {
  std::array<double, DirectionSlabs::kDirections> lo, hi;
};
// Corners given as boxes [lo[k], hi[k]] (a point: lo[k] == hi[k]): the extents of every
// triangle with a corner in each box.
inline DirectionExtents direction_extents(const std::array<std::array<double, 3>, 3>& lo,
                                          const std::array<std::array<double, 3>, 3>& hi) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  DirectionExtents e;
  // Below 2^1020 no sum of three coordinates, nor a widening, overflows; above it (rare),
  // every extent is the whole line.
  double largest = 0;
  for (int k = 0; k < 3; ++k)
    for (int axis = 0; axis < 3; ++axis) largest = std::max({largest, std::abs(lo[k][axis]), std::abs(hi[k][axis])});
  if (!(largest < 0x1p1020)) {
    e.lo.fill(-inf);
    e.hi.fill(inf);
    return e;
  }
  e.lo.fill(inf);
  e.hi.fill(-inf);
  for (int k = 0; k < 3; ++k) {
    const double lx = lo[k][0], ly = lo[k][1], lz = lo[k][2], hx = hi[k][0], hy = hi[k][1], hz = hi[k][2];
    // The least and the greatest value over the box: a coordinate with coefficient +1 at
    // its low end for the least, -1 at its high end.
    const double least[DirectionSlabs::kDirections] = {lx + ly,        lx - hy,        ly + lz,        ly - hz,
                                                       lx + lz,        lx - hz,        (lx + ly) + lz, (lx + ly) - hz,
                                                       (lx - hy) + lz, (ly - hx) + lz};
    const double greatest[DirectionSlabs::kDirections] = {hx + hy,        hx - ly,        hy + hz,
                                                          hy - lz,        hx + hz,        hx - lz,
                                                          (hx + hy) + hz, (hx + hy) - lz, (hx - ly) + hz,
                                                          (hy - lx) + hz};
    const double size = std::max(std::abs(lx), std::abs(hx)) + std::max(std::abs(ly), std::abs(hy)) +
                        std::max(std::abs(lz), std::abs(hz));
    const double widen = size * 0x1p-50 + 0x1p-1074;
    for (int d = 0; d < DirectionSlabs::kDirections; ++d) {
      e.lo[d] = std::min(e.lo[d], least[d] - widen);
      e.hi[d] = std::max(e.hi[d], greatest[d] + widen);
    }
  }
  return e;
}

inline DirectionSlabs to_float_slabs(const DirectionExtents& e) {
  DirectionSlabs out;
  out.lo.fill(-std::numeric_limits<float>::infinity());
  out.hi.fill(std::numeric_limits<float>::infinity());
  for (int d = 0; d < DirectionSlabs::kDirections; ++d) {
    out.lo[d] = float_below(e.lo[d]);
    out.hi[d] = float_above(e.hi[d]);
  }
  return out;
}
}  // namespace detail

// The slabs of the triangle (p, q, r).
inline DirectionSlabs direction_slabs(const std::array<double, 3>& p, const std::array<double, 3>& q,
                                      const std::array<double, 3>& r) {
  const std::array<std::array<double, 3>, 3> corners{p, q, r};
  return detail::to_float_slabs(detail::direction_extents(corners, corners));
}

// The slabs of every triangle with a corner in each box [lo[k], hi[k]] (points known
// only by certified bounds, such as implicit points).
inline DirectionSlabs direction_slabs(const std::array<std::array<double, 3>, 3>& lo,
                                      const std::array<std::array<double, 3>, 3>& hi) {
  return detail::to_float_slabs(detail::direction_extents(lo, hi));
}

// The slabs of triangle f (corner indices) over vertex boxes [Vlo[v], Vhi[v]] (the same span
// for double points, which then take the points' own computation).
inline DirectionSlabs triangle_slab(std::span<const std::array<double, 3>> Vlo,
                                    std::span<const std::array<double, 3>> Vhi, const std::array<int, 3>& f) {
  if (Vlo.data() == Vhi.data()) return direction_slabs(Vlo[f[0]], Vlo[f[1]], Vlo[f[2]]);
  return direction_slabs({Vlo[f[0]], Vlo[f[1]], Vlo[f[2]]}, {Vhi[f[0]], Vhi[f[1]], Vhi[f[2]]});
}

// The slabs of every triangle of F (triangle_slab); in parallel (oneTBB, in the calling
// thread's arena).
inline std::vector<DirectionSlabs> triangle_slabs(std::span<const std::array<double, 3>> Vlo,
                                                  std::span<const std::array<double, 3>> Vhi,
                                                  std::span<const std::array<int, 3>> F) {
  std::vector<DirectionSlabs> slabs(F.size());
  tbb::parallel_for(std::size_t{0}, F.size(), [&](std::size_t t) { slabs[t] = triangle_slab(Vlo, Vhi, F[t]); });
  return slabs;
}

// True when the slabs of a and b are apart along one direction (then the triangles do not
// meet); false says nothing.
inline bool slabs_apart(const DirectionSlabs& a, const DirectionSlabs& b) {
#if defined(__GNUC__)
  using V4 = float __attribute__((vector_size(16)));
  using M4 = int __attribute__((vector_size(16)));
  M4 apart = {0, 0, 0, 0};
  for (int k = 0; k < DirectionSlabs::kLanes; k += 4) {
    V4 alo, ahi, blo, bhi;
    std::memcpy(&alo, &a.lo[k], sizeof alo);
    std::memcpy(&ahi, &a.hi[k], sizeof ahi);
    std::memcpy(&blo, &b.lo[k], sizeof blo);
    std::memcpy(&bhi, &b.hi[k], sizeof bhi);
    apart |= (ahi < blo) | (bhi < alo);
  }
  return (apart[0] | apart[1] | apart[2] | apart[3]) != 0;
#else
  bool apart = false;
  for (int d = 0; d < DirectionSlabs::kLanes; ++d) apart |= (a.hi[d] < b.lo[d]) | (b.hi[d] < a.lo[d]);
  return apart;
#endif
}

// True when triangles a and b of one mesh (corner indices, with slabs sa and sb) share no
// corner and their slabs are apart: then they do not meet. Triangles sharing a corner meet
// there, so their slabs always overlap; the index test skips them cheaply (they are most box
// pairs of a clean mesh).
inline bool apart_by_slabs(const std::array<int, 3>& a, const std::array<int, 3>& b, const DirectionSlabs& sa,
                           const DirectionSlabs& sb) {
  bool share = false;
  for (int v : a) share |= (v == b[0]) | (v == b[1]) | (v == b[2]);
  return !share && slabs_apart(sa, sb);
}

// The slabs of F's triangles (over vertex boxes, as triangle_slabs), each computed on its
// first use and kept: for callers that test few of a mesh's triangles (after the box search
// and the embedded stars of a clean mesh, a few per hundred), so the others cost nothing,
// not even the pages of their slots. get() may be called from several threads at once: the
// first caller of a triangle claims its slot (an atomic state), the others compute their own
// copy meanwhile. The spans must outlive the object. Cost: one byte per triangle written at
// construction (the states), 96 reserved; a use costs an acquire load once computed.
class TriangleSlabsOnDemand {
 public:
  TriangleSlabsOnDemand(std::span<const std::array<double, 3>> Vlo, std::span<const std::array<double, 3>> Vhi,
                        std::span<const std::array<int, 3>> F)
      : Vlo_(Vlo),
        Vhi_(Vhi),
        F_(F),
        slabs_(new DirectionSlabs[F.size()]),
        state_(new std::atomic<std::uint8_t>[F.size()]()) {}

  // slabs_apart for triangles i and j of F (never true for triangles that share a corner:
  // their slabs hold it; the index test of apart_by_slabs would only cost their loads here).
  bool apart(std::size_t i, std::size_t j) const {
    DirectionSlabs si, sj;
    return slabs_apart(get(i, si), get(j, sj));
  }

  // The slabs of triangle t: the stored ones, or computed into scratch.
  const DirectionSlabs& get(std::size_t t, DirectionSlabs& scratch) const {
    if (state_[t].load(std::memory_order_acquire) == kReady) [[likely]]
      return slabs_[t];
    return compute(t, scratch);
  }

 private:
  enum : std::uint8_t { kEmpty, kWriting, kReady };

  // The first use of triangle t (or a use while another thread stores it).
#if defined(__GNUC__)
  __attribute__((noinline))
#endif
  const DirectionSlabs& compute(std::size_t t, DirectionSlabs& scratch) const {
    std::uint8_t state = state_[t].load(std::memory_order_acquire);
    if (state == kReady) return slabs_[t];
    scratch = triangle_slab(Vlo_, Vhi_, F_[t]);
    if (state == kEmpty && state_[t].compare_exchange_strong(state, kWriting, std::memory_order_relaxed)) {
      slabs_[t] = scratch;
      state_[t].store(kReady, std::memory_order_release);
    }
    return scratch;
  }

  std::span<const std::array<double, 3>> Vlo_, Vhi_;
  std::span<const std::array<int, 3>> F_;
  std::unique_ptr<DirectionSlabs[]> slabs_;  // default-initialised: untouched until written
  std::unique_ptr<std::atomic<std::uint8_t>[]> state_;
};

}  // namespace tritri
