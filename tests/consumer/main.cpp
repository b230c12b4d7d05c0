// Smoke test of an installed tritri: two triangles that cross must intersect.
#include <array>
#include <cstdio>

#include <tritri/tritri.h>

int main() {
  using P = std::array<double, 3>;
  // A lies in z = 0; B stands in x = 0.5 and pierces A's interior, then leaves through
  // A's edge 0 (y = 0): expected EA_CROSS_TB(0,-1) and EB_CROSS_TA(0,-1), one segment.
  const P a0{0, 0, 0}, a1{2, 0, 0}, a2{0, 2, 0};
  const P b0{0.5, 0.5, -1}, b1{0.5, 0.5, 1}, b2{0.5, -1, 0.5};

  const auto r = tritri::classify<tritri::DoubleKernel>(a0, a1, a2, b0, b1, b2);

  for (const auto& p : r.points)
    std::printf("point type=%d id0=%d id1=%d\n", static_cast<int>(p.type), int(p.id0), int(p.id1));
  for (const auto& s : r.segments) std::printf("segment %d-%d\n", int(s.p0), int(s.p1));
  std::printf("coplanar=%d intersects=%d\n", int(r.coplanar), int(r.intersects()));

  if (!r.intersects()) {
    std::fprintf(stderr, "FAIL: crossing triangles reported as disjoint\n");
    return 1;
  }
  std::printf("tritri consumer: OK\n");
  return 0;
}
