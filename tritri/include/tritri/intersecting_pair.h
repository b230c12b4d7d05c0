// tritri/intersecting_pair.h
//
// IntersectingPair: one pair of intersecting triangles of a mesh (or of two meshes) with
// its exact classification; the element type of the output of tritri::self_intersections
// (self_intersections.h) and tritri::intersections (intersections.h).
//
//   i       index of triangle A: a row of F (self_intersections) or of F1 (intersections)
//   j       index of triangle B: a row of F with j > i, or a row of F2
//   result  tritri::classify of (A, B) with the corners in the order of the rows of F,
//           so the ids in result.points name corners and edges of the two rows
//           (edge k joins columns k and (k+1)%3)
#pragma once

#include "tritri/result.h"

namespace tritri {

struct IntersectingPair {
  int i = 0;
  int j = 0;
  Result result;

  friend bool operator==(const IntersectingPair&, const IntersectingPair&) = default;
};

}  // namespace tritri
