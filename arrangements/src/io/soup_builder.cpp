// SoupBuilder (see mesh_reader.h): what the readers find, polygons triangulated at the end;
// rational coordinates (rational_token.h) kept exactly for load_mesh_files.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "arrangements/as_input.h"
#include "io/mesh_reader.h"
#include "io/rational_token.h"
#include "io/triangulate_polygon.h"

namespace arrangements::detail {

void SoupBuilder::refuse_too_large(const char* what) const {
  refuse(InputErrorKind::too_large, path_,
         std::string("more than ") + std::to_string(kMaxIndexCount) + " " + what +
             " (the pipeline's int indices allow no more)");
}

void SoupBuilder::add_polygon(std::span<const int> corners) {
  if (corners.size() - 2 > kMaxIndexCount - triangles.size()) refuse_too_large("triangles");
  polygon_start_.push_back(polygon_corners_.size());
  polygon_triangle_.push_back(triangles.size());
  polygon_corners_.insert(polygon_corners_.end(), corners.begin(), corners.end());
  triangles.resize(triangles.size() + (corners.size() - 2));
}

void SoupBuilder::other_coordinate(long line, const std::string& what, int axis, std::string_view token, RealParse r,
                                   double& value) {
  CGAL::Gmpq q;
  // A decimal beyond the double range is non_finite for parse_real, but has an exact value.
  RationalParse p = RationalParse::not_rational;
  if (r != RealParse::non_finite) p = parse_rational(token, q);
  if (p == RationalParse::not_rational && decimals_exact_) p = parse_exact_decimal(token, q);
  switch (p) {
    case RationalParse::ok:
      break;
    case RationalParse::not_rational:
      if (token.find('/') != std::string_view::npos)
        refuse_at_line(InputErrorKind::malformed, path_, line,
                       what + quoted(token) + " is not a number (a decimal, or a rational N/D of decimal digits)");
      refuse_coordinate(path_, line, r, what, token);
    case RationalParse::huge:  // a decimal only: rationals have no limit
      refuse_at_line(InputErrorKind::too_large, path_, line,
                     what + quoted(token) + " is a huge decimal: an exponent beyond +-" +
                         std::to_string(kMaxDecimalExponent));
    case RationalParse::zero_denominator:
      refuse_at_line(InputErrorKind::malformed, path_, line, what + quoted(token) + " has a zero denominator");
  }
  if (!decimals_exact_ && beyond_double_range(q))  // read_exact_mesh reads any rational
    refuse_at_line(
        InputErrorKind::non_finite_coordinate, path_, line,
        what + quoted(token) + " is beyond the largest finite double (the pipeline needs finite bounding boxes)");
  if (exact_double(q, value)) {  // false beyond the double range
    if (value == 0 && token.front() == '-') value = -0.0;  // as the decimal "-0" reads
    return;
  }
  if (!exact_allowed_)
    refuse_at_line(InputErrorKind::unsupported_variant, path_, line,
                   what + quoted(token) +
                       " is an exact rational that is not a double: the file has exact rational coordinates, "
                       "which load_mesh_files reads (load_triangle_soup reads doubles only)");
  pending_[axis] = std::move(q);
  pending_axes_ |= 1u << axis;
  value = 0;  // unspecified (documented): the vertex is exact
}

void SoupBuilder::keep_exact(const Vec3& v) {
  ExactVec3 e;
  for (int k = 0; k < 3; ++k) e[k] = (pending_axes_ >> k & 1u) ? std::move(pending_[k]) : CGAL::Gmpq(v[k]);
  exact_.emplace_back(vertices.size(), std::move(e));
  pending_axes_ = 0;
}

template <class Coordinates>
void SoupBuilder::triangulate_polygons(const std::vector<Coordinates>& V) {
  std::vector<Tri> split;  // one face's triangles
  for (std::size_t k = 0; k < polygon_start_.size(); ++k) {
    const std::size_t begin = polygon_start_[k];
    const std::size_t end = k + 1 < polygon_start_.size() ? polygon_start_[k + 1] : polygon_corners_.size();
    split.clear();
    const bool certified =
        triangulate_polygon(V, std::span<const int>(polygon_corners_.data() + begin, end - begin), split);
    if (split.size() != end - begin - 2)
      throw std::logic_error("triangulate_polygon returned " + std::to_string(split.size()) + " triangles for " +
                             std::to_string(end - begin) + " corners");
    const auto first = static_cast<std::ptrdiff_t>(polygon_triangle_[k]);
    std::copy(split.begin(), split.end(), triangles.begin() + first);
    if (certified) {  // its triangles cannot meet improperly: one id, no candidate pairs
      if (polygon.empty()) polygon.assign(triangles.size(), -1);
      std::fill_n(polygon.begin() + first, split.size(), static_cast<std::int64_t>(first));
    }
  }
}

void SoupBuilder::finish() {
  if (exact_.empty()) {
    triangulate_polygons(vertices);
  } else {
    exact_vertices.reserve(vertices.size());
    std::size_t next = 0;  // into exact_
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      if (next < exact_.size() && exact_[next].first == i) {
        exact_vertices.push_back(std::move(exact_[next++].second));
      } else {
        exact_vertices.push_back(to_exact(vertices[i]));
      }
    }
    std::vector<Vec3>().swap(vertices);
    std::vector<std::pair<std::size_t, ExactVec3>>().swap(exact_);
    triangulate_polygons(exact_vertices);
  }
  std::vector<int>().swap(polygon_corners_);
  std::vector<std::size_t>().swap(polygon_start_);
  std::vector<std::size_t>().swap(polygon_triangle_);
}

}  // namespace arrangements::detail
