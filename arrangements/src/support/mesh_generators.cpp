#include "support/mesh_generators.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "support/bounding_box.h"

namespace arrangements {
namespace {

void finish(TriangleSoup& s) {
  s.label_set.assign(s.triangles.size(), 0);
  s.label_sets = {LabelSet{0}};
  s.source.resize(s.triangles.size());
  for (std::size_t i = 0; i < s.source.size(); ++i) s.source[i] = static_cast<std::int64_t>(i);
}

}  // namespace

TriangleSoup uv_sphere(const Vec3& c, double r, int rings, int segments) {
  TriangleSoup s;
  const double pi = std::numbers::pi;
  s.vertices.push_back({c[0], c[1], c[2] + r});  // north pole
  for (int i = 1; i < rings; ++i) {
    const double theta = pi * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2 * pi * j / segments;
      s.vertices.push_back({c[0] + r * std::sin(theta) * std::cos(phi), c[1] + r * std::sin(theta) * std::sin(phi),
                            c[2] + r * std::cos(theta)});
    }
  }
  s.vertices.push_back({c[0], c[1], c[2] - r});  // south pole
  const int south = static_cast<int>(s.vertices.size() - 1);
  auto ring = [&](int i, int j) { return 1 + (i - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) s.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
  for (int i = 1; i + 1 < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      s.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      s.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  for (int j = 0; j < segments; ++j) s.triangles.push_back({south, ring(rings - 1, j + 1), ring(rings - 1, j)});
  finish(s);
  return s;
}

TriangleSoup box(const Vec3& lo, const Vec3& hi) {
  TriangleSoup s;
  for (int i = 0; i < 8; ++i)
    s.vertices.push_back({i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]});
  // Outward-oriented faces, two triangles each.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    s.triangles.push_back({q[0], q[1], q[2]});
    s.triangles.push_back({q[0], q[2], q[3]});
  }
  finish(s);
  return s;
}

TriangleSoup grid(int n, double cell, double z0, double x0, double y0) {
  TriangleSoup s;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) s.vertices.push_back({x0 + cell * j, y0 + cell * i, z0});
  auto id = [&](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      s.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
    }
  finish(s);
  return s;
}

TriangleSoup rotated_copies(const TriangleSoup& soup, int k) {
  const Vec3 centre = bounding_box(soup.vertices).centre();
  const double cx = centre[0], cy = centre[1];
  TriangleSoup s;
  for (int c = 0; c < k; ++c) {
    const double angle = 2 * std::numbers::pi * c / k, ca = std::cos(angle), sa = std::sin(angle);
    const int base = static_cast<int>(s.vertices.size());
    for (const Vec3& v : soup.vertices) {
      const double x = v[0] - cx, y = v[1] - cy;
      s.vertices.push_back({cx + ca * x - sa * y, cy + sa * x + ca * y, v[2]});
    }
    for (const Tri& t : soup.triangles) s.triangles.push_back({base + t[0], base + t[1], base + t[2]});
  }
  finish(s);
  return s;
}

RotationMatrix rotation_matrix(const Vec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  const double x = axis[0], y = axis[1], z = axis[2];
  return {{{c + x * x * t, x * y * t - z * s, x * z * t + y * s},
           {y * x * t + z * s, c + y * y * t, y * z * t - x * s},
           {z * x * t - y * s, z * y * t + x * s, c + z * z * t}}};
}

TriangleSoup turned(TriangleSoup soup, const Vec3& centre, const Vec3& axis, double angle, const Vec3& shift) {
  const RotationMatrix R = rotation_matrix(axis, angle);
  for (Vec3& v : soup.vertices) {
    const Vec3 d{v[0] - centre[0], v[1] - centre[1], v[2] - centre[2]};
    for (int i = 0; i < 3; ++i) v[i] = R[i][0] * d[0] + R[i][1] * d[1] + R[i][2] * d[2] + centre[i] + shift[i];
  }
  return soup;
}

TriangleSoup concatenate(const std::vector<TriangleSoup>& parts) {
  TriangleSoup s;
  for (const TriangleSoup& part : parts) {
    const int base = static_cast<int>(s.vertices.size()), sets = static_cast<int>(s.label_sets.size());
    s.vertices.insert(s.vertices.end(), part.vertices.begin(), part.vertices.end());
    for (std::size_t t = 0; t < part.triangles.size(); ++t) {
      const Tri& f = part.triangles[t];
      s.triangles.push_back({base + f[0], base + f[1], base + f[2]});
      s.label_set.push_back(sets + part.label_set[t]);
    }
    for (LabelSet set : part.label_sets) {
      for (std::uint32_t& l : set) l += static_cast<std::uint32_t>(sets);
      s.label_sets.push_back(set);
    }
  }
  s.source.resize(s.triangles.size());
  for (std::size_t i = 0; i < s.source.size(); ++i) s.source[i] = static_cast<std::int64_t>(i);
  return s;
}

TriangleSoup concatenate(const TriangleSoup& a, const TriangleSoup& b) { return concatenate({a, b}); }

}  // namespace arrangements
