// tritri/rational_kernel.h
//
// RationalKernel: tritri's kernel concept on points with exact rational coordinates
// (CGAL::Gmpq), e.g. the vertices of an exact arrangement. Its predicates are CGAL's
// filtered ones (CGAL::Filtered_kernel): interval arithmetic first, exact rational
// arithmetic only when the intervals cannot decide.
//
//   tritri::RationalKernel::Point p(CGAL::Gmpq(1, 3), CGAL::Gmpq(0), CGAL::Gmpq(2, 7));
//   tritri::Result r = tritri::classify<tritri::RationalKernel>(a0, a1, a2, b0, b1, b2);
//
// Exactness: every predicate is exact for any rational coordinates (no precondition on their
// size). Cost: a few interval operations per predicate when the filter decides; else GMP
// rationals, whose size grows with the coordinates' numerators and denominators.
// Used by self_intersections / intersections for Eigen matrices of CGAL::Gmpq.
#pragma once

#include <CGAL/Filtered_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include "tritri/cgal_kernel.h"

namespace tritri {

using RationalKernel = CgalKernel<CGAL::Filtered_kernel<CGAL::Simple_cartesian<CGAL::Gmpq>>>;

}  // namespace tritri
