// arrangements/triangle_soup.h
//
// TriangleSoup / ExactTriangleSoup: the pipeline's plain input and intermediate data, with
// double or exact rational coordinates (BasicTriangleSoup<Coordinates>).
//   vertices   #V list of exact coordinates: Vec3 (doubles) or ExactVec3 (rationals,
//              CGAL::Gmpq; any rational, e.g. a vertex of an exact arrangement)
//   triangles  #F list of vertex indices into `vertices`
//   label_set  #F label-set index per triangle, into `label_sets`
//   label_sets distinct sorted label sets (any number of labels per triangle: no cap)
//   source     #F index of each triangle in the concatenated input files' triangle lists
//              (after triangulation of polygons, in file order), so that output
//              provenance maps back to the input.
//   polygon    #F, or empty (= all -1): for a triangle of a polygon face that
//              triangulate_polygon split without overlap, an id shared by exactly the
//              triangles of that face (the source index of its first triangle); -1
//              otherwise. Two triangles with the same id meet only in shared corners and
//              edges, so candidate_pairs never pairs them.
#pragma once

#include <CGAL/Gmpq.h>

#include <array>
#include <cstdint>
#include <vector>

namespace arrangements {

using Vec3 = std::array<double, 3>;
using ExactVec3 = std::array<CGAL::Gmpq, 3>;
using Tri = std::array<int, 3>;
using LabelSet = std::vector<std::uint32_t>;  // sorted, unique

template <class Coordinates>
struct BasicTriangleSoup {
  std::vector<Coordinates> vertices;
  std::vector<Tri> triangles;
  std::vector<int> label_set;
  std::vector<LabelSet> label_sets;
  std::vector<std::int64_t> source;
  std::vector<std::int64_t> polygon;
};

using TriangleSoup = BasicTriangleSoup<Vec3>;
using ExactTriangleSoup = BasicTriangleSoup<ExactVec3>;

}  // namespace arrangements
