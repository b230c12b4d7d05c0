// arrangements/propagate_coplanar.h
//
// propagate_coplanar: coplanar partners share their points and segments (as in the 2020
// pipeline). For every triangle t and each coplanar partner u, the points of u (inside
// u or on its edges) that lie in the closed triangle t are added to t (inside t, or on
// the edge of t they lie on), and u's segments whose endpoints both lie in t are added to
// t's segments. Without it, a constraint of u meeting u's edge inside t would cross t's
// copy of that edge at a point t does not know, and t's triangulation would construct it
// again. Additions are computed from the graph as it was before the call, so the result
// does not depend on processing order.
//
// Exactness: point location is orient2d on implicit points (tritri's filtered exact
// predicates) in a projection where t is not degenerate. Cost: proportional to the points
// and segments of coplanar partners.
#pragma once

#include <vector>

#include "arrangements/intersection_graph.h"
#include "arrangements/triangle_soup.h"

namespace arrangements {

void propagate_coplanar(const std::vector<Vec3>& V, const std::vector<Tri>& F, IntersectionGraph& g);

}  // namespace arrangements
