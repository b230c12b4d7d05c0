// tritri/implicit_predicates.h
//
// Exact predicates on ImplicitPoints (any mix of explicit, LPI and TPI points):
// orient3d, orient2d (XY, YZ, ZX), equal, less and compare_xyz (lexicographic x, y, z).
//
// Each predicate is one polynomial in the points' homogeneous coordinates, written once
// over a number type and evaluated in stages: FilteredValue on offset and on cached
// coordinates (a certified error bound; decides almost always); then, when the filters
// cannot decide, the incidences known by construction (detail/incidence.h: points on one
// defining plane or line, coordinates fixed by axis-aligned planes), which decide most
// exact zeros without arithmetic; the same filter in long double where double's exponent
// range failed (subnormal-scale or overflowing monomials); then CGAL::Mpzf (exact).
// Predicates on explicit points only use the double backend (double_predicates.h).
// Exact for every input.
//
// Conventions are those of the kernel concept: orient3d(a, b, c, d) is the sign of
// det[b-a; c-a; d-a], orient2d the sign of det[b-a; c-a] in the projection.
// Homogeneous form: with rows (X, Y, Z, W), det4 = W_a W_b W_c W_d * (-orient3d), so
// orient3d = -sign(det4) * prod sign(W). When an operand e is explicit, subtracting its
// row leaves a 3x3 determinant of rows W_i (p_i - p_e), which has lower degree.
#pragma once

#include <CGAL/Mpzf.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <type_traits>

#include "tritri/detail/incidence.h"
#include "tritri/detail/staged_sign.h"
#include "tritri/detail/filtered_value.h"
#include "tritri/detail/homogeneous.h"
#include "tritri/double_predicates.h"
#include "tritri/implicit_point.h"
#include "tritri/sign.h"

