// arrangements/src/io/csg_transform.h (internal to load_csg_file)
//
// The exact affine maps of OpenSCAD's multmatrix statements, and their action on a soup.
//   ExactAffine     the map x -> A x + t, as the three rows [A | t] of its 4 x 4 matrix
//                   (the fourth row is 0 0 0 1), entries exact rationals
//   compose(outer, inner)   the map of "outer applied after inner": outer's matrix times
//                   inner's, exactly (nested multmatrix statements)
//   is_identity(t)  A = I and t = 0, exactly
//   determinant(t)  det A, exactly
//   transform_soup(soup, t)
//     soup  one operand, as load_mesh_file (load_mesh_file.h) loads it
//     Maps every vertex by t exactly; when det A < 0, reverses every triangle's corners
//     (c0 c1 c2 -> c2 c1 c0) so that a closed outward-oriented surface stays outward. A
//     TriangleSoup stays one when every mapped coordinate is exactly a double (e.g. an
//     integer translation of doubles), else becomes the ExactTriangleSoup of the mapped
//     coordinates; an ExactTriangleSoup stays one. Returns false (soup then unspecified)
//     when a mapped coordinate is beyond the largest finite double (the pipeline needs
//     finite boxes). Everything else is kept: `source`, labels, and `polygon` (an affine
//     bijection keeps a polygon's triangulation free of overlaps). Precondition: det A != 0.
// Exact: no rounding anywhere. Cost: at most 9 rational products and 9 sums per vertex
// (zero and unit entries of A cost nothing), plus one conversion of the soup when it
// becomes exact.
#pragma once

#include <CGAL/Gmpq.h>

#include <array>

#include "arrangements/load_triangle_soup.h"

namespace arrangements::detail {

struct ExactAffine {
  std::array<std::array<CGAL::Gmpq, 4>, 3> rows;
};

ExactAffine compose(const ExactAffine& outer, const ExactAffine& inner);

bool is_identity(const ExactAffine& t);

CGAL::Gmpq determinant(const ExactAffine& t);

bool transform_soup(AnyTriangleSoup& soup, const ExactAffine& t);

}  // namespace arrangements::detail
