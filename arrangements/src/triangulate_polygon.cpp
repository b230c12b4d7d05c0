// Polygon faces -> triangles (see triangulate_polygon.h).
#include "arrangements/triangulate_polygon.h"

namespace arrangements {

void triangulate_polygon(const std::vector<Vec3>& V, std::span<const int> corners, std::vector<Tri>& out) {
  (void)V;
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) out.push_back({corners[0], corners[i], corners[i + 1]});
}

}  // namespace arrangements
