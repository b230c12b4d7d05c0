// Hostile polygon faces and coplanar clusters (issue 36): inputs whose arrangement by the
// per-triangle pipeline costs up to the fourth power of their size. Each case finishes with
// a valid arrangement (check_arrangement, exact) or is refused with an InputError
// (too_large) that says why, before stage 3 allocates anything for it
// (stages/2_coplanar_budget.h, applied during detection). No timing assertions: the
// times are printed only.
// - a self-intersecting star polygon {n/(n/2)} given as ONE OFF face: its projection is
//   not simple, so the reader splits it into the fan from its first corner
//   (triangulate_polygon.h), whose n - 2 triangles all overlap each other;
// - n thin coplanar wedges whose centre lines all pass through one point, so every pair
//   crosses there.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <string>

#include "arrangements/arrange.h"
#include "arrangements/check_arrangement.h"
#include "arrangements/input_error.h"
#include "arrangements/load_triangle_soup.h"
#include "support/temp_dir.h"

namespace {

using arrangements::InputError;
using arrangements::InputErrorKind;
using tritri_test::TempDir;

// One OFF face of n corners: corner k at angle 2 pi (k * (n / 2) mod n) / n on the unit
// circle (n odd: a self-intersecting star whose edges nearly all cross each other).
void write_star(const std::string& path, int n) {
  std::ofstream f(path);
  f.precision(17);
  f << "OFF\n" << n << " 1 0\n";
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * static_cast<double>((static_cast<long long>(k) * (n / 2)) % n) / n;
    f << std::cos(a) << ' ' << std::sin(a) << " 0\n";
  }
  f << n;
  for (int k = 0; k < n; ++k) f << ' ' << k;
  f << '\n';
}

// n coplanar wedges in z = 0: wedge i from (-1, y) to (1, -y +- d), y = -1 + 2 (i + 1/2) / n,
// d = 1 / (2n); every centre line passes through the origin.
void write_wedges(const std::string& path, int n) {
  std::ofstream f(path);
  f.precision(17);
  f << "OFF\n" << 3 * n << ' ' << n << " 0\n";
  for (int i = 0; i < n; ++i) {
    const double y = -1 + 2 * (i + 0.5) / n, d = 0.5 / n;
    f << "-1 " << y << " 0\n1 " << -y + d << " 0\n1 " << -y - d << " 0\n";
  }
  for (int i = 0; i < n; ++i) f << "3 " << 3 * i << ' ' << 3 * i + 1 << ' ' << 3 * i + 2 << '\n';
}

// Arranges the file: true with a valid arrangement, false when refused as too large (the
// message checked); anything else fails the test.
bool arrange_or_refuse(const std::string& path, const std::string& what) {
  const auto start = std::chrono::steady_clock::now();
  const arrangements::TriangleSoup soup = arrangements::load_triangle_soup(path);
  arrangements::ArrangeOptions options;
  try {
    const arrangements::ArrangeResult r = arrangements::arrange(soup, options);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: arranged, %zu output triangles, %.2f s, peak %.0f MB\n", what.c_str(), r.mesh.triangles.size(), s,
                r.stats.peak_rss_mb);
    const arrangements::ArrangementCheck check = arrangements::check_arrangement(r.mesh);
    EXPECT_TRUE(check.ok()) << what << ": " << check.violations << " violations"
                            << (check.examples.empty() ? "" : ", e.g. " + check.examples[0]);
    EXPECT_GT(r.mesh.triangles.size(), soup.triangles.size()) << what;
    return true;
  } catch (const InputError& e) {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: refused in %.2f s: %s\n", what.c_str(), s, e.what());
    EXPECT_EQ(e.kind, InputErrorKind::too_large) << what;
    const std::string message = e.what();
    EXPECT_NE(message.find("coplanar triangles overlap each other too densely"), std::string::npos) << message;
    EXPECT_NE(message.find("polygon face"), std::string::npos) << message;
    return false;
  }
}

TEST(HostilePolygons, SmallStarFaceIsArranged) {
  TempDir dir;
  write_star(dir.path("star31.off"), 31);
  EXPECT_TRUE(arrange_or_refuse(dir.path("star31.off"), "star face of 31 corners"));
}

TEST(HostilePolygons, StarFaceOf2001CornersIsRefused) {
  TempDir dir;
  write_star(dir.path("star2001.off"), 2001);
  EXPECT_FALSE(arrange_or_refuse(dir.path("star2001.off"), "star face of 2001 corners"));
}

TEST(HostilePolygons, FewCoplanarWedgesAreArranged) {
  TempDir dir;
  write_wedges(dir.path("w30.off"), 30);
  EXPECT_TRUE(arrange_or_refuse(dir.path("w30.off"), "30 coplanar wedges"));
}

TEST(HostilePolygons, ManyCoplanarWedgesAreRefused) {
  TempDir dir;
  for (int n : {300, 3000}) {
    const std::string path = dir.path("w" + std::to_string(n) + ".off");
    write_wedges(path, n);
    EXPECT_FALSE(arrange_or_refuse(path, std::to_string(n) + " coplanar wedges"));
  }
}

// Layered tessellations of one square stay under the budget: ten 10 x 10 grids (200
// triangles each), the interior points of each moved differently, all in z = 0.
TEST(HostilePolygons, LayeredCoplanarTessellationsAreArranged) {
  TempDir dir;
  const int m = 10, layers = 10;
  std::ofstream f(dir.path("layers.off"));
  f.precision(17);
  const int per = (m + 1) * (m + 1);
  f << "OFF\n" << layers * per << ' ' << layers * 2 * m * m << " 0\n";
  unsigned state = 12345;
  auto jitter = [&] {
    state = state * 1103515245u + 12345u;
    return (static_cast<double>(state >> 8 & 0xffff) / 65535.0 - 0.5) * 0.6 / m;
  };
  for (int l = 0; l < layers; ++l)
    for (int i = 0; i <= m; ++i)
      for (int j = 0; j <= m; ++j) {
        const bool inner = i > 0 && i < m && j > 0 && j < m;
        f << static_cast<double>(i) / m + (inner ? jitter() : 0) << ' '
          << static_cast<double>(j) / m + (inner ? jitter() : 0) << " 0\n";
      }
  for (int l = 0; l < layers; ++l)
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) {
        const int a = l * per + i * (m + 1) + j, b = a + m + 1, c = b + 1, d = a + 1;
        if ((i + j + l) % 2 == 0)
          f << "3 " << a << ' ' << b << ' ' << c << "\n3 " << a << ' ' << c << ' ' << d << '\n';
        else
          f << "3 " << a << ' ' << b << ' ' << d << "\n3 " << b << ' ' << c << ' ' << d << '\n';
      }
  f.close();
  EXPECT_TRUE(arrange_or_refuse(dir.path("layers.off"), "ten coplanar tessellations"));
}

}  // namespace
