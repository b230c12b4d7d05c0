// arrangements/as_input.h
//
// Carrying an arrangement on: a result as the input of the next arrangement, and double
// input as exact input. Nothing is rounded.
//
// as_input(mesh)
//   The output mesh as a soup for arrange() (arrange.h): the same vertices in the same
//   order, the same triangles, label sets and sources (so provenance keeps naming the first
//   input's triangles through any number of arrangements); `polygon` empty.
//     OutputMesh (double path)  -> ExactTriangleSoup: every implicit point (LPI, TPI) by
//                                  its exact rational coordinates (tritri::to_exact)
//     ExactOutputMesh           -> ExactTriangleSoup
//     RoundedMesh (round_mesh.h)-> TriangleSoup
//   Arranging the result of as_input again finds no new point (tests/test_iterate_shared.cpp).
// to_exact(soup)
//   A double soup as an exact one (every double is a rational): to join it with exact
//   soups, or to take the exact path.
//
// Preconditions: none beyond the types' own (an arrange() result is fine as it is).
// Complexity: O(#V + #F); to_exact of an implicit point builds its rational coordinates
// (a few hundred bits).
#pragma once

#include "arrangements/output_mesh.h"
#include "arrangements/triangle_soup.h"

namespace arrangements {

ExactTriangleSoup as_input(const OutputMesh& mesh);
ExactTriangleSoup as_input(const ExactOutputMesh& mesh);
TriangleSoup as_input(const RoundedMesh& mesh);

ExactVec3 to_exact(const Vec3& v);
ExactTriangleSoup to_exact(TriangleSoup soup);

}  // namespace arrangements
