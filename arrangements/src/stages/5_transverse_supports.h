// arrangements/src/stages/5_transverse_supports.h (internal to stage 5)
//
// TransverseSupports<M>(soup, graph, corners): for constraints in the plane of the
// triangle `corners` (one soup triangle, or any of a coplanar cluster), a plane through
// each constraint's line that is transverse to that plane, as three vertices: the TPI
// where two constraints cross is built from the triangle's plane and one such plane of
// each (M::tpi). Each distinct plane is tested once (three exact orient3d against the
// triangle's corners) and numbered in first-test order: constraints with the same number
// lie on one line (the triangle's plane meets that plane in it), which the local
// triangulation uses as an exact collinearity known by construction.
//   of_segment(ends)  one of the graph's SegmentSupport planes of segment `ends` (the
//                     first transverse one), throws std::logic_error when none is
//   of_plane(key)     the plane of three vertex ids (an id below 0: the auxiliary point of
//                     triangle -1 - id, as in SegmentSupport), if transverse
// Exactness: orient3d of the model (exact). Cost: O(log S) per lookup for S supports.
#pragma once

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "arrangements/triangle_soup.h"
#include "stages/4_intersection_graph.h"

namespace arrangements {

template <class M>
class TransverseSupports {
 public:
  using Vertex = typename M::Vertex;
  struct Support {
    std::array<Vertex, 3> plane;
    int line;
  };

  TransverseSupports(const BasicTriangleSoup<Vertex>& soup, const BasicIntersectionGraph<typename M::Point>& g,
                     const Tri& corners)
      : soup_(soup), g_(g), corners_(corners) {}

  Support of_segment(const std::array<int, 2>& ends) {
    auto it = std::lower_bound(g_.segment_supports.begin(), g_.segment_supports.end(), ends,
                               [](const SegmentSupport& x, const std::array<int, 2>& e) { return x.ends < e; });
    for (; it != g_.segment_supports.end() && it->ends == ends; ++it)
      for (const auto& pl : it->planes)
        if (auto s = of_plane(pl)) return *s;
    throw std::logic_error("triangulate: no transverse plane for a constraint segment");
  }

  std::optional<Support> of_plane(const std::array<int, 3>& key) {
    auto [known, fresh] = index_.emplace(key, static_cast<int>(transverse_.size()));
    if (fresh) {
      const std::array<Vertex, 3> P = {at(key[0]), at(key[1]), at(key[2])};
      bool transverse = false;
      for (int k = 0; k < 3 && !transverse; ++k)
        transverse = M::orient3d(P[0], P[1], P[2], soup_.vertices[corners_[k]]) != tritri::Sign::Zero;
      transverse_.push_back(transverse);
    }
    if (!transverse_[static_cast<std::size_t>(known->second)]) return std::nullopt;
    return Support{{at(key[0]), at(key[1]), at(key[2])}, known->second};
  }

 private:
  const BasicTriangleSoup<Vertex>& soup_;
  const BasicIntersectionGraph<typename M::Point>& g_;
  Tri corners_;
  std::vector<char> transverse_;  // per distinct plane, in first-test order
  std::map<std::array<int, 3>, int> index_;

  Vertex at(int id) const {
    if (id >= 0) return soup_.vertices[id];
    const Tri& u = soup_.triangles[-1 - id];
    return M::auxiliary_point(soup_.vertices[u[0]], soup_.vertices[u[1]], soup_.vertices[u[2]]);
  }
};

}  // namespace arrangements
