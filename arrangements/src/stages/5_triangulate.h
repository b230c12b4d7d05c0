// arrangements/src/stages/5_triangulate.h
//
// Stage 5 of the pipeline (the last): split every triangle that has intersection points,
// constraint segments or coplanar partners, exactly, and assemble the output mesh.
//
// triangulate<M>(soup, graph, scale_exponent, info), for a point model M
// (models/point_model.h); without M, DoubleModel:
//   soup            the preprocessed soup (stage 1: merged vertices, no degenerate or
//                   duplicate triangles)
//   graph           its intersection graph (stage 4, coplanar partners already sharing)
//   scale_exponent  the preprocessing's power-of-two scaling k (0: none); the output
//                   points are rebuilt from their unscaled defining points, exactly
// returns the arrangement (output_mesh.h): the referenced points only, in first-use order
// of the triangles; soup triangles in order, each one either copied (nothing cuts it) or
// replaced by its pieces; a region covered by several coplanar triangles is emitted once,
// by the smallest soup triangle covering it, labelled with the union of their label sets;
// source maps back to the input numbering (TriangleSoup::source).
// info (filled; pass a fresh, default-constructed one, with keep_covers and
// per_triangle_only set as wanted):
//   new_tpi         the TPIs created (crossings of two constraint segments inside a
//                   triangle; distinct from each other and from every graph point,
//                   compared exactly): the stats key `tpi`
//   emitted_by, cover_of, covers   with keep_covers only (see TriangulationInfo)
//   output_vertex   per graph point id, then per new TPI (ids graph.points.size() + k, in
//                   the model's exact order, M::compare): its index in the mesh's vertices,
//                   -1 if no output triangle uses it (for checks that follow graph ids into
//                   the mesh)
// Exactness: see 5_triangulate_triangle.h; points are never rounded here.
// Output does not depend on the number of threads.
// Cost: the per-triangle triangulations, parallel over triangles (TBB), or one per
// coplanar cluster where that saves the repeated work (5_triangulate_cluster.h), plus
// O(T log T) for deduplicating T new TPIs.
#pragma once

#include <cstddef>
#include <vector>

#include "arrangements/output_mesh.h"
#include "arrangements/triangle_soup.h"
#include "models/double_model.h"
#include "stages/4_intersection_graph.h"

namespace arrangements {

struct TriangulationInfo {
  std::size_t new_tpi = 0;
  std::vector<int> output_vertex;
  // With keep_covers (stage 6 needs them): per output triangle, the soup triangle that
  // emitted it (its orientation is that triangle's) and, when coplanar soup triangles
  // share its region, an index into covers (the soup triangles covering it, the emitting
  // one included), else -1.
  bool keep_covers = false;
  // Coplanar clusters triangulated whole (5_triangulate_cluster.h): how many; with
  // per_triangle_only, none (every triangle split by itself: tests compare both ways).
  bool per_triangle_only = false;
  std::size_t whole_clusters = 0;
  std::vector<int> emitted_by, cover_of;
  std::vector<std::vector<int>> covers;
};

template <class M>
BasicOutputMesh<typename M::Point> triangulate(const BasicTriangleSoup<typename M::Vertex>& soup,
                                               const BasicIntersectionGraph<typename M::Point>& graph,
                                               int scale_exponent, TriangulationInfo& info);

inline OutputMesh triangulate(const TriangleSoup& soup, const IntersectionGraph& graph, int scale_exponent,
                              TriangulationInfo& info) {
  return triangulate<DoubleModel>(soup, graph, scale_exponent, info);
}

}  // namespace arrangements
