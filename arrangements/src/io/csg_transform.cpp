// Exact affine maps of multmatrix statements (csg_transform.h).
#include "io/csg_transform.h"

#include <algorithm>
#include <cstddef>
#include <utility>
#include <variant>

#include "arrangements/as_input.h"
#include "io/rational_token.h"

namespace arrangements::detail {

ExactAffine compose(const ExactAffine& outer, const ExactAffine& inner) {
  ExactAffine m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) {
      CGAL::Gmpq sum = c == 3 ? outer.rows[r][3] : CGAL::Gmpq(0);  // inner's fourth row is 0 0 0 1
      for (int k = 0; k < 3; ++k) sum += outer.rows[r][k] * inner.rows[k][c];
      m.rows[r][c] = sum;
    }
  return m;
}

bool is_identity(const ExactAffine& t) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c)
      if (t.rows[r][c] != CGAL::Gmpq(r == c ? 1 : 0)) return false;
  return true;
}

CGAL::Gmpq determinant(const ExactAffine& t) {
  const auto& a = t.rows;
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

namespace {

// t applied to points, skipping the products by 0 and 1 (most entries of the usual
// rotations, scalings and translations).
class ExactMap {
 public:
  explicit ExactMap(const ExactAffine& t) : t_(t) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        kind_[r][c] = t.rows[r][c] == CGAL::Gmpq(0) ? Entry::zero : t.rows[r][c] == CGAL::Gmpq(1) ? Entry::one : Entry::other;
  }
  ExactVec3 operator()(const ExactVec3& p) const {
    ExactVec3 q;
    for (int r = 0; r < 3; ++r) {
      CGAL::Gmpq sum = t_.rows[r][3];
      for (int c = 0; c < 3; ++c) {
        if (kind_[r][c] == Entry::one) sum += p[c];
        else if (kind_[r][c] == Entry::other) sum += t_.rows[r][c] * p[c];
      }
      q[r] = std::move(sum);
    }
    return q;
  }

 private:
  enum class Entry { zero, one, other };
  const ExactAffine& t_;
  Entry kind_[3][3];
};

bool exact_doubles(const ExactVec3& p, Vec3& d) {
  return exact_double(p[0], d[0]) && exact_double(p[1], d[1]) && exact_double(p[2], d[2]);
}

bool finite(const ExactVec3& p) {
  return !beyond_double_range(p[0]) && !beyond_double_range(p[1]) && !beyond_double_range(p[2]);
}

// Maps the vertices from k on; false when one leaves the double range.
bool map_exact(std::vector<ExactVec3>& vertices, std::size_t k, const ExactMap& map) {
  for (; k < vertices.size(); ++k) {
    vertices[k] = map(vertices[k]);
    if (!finite(vertices[k])) return false;
  }
  return true;
}

}  // namespace

bool transform_soup(AnyTriangleSoup& soup, const ExactAffine& t) {
  const ExactMap map(t);
  if (TriangleSoup* s = std::get_if<TriangleSoup>(&soup)) {
    // Doubles in place while every mapped coordinate is one; at the first that is not,
    // the soup turns exact (the vertices mapped so far are doubles: converted exactly).
    std::size_t k = 0;
    for (; k < s->vertices.size(); ++k) {
      const ExactVec3 q = map(to_exact(s->vertices[k]));
      Vec3 d;
      if (!exact_doubles(q, d)) break;
      s->vertices[k] = d;
    }
    if (k < s->vertices.size()) {
      ExactTriangleSoup e = to_exact(std::move(*s));
      if (!map_exact(e.vertices, k, map)) return false;
      soup = std::move(e);
    }
  } else if (!map_exact(std::get<ExactTriangleSoup>(soup).vertices, 0, map)) {
    return false;
  }
  if (determinant(t) < CGAL::Gmpq(0))
    std::visit([](auto& s) { for (Tri& tri : s.triangles) std::reverse(tri.begin(), tri.end()); }, soup);
  return true;
}

}  // namespace arrangements::detail