namespace tritri {
namespace detail {

// The sign of p_k - q_k when known without arithmetic: one point built twice (a crossing
// found from both triangles), or both on planes (or lines) constant in k, by construction.
inline std::optional<int> compare_coordinate_by_construction(const ImplicitPoint& p, const ImplicitPoint& q, int k) {
  if (same_point_by_construction(p, q)) return 0;
  if (const auto pk = known_coordinate(p, k)) {
    if (const auto qk = known_coordinate(q, k)) return *pk < *qk ? -1 : (*pk > *qk ? 1 : 0);
  }
  return std::nullopt;
}

// The sign of p_k - q_k by the filters and the exact stage, for callers that already
// asked compare_coordinate_by_construction (not both explicit). with_offset = false skips
// the offset filter stage (for callers that already tried it).
inline int compare_coordinate_staged(const ImplicitPoint& p, const ImplicitPoint& q, int k, bool with_offset) {
  auto offset_stage = [&] {
    if (!with_offset) return 0;
    const auto& o = q.is_explicit() ? q.approx() : offset_origin({&p});
    return offset_filter_sign(
        [&](auto tag) {
          using T = decltype(tag);
          const auto hp = p.offset_homogeneous<T>(o);
          const auto hq = q.offset_homogeneous<T>(o);
          const T* pc[3] = {&hp.x, &hp.y, &hp.z};
          const T* qc[3] = {&hq.x, &hq.y, &hq.z};
          return *pc[k] * hq.w - *qc[k] * hp.w;
        },
        shape_of({&p, &q}));
  };
  const int s = staged_sign(
      [&](auto tag, const auto& get) {
        using T = decltype(tag);
        (void)tag;
        if (q.is_explicit()) {
          const auto& h = get(p);
          const T* hc[3] = {&h.x, &h.y, &h.z};
          return *hc[k] - T(q.approx()[k]) * h.w;
        }
        if (p.is_explicit()) {
          const auto& h = get(q);
          const T* hc[3] = {&h.x, &h.y, &h.z};
          return T(p.approx()[k]) * h.w - *hc[k];
        }
        const auto& hp = get(p);
        const auto& hq = get(q);
        const T* pc[3] = {&hp.x, &hp.y, &hp.z};
        const T* qc[3] = {&hq.x, &hq.y, &hq.z};
        return *pc[k] * hq.w - *qc[k] * hp.w;
      },
      shape_of({&p, &q}), offset_stage, [] { return false; }, any_tiny_scale({&p, &q}));
  return s * p.w_sign() * q.w_sign();
}

// sign(X_p W_q - X_q W_p) along axis k, times sign(W_p W_q): the sign of p_k - q_k.
inline int compare_coordinate(const ImplicitPoint& p, const ImplicitPoint& q, int k) {
  if (p.is_explicit() && q.is_explicit()) {
    const double a = p.approx()[k], b = q.approx()[k];
    return a < b ? -1 : (a > b ? 1 : 0);
  }
  if (const auto known = compare_coordinate_by_construction(p, q, k)) {
    ++implicit_predicate_stats().structural;
    return *known;
  }
  return compare_coordinate_staged(p, q, k, /*with_offset=*/true);
}

}  // namespace detail

// Sign of det[b-a; c-a; d-a] (Positive: d on the side of plane abc that (b-a) x (c-a)
// points to). Exact.
inline Sign orient3d(const ImplicitPoint& a, const ImplicitPoint& b, const ImplicitPoint& c, const ImplicitPoint& d) {
  if (a.is_explicit() && b.is_explicit() && c.is_explicit() && d.is_explicit())
    return orient3d(a.approx(), b.approx(), c.approx(), d.approx());
  const ImplicitPoint* pts[4] = {&a, &b, &c, &d};
  const int e = detail::first_explicit({&a, &b, &c, &d});
  const int w = a.w_sign() * b.w_sign() * c.w_sign() * d.w_sign();
  // Offset filter stage, as the sign of det4 of the rows (W (p - o), W).
  auto offset_det4 = [&] {
    const auto& o = detail::offset_origin({&a, &b, &c, &d});
    return detail::offset_filter_sign(
        [&](auto tag) {
          using T = decltype(tag);
          std::array<T, 4> rows[4];
          for (int i = 0; i < 4; ++i) {
            const auto h = pts[i]->offset_homogeneous<T>(o);
            rows[i] = {h.x, h.y, h.z, h.w};
          }
          return detail::det4<T>(rows[0], rows[1], rows[2], rows[3]);
        },
        detail::shape_of({&a, &b, &c, &d}));
  };
  auto on_one_plane = [&] { return detail::orient3d_known_zero({&a, &b, &c, &d}); };
  const bool tiny = detail::any_tiny_scale({&a, &b, &c, &d});
  if (e >= 0) {
    // orient3d = (-1)^e det3(rows W_i (p_i - p_e), i != e, in order) * prod sign(W_i).
    const auto& ref = pts[e]->approx();
    // The three operands other than e, in order.
    const ImplicitPoint& p0 = *pts[e == 0 ? 1 : 0];
    const ImplicitPoint& p1 = *pts[e <= 1 ? 2 : 1];
    const ImplicitPoint& p2 = *pts[e <= 2 ? 3 : 2];
    const int s = detail::staged_sign(
        [&](auto tag, const auto& get) {
          using T = decltype(tag);
          return detail::det3(detail::scaled_difference3<T>(p0, ref, get), detail::scaled_difference3<T>(p1, ref, get),
                              detail::scaled_difference3<T>(p2, ref, get));
        },
        detail::shape_of({&a, &b, &c, &d}), [&] { return e % 2 ? offset_det4() : -offset_det4(); },
        on_one_plane, tiny);
    return detail::to_sign((e % 2 ? -s : s) * w);
  }
  const int s = detail::staged_sign(
      [&](auto tag, const auto& get) {
        using T = decltype(tag);
        (void)tag;
        return detail::det4<T>(detail::row4<T>(get(a)), detail::row4<T>(get(b)), detail::row4<T>(get(c)),
                               detail::row4<T>(get(d)));
      },
      detail::shape_of({&a, &b, &c, &d}), offset_det4, on_one_plane, tiny);
  return detail::to_sign(-s * w);
}

namespace detail {
// orient2d on implicit points; with_offset = false skips the offset filter stage.
inline Sign orient2d_staged(const ImplicitPoint& a, const ImplicitPoint& b, const ImplicitPoint& c, Plane plane,
                            bool with_offset) {
  if (a.is_explicit() && b.is_explicit() && c.is_explicit()) return orient2d(a.approx(), b.approx(), c.approx(), plane);
  const auto axes = plane_axes(plane);
  const ImplicitPoint* pts[3] = {&a, &b, &c};
  const int e = detail::first_explicit({&a, &b, &c});
  const int w = a.w_sign() * b.w_sign() * c.w_sign();
  // Offset filter stage, as the sign of det3 of the rows (W (p - o) projected, W).
  auto offset_det3 = [&] {
    if (!with_offset) return 0;
    const auto& o = detail::offset_origin({&a, &b, &c});
    return detail::offset_filter_sign(
        [&](auto tag) {
          using T = decltype(tag);
          std::array<T, 3> rows[3];
          for (int i = 0; i < 3; ++i) {
            const auto h = pts[i]->offset_homogeneous<T>(o);
            const T* hc[3] = {&h.x, &h.y, &h.z};
            rows[i] = {*hc[axes[0]], *hc[axes[1]], h.w};
          }
          return detail::det3(rows[0], rows[1], rows[2]);
        },
        detail::shape_of({&a, &b, &c}));
  };
  auto on_one_line = [&] { return detail::orient2d_known_zero({&a, &b, &c}, plane); };
  const bool tiny = detail::any_tiny_scale({&a, &b, &c});
  if (e >= 0) {
    const auto& ref = pts[e]->approx();
    const int s = detail::staged_sign(
        [&](auto tag, const auto& get) {
          using T = decltype(tag);
          std::array<T, 2> rows[2];
          int n = 0;
          for (int i = 0; i < 3; ++i)
            if (i != e) rows[n++] = detail::scaled_difference<T>(*pts[i], ref, axes, get);
          return rows[0][0] * rows[1][1] - rows[0][1] * rows[1][0];
        },
        detail::shape_of({&a, &b, &c}), [&] { return e % 2 ? -offset_det3() : offset_det3(); }, on_one_line,
        tiny);
    return detail::to_sign((e % 2 ? -s : s) * w);
  }
  const int s = detail::staged_sign(
      [&](auto tag, const auto& get) {
        using T = decltype(tag);
        std::array<T, 3> rows[3];
        for (int i = 0; i < 3; ++i) {
          const auto& h = get(*pts[i]);
          const T* hc[3] = {&h.x, &h.y, &h.z};
          rows[i] = {*hc[axes[0]], *hc[axes[1]], h.w};
        }
        return detail::det3(rows[0], rows[1], rows[2]);
      },
      detail::shape_of({&a, &b, &c}), offset_det3, on_one_line, tiny);
  return detail::to_sign(s * w);
}
}  // namespace detail

// Sign of det[b-a; c-a] in the projection onto `plane`. Exact.
inline Sign orient2d(const ImplicitPoint& a, const ImplicitPoint& b, const ImplicitPoint& c, Plane plane) {
  return detail::orient2d_staged(a, b, c, plane, /*with_offset=*/true);
}

// Points with cached offset coordinates, for many predicates on points near one explicit
// origin (e.g. every point of one triangle of an arrangement): the first filter stage
// reads the cache instead of rebuilding W (p - o) per call; undecided calls fall back to
// the plain predicates (same results, exact).
//   OffsetPoint q = offset_point(p, o);   // o: an explicit point near p
// Precondition of the predicates: all operands were made with the same origin; the
// ImplicitPoint must outlive the OffsetPoint.
struct OffsetPoint {
  const ImplicitPoint* point = nullptr;
  detail::Homogeneous<detail::FilteredValue> h{};
};

inline OffsetPoint offset_point(const ImplicitPoint& p, const ImplicitPoint::Coords& origin) {
  return {&p, p.offset_homogeneous<detail::FilteredValue>(origin)};
}

// orient2d(*a.point, *b.point, *c.point, plane). Exact.
inline Sign orient2d(const OffsetPoint& a, const OffsetPoint& b, const OffsetPoint& c, Plane plane) {
  const ImplicitPoint& pa = *a.point;
  const ImplicitPoint& pb = *b.point;
  const ImplicitPoint& pc = *c.point;
  const auto axes = plane_axes(plane);
  const int shape = detail::shape_of({&pa, &pb, &pc});
  static std::atomic<int> depth_of_shape[27] = {};
  int depth = depth_of_shape[shape].load(std::memory_order_relaxed);
  auto rows_det = [&](const auto& ha, const auto& hb, const auto& hc) {
    using T = std::decay_t<decltype(ha.w)>;
    std::array<T, 3> rows[3];
    const detail::Homogeneous<T>* h[3] = {&ha, &hb, &hc};
    for (int i = 0; i < 3; ++i) {
      const T* hcoord[3] = {&h[i]->x, &h[i]->y, &h[i]->z};
      rows[i] = {*hcoord[axes[0]], *hcoord[axes[1]], h[i]->w};
    }
    return detail::det3(rows[0], rows[1], rows[2]);
  };
  if (depth == 0) {
    const ImplicitPoint::Coords o{0, 0, 0};  // the depth depends on the kinds only
    depth = rows_det(pa.offset_homogeneous<detail::RoundingDepth>(o), pb.offset_homogeneous<detail::RoundingDepth>(o),
                     pc.offset_homogeneous<detail::RoundingDepth>(o))
                .depth +
            1;
    depth_of_shape[shape].store(depth, std::memory_order_relaxed);
  }
  const int f = rows_det(a.h, b.h, c.h).certified_sign(depth);
  if (f != 0) {
    ++implicit_predicate_stats().filtered;
    return detail::to_sign(f * pa.w_sign() * pb.w_sign() * pc.w_sign());
  }
  return detail::orient2d_staged(pa, pb, pc, plane, /*with_offset=*/false);  // the offset filter failed
}

// Exact lexicographic (x, y, z) comparison: -1 if p < q, 0 if p == q, +1 if p > q.
// One call decides what less(p, q) and less(q, p) would, at the cost of one.
inline int compare_xyz(const ImplicitPoint& p, const ImplicitPoint& q) {
  if (p.is_explicit() && q.is_explicit()) {
    const auto &a = p.approx(), &b = q.approx();
    return a < b ? -1 : (b < a ? 1 : 0);
  }
  // Per axis: the filter on the cached absolute coordinates (cheap; decides points that
  // are far apart, most comparisons of a sort), then the comparison known by
  // construction (equal coordinates, which no filter decides), then the filter on offset
  // coordinates (computed once for all axes: they decide near points), then
  // compare_coordinate (exact).
  const int w = p.w_sign() * q.w_sign();
  const int shape = detail::shape_of({&p, &q});
  static std::atomic<int> depth_of_shape[2][9] = {};
  auto depth = [&](int which, auto&& compute) {
    int d = depth_of_shape[which][shape].load(std::memory_order_relaxed);
    if (d == 0) {
      d = compute() + 1;
      depth_of_shape[which][shape].store(d, std::memory_order_relaxed);
    }
    return d;
  };
  using detail::FilteredValue;
  using detail::RoundingDepth;
  const auto abs_p = p.homogeneous_filtered(), abs_q = q.homogeneous_filtered();
  const int abs_depth = depth(0, [&] {
    const auto& dp = ImplicitPoint::rounding_depth(p.kind());
    const auto& dq = ImplicitPoint::rounding_depth(q.kind());
    return (dp.x * dq.w - dq.x * dp.w).depth;
  });
  // With tiny-scale operands the offset filter is left to compare_coordinate's last
  // filter stage (staged_sign): the long double one decides first there.
  const bool tiny = p.tiny_scale() || q.tiny_scale();
  const ImplicitPoint::Coords* origin = nullptr;
  detail::Homogeneous<FilteredValue> off_p{}, off_q{};
  int off_depth = 0;
  for (int k = 0; k < 3; ++k) {
    const FilteredValue* ap[3] = {&abs_p.x, &abs_p.y, &abs_p.z};
    const FilteredValue* aq[3] = {&abs_q.x, &abs_q.y, &abs_q.z};
    int c = (*ap[k] * abs_q.w - *aq[k] * abs_p.w).certified_sign(abs_depth);
    if (c == 0) {
      // Equal coordinates, which no filter decides, are mostly known by construction.
      if (const auto known = detail::compare_coordinate_by_construction(p, q, k)) {
        ++implicit_predicate_stats().structural;
        if (*known != 0) return *known;
        continue;
      }
    }
    if (c == 0 && !tiny) {
      if (!origin) {
        origin = q.is_explicit() ? &q.approx() : &detail::offset_origin({&p});
        off_p = p.offset_homogeneous<FilteredValue>(*origin);
        off_q = q.offset_homogeneous<FilteredValue>(*origin);
        off_depth = depth(1, [&] {
          const auto hp = p.offset_homogeneous<RoundingDepth>(*origin);
          const auto hq = q.offset_homogeneous<RoundingDepth>(*origin);
          return (hp.x * hq.w - hq.x * hp.w).depth;  // the same for every axis
        });
      }
      const FilteredValue* op[3] = {&off_p.x, &off_p.y, &off_p.z};
      const FilteredValue* oq[3] = {&off_q.x, &off_q.y, &off_q.z};
      c = (*op[k] * off_q.w - *oq[k] * off_p.w).certified_sign(off_depth);
    }
    if (c != 0) {
      ++implicit_predicate_stats().filtered;
      c *= w;
    } else {
      c = detail::compare_coordinate_staged(p, q, k, /*with_offset=*/origin == nullptr || tiny);
    }
    if (c != 0) return c;
  }
  return 0;
}

// Exact coincidence.
inline bool equal(const ImplicitPoint& p, const ImplicitPoint& q) {
  for (int k = 0; k < 3; ++k)
    if (detail::compare_coordinate(p, q, k) != 0) return false;
  return true;
}

// Exact lexicographic (x, y, z) order.
inline bool less(const ImplicitPoint& p, const ImplicitPoint& q) { return compare_xyz(p, q) < 0; }

}  // namespace tritri
