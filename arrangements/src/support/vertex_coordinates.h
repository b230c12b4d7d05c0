// The coordinates of an output vertex, whatever the mesh stores (output_mesh.h): implicit
// points (OutputMesh), rationals (ExactOutputMesh) or doubles (RoundedMesh). Shared by the
// writer (io/write_mesh.cpp) and the rounding (rounding/round_mesh.cpp).
#pragma once

#include <tritri/implicit_point.h>

#include "arrangements/as_input.h"
#include "arrangements/triangle_soup.h"

namespace arrangements {

// Exact rational coordinates.
inline ExactVec3 exact_coordinates(const tritri::ImplicitPoint& p) { return tritri::to_exact(p); }
inline const ExactVec3& exact_coordinates(const ExactVec3& p) { return p; }
inline ExactVec3 exact_coordinates(const Vec3& p) { return to_exact(p); }

// Whether the vertex is a double point already (a rational is not asked: rounding decides).
inline bool is_double(const tritri::ImplicitPoint& p) { return p.is_explicit(); }
inline bool is_double(const ExactVec3&) { return false; }

// Each coordinate rounded to the nearest double.
inline Vec3 nearest_double(const tritri::ImplicitPoint& p) { return tritri::to_double(p); }
inline Vec3 nearest_double(const ExactVec3& p) { return tritri::to_double(p); }
inline const Vec3& nearest_double(const Vec3& p) { return p; }

}  // namespace arrangements
