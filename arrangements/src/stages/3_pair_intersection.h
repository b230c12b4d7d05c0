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

// The records of one chunk of pairs, stored compactly: a 20-byte head per record and its
// points and segments in two shared arrays (a PairIntersection reserves room for 6 of
// each, 216 bytes, where most pairs have 2 points and 1 segment). Arrays are trimmed to
// size when the chunk is done. Reading gives the PairIntersection back, by value.
class PairRecordChunk {
 public:
  void push_back(const PairIntersection& r) {
    heads_.push_back({{r.tri[0], r.tri[1]}, static_cast<std::uint32_t>(points_.size()),
                      static_cast<std::uint32_t>(segments_.size()), static_cast<std::uint8_t>(r.points.size()),
                      static_cast<std::uint8_t>(r.segments.size()), r.coplanar});
    points_.insert(points_.end(), r.points.begin(), r.points.end());
    segments_.insert(segments_.end(), r.segments.begin(), r.segments.end());
  }
  void shrink_to_fit() {
    heads_.shrink_to_fit();
    points_.shrink_to_fit();
    segments_.shrink_to_fit();
  }
  std::size_t size() const noexcept { return heads_.size(); }
  PairIntersection operator[](std::size_t i) const {
    const Head& h = heads_[i];
    PairIntersection r;
    r.tri[0] = h.tri[0];
    r.tri[1] = h.tri[1];
    r.coplanar = h.coplanar;
    for (std::uint32_t k = 0; k < h.points; ++k) r.points.push_back(points_[h.first_point + k]);
    for (std::uint32_t k = 0; k < h.segments; ++k) r.segments.push_back(segments_[h.first_segment + k]);
    return r;
  }

 private:
  struct Head {
    int tri[2];
    std::uint32_t first_point, first_segment;  // a chunk holds a few thousand records
    std::uint8_t points, segments;
    bool coplanar;
  };
  std::vector<Head> heads_;
  std::vector<PairPoint> points_;
  std::vector<tritri::Segment> segments_;
};

// The records of a classification, in pair order, held in the chunks its parallel loop
// filled (tritri::detail::collect_chunks_in_order): concatenating them would double the
// peak memory when there are millions. Iterates like one sequence of PairIntersection
// (given by value: read each once, in a range-for).
class PairRecords {
 public:
  PairRecords() = default;
  explicit PairRecords(std::vector<PairRecordChunk> chunks) : chunks_(std::move(chunks)) {
    for (const auto& c : chunks_) size_ += c.size();
  }

  class const_iterator {
   public:
    using value_type = PairIntersection;
    using difference_type = std::ptrdiff_t;
    const_iterator() = default;
    const_iterator(const std::vector<PairRecordChunk>* c, std::size_t chunk) : c_(c), chunk_(chunk) { skip_empty(); }
    PairIntersection operator*() const { return (*c_)[chunk_][pos_]; }
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
    const std::vector<PairRecordChunk>* c_ = nullptr;
    std::size_t chunk_ = 0, pos_ = 0;
  };

  const_iterator begin() const { return {&chunks_, 0}; }
  const_iterator end() const { return {&chunks_, chunks_.size()}; }
  std::size_t size() const noexcept { return size_; }
  // The chunks themselves, in order (for reading them in parallel).
  const std::vector<PairRecordChunk>& chunks() const noexcept { return chunks_; }

 private:
  std::vector<PairRecordChunk> chunks_;
  std::size_t size_ = 0;
};

}  // namespace arrangements
