// tritri/projection.h and tritri/location.h: the projection chooser's order of predicate
// calls (which callers that count predicates depend on), the dominant-plane hint, and the
// location numbering shared by classify, the pipeline's pair records and the graph.
#include <gtest/gtest.h>

#include <tritri/tritri.h>

#include <array>
#include <vector>

namespace {

using P = std::array<double, 3>;
using tritri::Location;
using tritri::Plane;

// DoubleKernel that records the plane of every orient2d call.
struct RecordingKernel {
  using Point = P;
  std::vector<Plane>* planes;
  tritri::Sign orient2d(const P& a, const P& b, const P& c, Plane p) const {
    planes->push_back(p);
    return tritri::DoubleKernel::orient2d(a, b, c, p);
  }
};

struct Call {
  std::pair<Plane, int> result;
  std::vector<Plane> planes;
};

Call project(const P& a, const P& b, const P& c, Plane first = Plane::XY) {
  Call call;
  call.result = tritri::projection(RecordingKernel{&call.planes}, a, b, c, first);
  return call;
}

TEST(Projection, CyclicOrder) {
  EXPECT_EQ(tritri::next_plane(Plane::XY), Plane::YZ);
  EXPECT_EQ(tritri::next_plane(Plane::YZ), Plane::ZX);
  EXPECT_EQ(tritri::next_plane(Plane::ZX), Plane::XY);
}

TEST(Projection, FirstNonDegeneratePlaneInCyclicOrder) {
  const P o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  // In z = 0: XY at once.
  Call c = project(o, x, y);
  EXPECT_EQ(c.result, (std::pair<Plane, int>{Plane::XY, 1}));
  EXPECT_EQ(c.planes, (std::vector<Plane>{Plane::XY}));
  // In x = 0: XY is degenerate, YZ (y, z) turns counter-clockwise.
  c = project(o, y, z);
  EXPECT_EQ(c.result, (std::pair<Plane, int>{Plane::YZ, 1}));
  EXPECT_EQ(c.planes, (std::vector<Plane>{Plane::XY, Plane::YZ}));
  // In y = 0: only ZX, where (z, x) of o, x, z turn clockwise.
  c = project(o, x, z);
  EXPECT_EQ(c.result, (std::pair<Plane, int>{Plane::ZX, -1}));
  EXPECT_EQ(c.planes, (std::vector<Plane>{Plane::XY, Plane::YZ, Plane::ZX}));
  // Starting at ZX, a triangle in z = 0 is found after wrapping around to XY.
  c = project(o, x, y, Plane::ZX);
  EXPECT_EQ(c.result, (std::pair<Plane, int>{Plane::XY, 1}));
  EXPECT_EQ(c.planes, (std::vector<Plane>{Plane::ZX, Plane::XY}));
  // Starting at YZ, a triangle in x = 0 needs one call.
  c = project(o, y, z, Plane::YZ);
  EXPECT_EQ(c.planes, (std::vector<Plane>{Plane::YZ}));
}

TEST(Projection, DegenerateTriangleGivesZeroAfterThreeCalls) {
  const P a{1, 2, 3}, b{2, 4, 6}, c{3, 6, 9};  // collinear
  for (Plane first : {Plane::XY, Plane::YZ, Plane::ZX}) {
    const Call call = project(a, b, c, first);
    EXPECT_EQ(call.result, (std::pair<Plane, int>{first, 0}));
    EXPECT_EQ(call.planes,
              (std::vector<Plane>{first, tritri::next_plane(first), tritri::next_plane(tritri::next_plane(first))}));
  }
  EXPECT_EQ(project(a, a, c).result.second, 0);  // repeated vertex
}

TEST(Projection, CountsLikeAnyKernel) {
  tritri::PredicateCounts counts;
  const tritri::CountingKernel<tritri::DoubleKernel> k(counts);
  tritri::projection(k, P{0, 0, 0}, P{1, 0, 0}, P{0, 0, 1});
  EXPECT_EQ(counts.orient2d, 3u);
  EXPECT_EQ(counts.total(), 3u);
}

TEST(Projection, DominantPlaneDropsTheLargestNormalComponent) {
  const P o{0, 0, 0};
  EXPECT_EQ(tritri::dominant_plane(o, P{1, 0, 0.1}, P{0, 1, 0.2}), Plane::XY);  // normal ~ z
  EXPECT_EQ(tritri::dominant_plane(o, P{0.1, 1, 0}, P{0.2, 0, 1}), Plane::YZ);  // normal ~ x
  EXPECT_EQ(tritri::dominant_plane(o, P{0, 0.1, 1}, P{1, 0.2, 0}), Plane::ZX);  // normal ~ y
  // Ties go to the lower axis: normal (1, 1, 0) -> drop x.
  EXPECT_EQ(tritri::dominant_plane(o, P{0, 0, 1}, P{1, -1, 0}), Plane::YZ);
  // A hint only: in x = 0 with overflowing products the rounded normal is (NaN, 0, 0) and
  // the hint is ZX, where the triangle is degenerate; projection goes on to XY, then YZ.
  const P a{0, 0, 0}, b{0, 1e200, 1e200}, c{0, 1e200, 2e200};
  EXPECT_EQ(tritri::dominant_plane(a, b, c), Plane::ZX);
  const Call call = project(a, b, c, tritri::dominant_plane(a, b, c));
  EXPECT_EQ(call.result, (std::pair<Plane, int>{Plane::YZ, 1}));
  EXPECT_EQ(call.planes, (std::vector<Plane>{Plane::ZX, Plane::XY, Plane::YZ}));
}

// Implicit points give the hint from their cached rounded coordinates (before, the generic
// overload found no approximation for them and answered XY for every triangle, so every
// projection of a vertical triangle of implicit points began with an exact zero).
TEST(Projection, DominantPlaneOfImplicitPoints) {
  using tritri::ImplicitPoint;
  const P p{0, 0, -1}, q{0, 0, 1};  // the z axis, cut by planes z = h
  auto on_axis = [&](double h, double x, double y) {
    const ImplicitPoint lpi = ImplicitPoint::lpi(P{p[0] + x, p[1] + y, p[2]}, P{q[0] + x, q[1] + y, q[2]},
                                                 P{0, 0, h}, P{1, 0, h}, P{0, 1, h});
    EXPECT_FALSE(lpi.is_explicit());
    return lpi;
  };
  // In x = 0 (normal along x): YZ. In y = 0: ZX. In z = 0.5: XY.
  EXPECT_EQ(tritri::dominant_plane(on_axis(0.25, 0, 0), on_axis(0.5, 0, 1), on_axis(0.75, 0, 3)), Plane::YZ);
  EXPECT_EQ(tritri::dominant_plane(on_axis(0.25, 0, 0), on_axis(0.5, 1, 0), on_axis(0.75, 3, 0)), Plane::ZX);
  EXPECT_EQ(tritri::dominant_plane(on_axis(0.5, 0, 0), on_axis(0.5, 1, 0), on_axis(0.5, 0, 1)), Plane::XY);
  const ImplicitPoint e = ImplicitPoint::explicit_point(0, 0, 0);
  EXPECT_EQ(tritri::dominant_plane(e, ImplicitPoint::explicit_point(0, 1, 0), ImplicitPoint::explicit_point(0, 0, 1)),
            Plane::YZ);
}

TEST(Location, TwoBytesAndDefaultOutside) {
  EXPECT_EQ(sizeof(Location), 2u);
  EXPECT_EQ(Location{}.kind, Location::Outside);
  EXPECT_EQ(Location{}.id, -1);
  EXPECT_EQ(Location::interior(), (Location{Location::Interior, -1}));
  EXPECT_EQ(Location::edge(2), (Location{Location::Edge, 2}));
  EXPECT_EQ(Location::vertex(1), (Location{Location::Vertex, 1}));
}

TEST(Location, ClosedEdges) {
  // Vertex k is the common end of edge k (k -> k+1) and edge k+2 (k+2 -> k).
  EXPECT_EQ(tritri::closed_edges(Location::vertex(0)), 0b101);
  EXPECT_EQ(tritri::closed_edges(Location::vertex(1)), 0b011);
  EXPECT_EQ(tritri::closed_edges(Location::vertex(2)), 0b110);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(tritri::closed_edges(Location::edge(k)), 1 << k);
  EXPECT_EQ(tritri::closed_edges(Location::interior()), 0);
  EXPECT_EQ(tritri::closed_edges(Location::outside()), 0);
}

// Every sign triple but (0, 0, 0): the location must be the one whose closed edges are
// exactly the edge lines with sign zero.
TEST(Location, FromEdgeSignsAllCases) {
  for (int s0 = -1; s0 <= 1; ++s0)
    for (int s1 = -1; s1 <= 1; ++s1)
      for (int s2 = -1; s2 <= 1; ++s2) {
        const int s[3] = {s0, s1, s2};
        if (s0 == 0 && s1 == 0 && s2 == 0) continue;
        const Location l = tritri::location_from_edge_signs(s);
        if (s0 < 0 || s1 < 0 || s2 < 0) {
          EXPECT_EQ(l, Location::outside());
          continue;
        }
        const int zero_mask = (s0 == 0) | (s1 == 0) << 1 | (s2 == 0) << 2;
        EXPECT_NE(l.kind, Location::Outside);
        EXPECT_EQ(tritri::closed_edges(l), zero_mask) << s0 << s1 << s2;
      }
  const int on_edges_1_and_2[3] = {1, 0, 0};
  EXPECT_EQ(tritri::location_from_edge_signs(on_edges_1_and_2), Location::vertex(2));
}

}  // namespace
