// tritri/result.h
//
// The output of tritri::classify: a small fixed-capacity value (no heap allocation).
//
// Numbering: vertices of each triangle are 0, 1, 2; edge k joins vertex k and vertex
// (k+1)%3; "edge" means the open edge, "face" (T) the open interior.
//
// Point order (deterministic, independent of the kernel): points are sorted by
// (type, id0, id1). Segments index into `points`, have p0 < p1, and are sorted by
// (p0, p1).
#pragma once

#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <ostream>

namespace tritri {

// Which pair of sub-simplices meets at an intersection point (values 0..7 are fixed).
enum class Type : std::int8_t {
  VA_ON_VB = 0,     // id0: vertex of A, id1: vertex of B
  VA_ON_EB = 1,     // id0: vertex of A, id1: edge of B
  VB_ON_EA = 2,     // id0: vertex of B, id1: edge of A
  VA_ON_TB = 3,     // id0: vertex of A, id1: -1
  VB_ON_TA = 4,     // id0: vertex of B, id1: -1
  EA_CROSS_EB = 5,  // id0: edge of A,   id1: edge of B
  EA_CROSS_TB = 6,  // id0: edge of A,   id1: -1
  EB_CROSS_TA = 7,  // id0: edge of B,   id1: -1
};

inline const char* to_string(Type t) noexcept {
  constexpr const char* names[] = {"VA_ON_VB", "VA_ON_EB",    "VB_ON_EA",    "VA_ON_TB",
                                   "VB_ON_TA", "EA_CROSS_EB", "EA_CROSS_TB", "EB_CROSS_TA"};
  return names[static_cast<int>(t)];
}

// One intersection point, named by the two sub-simplices that meet there.
struct IntersectionPoint {
  Type type;
  std::int8_t id0;
  std::int8_t id1;

  friend bool operator==(const IntersectionPoint&, const IntersectionPoint&) = default;
  friend bool operator<(const IntersectionPoint& a, const IntersectionPoint& b) noexcept {
    if (a.type != b.type) return a.type < b.type;
    if (a.id0 != b.id0) return a.id0 < b.id0;
    return a.id1 < b.id1;
  }
};

// A segment of the intersection, as two indices into Result::points.
struct Segment {
  std::int8_t p0;
  std::int8_t p1;
  friend bool operator==(const Segment&, const Segment&) = default;
};

// A vector with fixed capacity N stored inline.
template <class T, std::size_t N>
class StaticVector {
 public:
  using value_type = T;
  using const_iterator = const T*;
  using iterator = T*;

  std::size_t size() const noexcept { return size_; }
  static constexpr std::size_t capacity() noexcept { return N; }
  bool empty() const noexcept { return size_ == 0; }
  const T& operator[](std::size_t i) const noexcept {
    assert(i < size_);
    return data_[i];
  }
  T& operator[](std::size_t i) noexcept {
    assert(i < size_);
    return data_[i];
  }
  const T* begin() const noexcept { return data_.data(); }
  const T* end() const noexcept { return data_.data() + size_; }
  T* begin() noexcept { return data_.data(); }
  T* end() noexcept { return data_.data() + size_; }
  void push_back(const T& v) noexcept {
    assert(size_ < N);
    data_[size_++] = v;
  }
  void clear() noexcept { size_ = 0; }

  friend bool operator==(const StaticVector& a, const StaticVector& b) noexcept {
    if (a.size_ != b.size_) return false;
    for (std::size_t i = 0; i < a.size_; ++i)
      if (!(a.data_[i] == b.data_[i])) return false;
    return true;
  }

 private:
  std::array<T, N> data_{};
  std::size_t size_ = 0;
};

// Complete classification of the intersection of two triangles A and B.
// Non-coplanar pairs have at most 2 points and 1 segment. Coplanar pairs have at most 6
// points; their segments are the boundary edges of the overlap (a point, a segment, or a
// convex polygon with up to 6 corners). Every point is a corner of the intersection set.
struct Result {
  StaticVector<IntersectionPoint, 6> points;
  StaticVector<Segment, 6> segments;
  bool coplanar = false;    // the two triangles lie in one plane (and were classified)
  bool degenerate = false;  // an input triangle is degenerate (repeated or collinear
                            // vertices) and the pair was not classified: points empty

  bool intersects() const noexcept { return !points.empty(); }
  friend bool operator==(const Result&, const Result&) = default;
};

inline std::ostream& operator<<(std::ostream& os, const Result& r) {
  os << "{points:[";
  for (std::size_t i = 0; i < r.points.size(); ++i)
    os << (i ? "," : "") << to_string(r.points[i].type) << "(" << int(r.points[i].id0) << "," << int(r.points[i].id1)
       << ")";
  os << "] segments:[";
  for (std::size_t i = 0; i < r.segments.size(); ++i)
    os << (i ? "," : "") << "(" << int(r.segments[i].p0) << "," << int(r.segments[i].p1) << ")";
  os << "] coplanar:" << r.coplanar << " degenerate:" << r.degenerate << "}";
  return os;
}

}  // namespace tritri
