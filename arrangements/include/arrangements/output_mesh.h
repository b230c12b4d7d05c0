// arrangements/output_mesh.h
//
// OutputMesh / ExactOutputMesh: the arrangement as it is written out. Triangles meet
// only at shared vertices and shared edges.
//   vertices    the referenced points only, in first-use order of `triangles`, exact:
//               OutputMesh (double input): tritri::ImplicitPoint, explicit input
//               vertices, LPIs and TPIs over them (never rounded);
//               ExactOutputMesh (exact input, ExactTriangleSoup): rational coordinates
//   triangles   indices into `vertices`, each oriented like the input triangle it lies in
//   source      per triangle: the index of the input triangle it lies in, in the input
//               files' concatenated triangle lists (an n-corner polygon face is n - 2
//               consecutive entries: arrangements/src/io/triangulate_polygon.h)
//               (TriangleSoup::source); for a region shared by coplanar overlapping
//               triangles, the one that the preprocessing numbered first
//   label_set   per triangle: index into label_sets; the union of the labels of every
//               input triangle (duplicates included) that covers the triangle
//   label_sets  distinct sorted label sets
// RoundedMesh: the same with double coordinates (round_mesh.h: rounded to the nearest
// double, or rounded safely so that it is still an arrangement).
#pragma once

#include <cstdint>
#include <vector>

#include <tritri/implicit_point.h>

#include "arrangements/triangle_soup.h"

namespace arrangements {

template <class Point>
struct BasicOutputMesh {
  std::vector<Point> vertices;
  std::vector<Tri> triangles;
  std::vector<std::int64_t> source;
  std::vector<int> label_set;
  std::vector<LabelSet> label_sets;
};

using OutputMesh = BasicOutputMesh<tritri::ImplicitPoint>;
using ExactOutputMesh = BasicOutputMesh<ExactVec3>;
using RoundedMesh = BasicOutputMesh<Vec3>;

}  // namespace arrangements
