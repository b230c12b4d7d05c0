// tritri/tritri.h
//
// The whole public API of tritri: exact classification of the intersection of two
// triangles, generic over the number representation.
//
//   #include <tritri/tritri.h>
//   using P = tritri::DoubleKernel::Point;             // std::array<double, 3>
//   tritri::Result r = tritri::classify<tritri::DoubleKernel>(a0, a1, a2, b0, b1, b2);
//   for (const auto& p : r.points) { /* p.type, p.id0, p.id1 */ }
//   for (const auto& s : r.segments) { /* r.points[s.p0], r.points[s.p1] */ }
//
// The shared 2D geometry of a triangle is public too: tritri::projection (an axis plane
// where a triangle is not degenerate, projection.h) and tritri::Location (where a point
// lies in a triangle, location.h).
//
// CgalKernel<CK>, RationalKernel (CGAL::Gmpq coordinates) and ImplicitKernel (LPI / TPI
// points) are included when CGAL's headers are available.
#pragma once

#include "tritri/sign.h"
#include "tritri/kernel_concept.h"
#include "tritri/result.h"
#include "tritri/location.h"
#include "tritri/projection.h"
#include "tritri/double_predicates.h"
#include "tritri/double_kernel.h"
#include "tritri/counting_kernel.h"
#include "tritri/classify.h"
#include "tritri/plane_filter.h"
#include "tritri/shared_vertices.h"

#if __has_include(<CGAL/Kernel/global_functions.h>)
#include "tritri/cgal_kernel.h"
#include "tritri/rational_kernel.h"
#include "tritri/implicit_kernel.h"
#include "tritri/constructed_plane_sides.h"
#endif
