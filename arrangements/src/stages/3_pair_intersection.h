// arrangements/src/stages/3_pair_intersection.h
//
// PairIntersection: what a classifier reports for one pair of triangles, in terms of
// input vertex ids, before points are deduplicated globally. Every classifier (the native
// one, the tritri adapter) fills this same record; build_intersection_graph consumes it.
//
// A point is either an existing vertex, or a new point defined as an LPI by vertex ids:
// the line through vertices (p, q) meets the plane through (r, s, t). A plane id below 0
// stands for auxiliary_point(-1 - id), the auxiliary point of that triangle (used by
// coplanar edge-edge crossings, whose plane passes through the other edge and a point off
// the triangles' common plane).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <tritri/location.h>
#include <tritri/result.h>

namespace arrangements {

// Where a point lies in one triangle of the pair: tritri's Location (vertex k, edge k from
// vertex k to vertex (k+1)%3, Interior; never Outside in a record), with closed_edges.
using tritri::closed_edges;
using tritri::Location;

// An LPI by vertex ids: line (p, q), plane (r, s, t). Canonical form: p < q, r < s < t.
struct LpiKey {
  std::array<int, 5> v{};
  friend bool operator==(const LpiKey&, const LpiKey&) = default;
  friend auto operator<=>(const LpiKey&, const LpiKey&) = default;
};

inline LpiKey make_lpi_key(int p, int q, int r, int s, int t) {
  if (p > q) std::swap(p, q);
  if (r > s) std::swap(r, s);
  if (s > t) std::swap(s, t);
  if (r > s) std::swap(r, s);
  return {{p, q, r, s, t}};
}

struct PairPoint {
  int vertex = -1;  // an existing vertex id, or -1 for a new point given by `lpi`
  LpiKey lpi;
  Location in[2];  // location in the pair's first and second triangle
};

struct PairIntersection {
  int tri[2] = {-1, -1};
  bool coplanar = false;
  tritri::StaticVector<PairPoint, 6> points;
  tritri::StaticVector<tritri::Segment, 6> segments;  // indices into points
};

// The records of a classification, in pair order, held in the chunks its parallel loop
// filled (tritri::detail::collect_chunks_in_order): concatenating them would double the
// peak memory when there are millions. Iterates like one sequence.
class PairRecords {
 public:
  PairRecords() = default;
  explicit PairRecords(std::vector<std::vector<PairIntersection>> chunks) : chunks_(std::move(chunks)) {
    for (const auto& c : chunks_) size_ += c.size();
  }

  class const_iterator {
   public:
    using value_type = PairIntersection;
    using difference_type = std::ptrdiff_t;
    const_iterator() = default;
    const_iterator(const std::vector<std::vector<PairIntersection>>* c, std::size_t chunk) : c_(c), chunk_(chunk) {
      skip_empty();
    }
    const PairIntersection& operator*() const { return (*c_)[chunk_][pos_]; }
    const PairIntersection* operator->() const { return &(*c_)[chunk_][pos_]; }
    const_iterator& operator++() {
      ++pos_;
      skip_empty();
      return *this;
    }
    friend bool operator==(const const_iterator& a, const const_iterator& b) {
      return a.chunk_ == b.chunk_ && a.pos_ == b.pos_;
    }

   private:
    void skip_empty() {
      while (chunk_ < c_->size() && pos_ == (*c_)[chunk_].size()) {
        ++chunk_;
        pos_ = 0;
      }
    }
    const std::vector<std::vector<PairIntersection>>* c_ = nullptr;
    std::size_t chunk_ = 0, pos_ = 0;
  };

  const_iterator begin() const { return {&chunks_, 0}; }
  const_iterator end() const { return {&chunks_, chunks_.size()}; }
  std::size_t size() const noexcept { return size_; }

 private:
  std::vector<std::vector<PairIntersection>> chunks_;
  std::size_t size_ = 0;
};

}  // namespace arrangements
