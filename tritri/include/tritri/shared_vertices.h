// tritri/shared_vertices.h
//
// meet_only_in_shared(k, a, ia, b, ib): a cheap exact test for two triangles of one mesh
// that share vertices (by index). Returns true when the triangles are certain to meet in
// exactly what they share (the common vertex, or the common edge), so that
// tritri::classify would report only VA_ON_VB points at the shared vertices; false when
// they share nothing, share all three vertices, or may meet anywhere else (then classify
// them in full). Most candidate pairs of a mesh are such neighbours.
//
//   a, b    the triangles' corners (K::Point); ia, ib their vertex indices in the mesh
// Preconditions: equal indices name equal points. Nothing else: degenerate triangles, or
// equal points under different indices, only make the answer false more often.
//
// Why it is exact. One shared vertex u, A = (u, a1, a2), B = (u, b1, b2): if b1 and b2 lie
// strictly on the same side of A's plane, every point of B but u (a convex combination
// with positive weight on b1 or b2) lies strictly on that side, so A and B meet only in
// u; the same with the roles swapped. A shared edge uv, A = (u, v, a), B = (u, v, b): if b
// is not in A's plane, B meets that plane only in the segment uv, which lies in A: the
// triangles meet exactly in the edge. (Coplanar neighbours are left to classify.)
// Cost: 1 orient3d for a shared edge, 2 to 4 for a shared vertex. Exact when K is.
#pragma once

#include <array>

#include "tritri/kernel_concept.h"

namespace tritri {

template <Kernel K>
bool meet_only_in_shared(const K& k, const std::array<typename K::Point, 3>& a, const std::array<int, 3>& ia,
                         const std::array<typename K::Point, 3>& b, const std::array<int, 3>& ib) {
  int in_b[3] = {-1, -1, -1};  // for each corner of a, its position in b (-1: not shared)
  int shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (ia[i] == ib[j]) {
        in_b[i] = j;
        ++shared;
      }
  if (shared == 1) {
    const int i = in_b[0] >= 0 ? 0 : (in_b[1] >= 0 ? 1 : 2), j = in_b[i];
    const auto& u = a[i];
    const auto &a1 = a[(i + 1) % 3], &a2 = a[(i + 2) % 3], &b1 = b[(j + 1) % 3], &b2 = b[(j + 2) % 3];
    const Sign s1 = k.orient3d(u, a1, a2, b1);
    if (s1 != Sign::Zero && k.orient3d(u, a1, a2, b2) == s1) return true;
    const Sign t1 = k.orient3d(u, b1, b2, a1);
    return t1 != Sign::Zero && k.orient3d(u, b1, b2, a2) == t1;
  }
  if (shared == 2) {
    const int w = in_b[0] < 0 ? 0 : (in_b[1] < 0 ? 1 : 2);    // a's corner not in b
    const int x = 3 - in_b[(w + 1) % 3] - in_b[(w + 2) % 3];  // b's corner not in a
    return k.orient3d(a[0], a[1], a[2], b[x]) != Sign::Zero;
  }
  return false;
}

}  // namespace tritri
