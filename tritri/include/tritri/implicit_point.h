// tritri/implicit_point.h
//
// ImplicitPoint: a point that is either explicit (three doubles) or implicit, defined
// exactly by explicit input points and never rounded:
//   LPI  the line through p, q meets the plane through r, s, t;
//   TPI  the three planes through (a0,a1,a2), (b0,b1,b2), (c0,c1,c2) meet.
// Predicates on any mix of them are in implicit_predicates.h; ImplicitKernel
// (implicit_kernel.h) makes them a tritri kernel.
//
// Construction: explicit_point(x, y, z); lpi(p, q, r, s, t); tpi(a0, ..., c2), where each
// argument is a std::array<double, 3> or an explicit ImplicitPoint. lpi / tpi check
// exactly that the point is defined (the line is not parallel to the plane, the planes
// are independent, every defining triple spans a plane) and throw std::domain_error
// otherwise; try_lpi / try_tpi return std::nullopt instead. Non-finite coordinates throw
// std::invalid_argument.
//
// Ownership and lifetime: a point owns copies of its defining coordinates; it does not
// refer to the arguments it was built from. Implicit points share one immutable,
// reference-counted representation between copies, so copying costs an atomic increment
// (explicit points: three doubles) and copies may be used from several threads.
//
// Cost: construction evaluates the homogeneous coordinates once in filtered double
// arithmetic (cached for the predicates' filter stage; about 50 flops for an LPI, 200
// for a TPI) and decides the sign of W, exactly if the filter cannot. The exact
// coordinates are computed only if a predicate's filter fails, then cached.
#pragma once

#include <CGAL/Gmpq.h>
#include <CGAL/Mpzf.h>
#include <mpfr.h>

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <algorithm>
#include <stdexcept>

#include "tritri/detail/filtered_value.h"
#include "tritri/detail/homogeneous.h"
#include "tritri/detail/offset.h"

namespace tritri {

class ImplicitPoint {
 public:
  using Coords = std::array<double, 3>;
  enum class Kind : unsigned char { Explicit, LPI, TPI };

  ImplicitPoint() = default;  // the explicit origin

  static ImplicitPoint explicit_point(double x, double y, double z) {
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      throw std::invalid_argument("tritri::ImplicitPoint: non-finite coordinate");
    ImplicitPoint p;
    p.xyz_ = {x, y, z};
    return p;
  }
  static ImplicitPoint explicit_point(const Coords& c) { return explicit_point(c[0], c[1], c[2]); }

  template <class A>
  static std::optional<ImplicitPoint> try_lpi(const A& p, const A& q, const A& r, const A& s, const A& t) {
    return make({coords(p), coords(q), coords(r), coords(s), coords(t)}, Kind::LPI);
  }
  template <class A>
  static ImplicitPoint lpi(const A& p, const A& q, const A& r, const A& s, const A& t) {
    auto pt = try_lpi(p, q, r, s, t);
    if (!pt)
      throw std::domain_error(
          "tritri::ImplicitPoint::lpi: undefined point (the line is parallel to the plane, "
          "p == q, or r, s, t are collinear)");
    return *pt;
  }
  template <class A>
  static std::optional<ImplicitPoint> try_tpi(const A& a0, const A& a1, const A& a2, const A& b0, const A& b1,
                                              const A& b2, const A& c0, const A& c1, const A& c2) {
    return make(
        {coords(a0), coords(a1), coords(a2), coords(b0), coords(b1), coords(b2), coords(c0), coords(c1), coords(c2)},
        Kind::TPI);
  }
  template <class A>
  static ImplicitPoint tpi(const A& a0, const A& a1, const A& a2, const A& b0, const A& b1, const A& b2, const A& c0,
                           const A& c1, const A& c2) {
    auto pt = try_tpi(a0, a1, a2, b0, b1, b2, c0, c1, c2);
    if (!pt)
      throw std::domain_error(
          "tritri::ImplicitPoint::tpi: undefined point (the three planes are not independent, "
          "or a defining triple is collinear)");
    return *pt;
  }

  Kind kind() const noexcept { return rep_ ? rep_->kind : Kind::Explicit; }
  bool is_explicit() const noexcept { return !rep_; }
  // The coordinates of an explicit point; for an implicit point, an approximation from the
  // filter stage (use to_double for the correctly rounded value).
  const Coords& approx() const noexcept { return xyz_; }
  // The defining explicit points: 5 for an LPI (p, q, r, s, t), 9 for a TPI; 0 if explicit.
  int input_count() const noexcept { return rep_ ? (rep_->kind == Kind::LPI ? 5 : 9) : 0; }
  const Coords& input(int i) const noexcept { return rep_->in[i]; }

  // Sign of W (+1 / -1) for implicit points, +1 for explicit ones.
  int w_sign() const noexcept { return rep_ ? rep_->w_sign : 1; }
  // True when a coordinate of the point (explicit) or of a defining point is nonzero and
  // below 2^-400 in magnitude: products of such numbers underflow, so the double filters
  // often fail on predicates of this point and the predicates try the long double one
  // sooner (a speed hint; every stage is exact).
  bool tiny_scale() const noexcept { return rep_ ? rep_->tiny : is_tiny(xyz_); }
  // Filtered homogeneous coordinates: the cached ones, or (x, y, z, 1) for explicit points.
  detail::Homogeneous<detail::FilteredValue> homogeneous_filtered() const noexcept {
    if (!rep_) return {xyz_[0], xyz_[1], xyz_[2], 1.0};
    return rep_->filtered;
  }
  // Cached filtered homogeneous coordinates (implicit points only).
  const detail::Homogeneous<detail::FilteredValue>& filtered() const noexcept { return rep_->filtered; }

  // Exact homogeneous coordinates of an implicit point, computed once and cached (thread
  // safe). Precondition: !is_explicit().
  const detail::Homogeneous<CGAL::Mpzf>& exact_homogeneous() const {
    std::call_once(rep_->exact_once, [this] {
      rep_->exact = std::make_unique<const detail::Homogeneous<CGAL::Mpzf>>(homogeneous<CGAL::Mpzf>());
    });
    return *rep_->exact;
  }

  // The homogeneous coordinates in the long double filter (detail::WideFilteredValue),
  // computed once and cached (thread safe), for the stage between the double filters and
  // the exact one. Precondition: !is_explicit().
  const detail::Homogeneous<detail::WideFilteredValue>& wide_homogeneous() const {
    std::call_once(rep_->wide_once, [this] {
      rep_->wide = std::make_unique<const detail::Homogeneous<detail::WideFilteredValue>>(
          homogeneous<detail::WideFilteredValue>());
    });
    return *rep_->wide;
  }

  // Rounding depths of the cached filtered coordinates of a point of this kind.
  static const detail::Homogeneous<detail::RoundingDepth>& rounding_depth(Kind kind) {
    static const std::array<Coords, 9> none{};  // the depths do not depend on the values
    static const auto lpi = evaluate<detail::RoundingDepth>(Kind::LPI, none.data());
    static const auto tpi = evaluate<detail::RoundingDepth>(Kind::TPI, none.data());
    static const detail::Homogeneous<detail::RoundingDepth> exact{0.0, 0.0, 0.0, 0.0};
    return kind == Kind::LPI ? lpi : (kind == Kind::TPI ? tpi : exact);
  }

  // (W (p - o), W) for an explicit origin o, evaluated with T from differences of the
  // defining points and o (detail/offset.h); explicit points: (p - o, 1). For T =
  // RoundingDepth the result depends only on the kind.
  template <class T>
  detail::Homogeneous<T> offset_homogeneous(const Coords& o) const {
    if (!rep_) {
      const auto d = detail::difference_leaves<T>(xyz_, o);
      return {d[0], d[1], d[2], T(1.0)};
    }
    const Coords* in = rep_->in;
    if (rep_->kind == Kind::LPI) return detail::lpi_offset<T>(in[0], in[1], in[2], in[3], in[4], o);
    return detail::tpi_offset<T>(std::span<const Coords, 9>(in, 9), o);
  }

  // Homogeneous coordinates evaluated with number type T (explicit: (x, y, z, 1)).
  template <class T>
  detail::Homogeneous<T> homogeneous() const {
    if (!rep_) return {T(xyz_[0]), T(xyz_[1]), T(xyz_[2]), T(1.0)};
    return evaluate<T>(rep_->kind, rep_->in);
  }

 private:
  // The shared representation; its defining points follow it in a block sized for the
  // kind (5 for an LPI, 9 for a TPI: pipelines hold millions of LPIs).
  struct Rep {
    Kind kind;
    bool tiny;  // tiny_scale()
    const Coords* in;  // the defining points, in the block below
    detail::Homogeneous<detail::FilteredValue> filtered;
    int w_sign;
    // Exact homogeneous coordinates, computed on first use by the exact stage only.
    mutable std::once_flag exact_once;
    mutable std::unique_ptr<const detail::Homogeneous<CGAL::Mpzf>> exact;
    // Long double filter coordinates, computed on first use (subnormal-scale input).
    mutable std::once_flag wide_once;
    mutable std::unique_ptr<const detail::Homogeneous<detail::WideFilteredValue>> wide;
  };
  template <int N>
  struct RepWith : Rep {
    std::array<Coords, N> storage;
  };

  static bool is_tiny(const Coords& c) noexcept {
    for (double x : c)
      if (x != 0 && std::fabs(x) < 0x1p-400) return true;
    return false;
  }

  static const Coords& coords(const Coords& c) { return c; }
  static const Coords& coords(const ImplicitPoint& p) {
    if (!p.is_explicit())
      throw std::invalid_argument("tritri::ImplicitPoint: lpi/tpi take explicit points as arguments");
    return p.xyz_;
  }

  // `in`: 5 points for an LPI, 9 for a TPI (none when kind is Explicit and T only serves
  // rounding_depth, which reads no input).
  template <class T>
  static detail::Homogeneous<T> evaluate(Kind kind, const Coords* in) {
    if (kind == Kind::LPI) return detail::lpi_homogeneous<T>(in[0], in[1], in[2], in[3], in[4]);
    return detail::tpi_homogeneous<T>(std::span<const Coords, 9>(in, 9));
  }

  static std::optional<ImplicitPoint> make(std::initializer_list<Coords> list, Kind kind) {
    for (const Coords& c : list)
      if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]))
        throw std::invalid_argument("tritri::ImplicitPoint: non-finite coordinate");
    std::shared_ptr<Rep> rep;
    if (kind == Kind::LPI) {
      auto r = std::make_shared<RepWith<5>>();
      std::copy(list.begin(), list.end(), r->storage.begin());
      r->in = r->storage.data();
      rep = std::move(r);
    } else {
      auto r = std::make_shared<RepWith<9>>();
      std::copy(list.begin(), list.end(), r->storage.begin());
      r->in = r->storage.data();
      rep = std::move(r);
    }
    rep->kind = kind;
    rep->tiny = std::any_of(list.begin(), list.end(), [](const Coords& c) { return is_tiny(c); });
    rep->filtered = evaluate<detail::FilteredValue>(kind, rep->in);
    // W = 0 exactly means the point is undefined: decide its sign exactly.
    int s = rep->filtered.w.certified_sign(rounding_depth(kind).w.depth);
    if (s == 0 && detail::kWideFilterUseful && detail::may_have_left_double_range(rep->filtered.w.perm))
      s = evaluate<detail::WideFilteredValue>(kind, rep->in).w.certified_sign(rounding_depth(kind).w.depth);
    if (s == 0) s = static_cast<int>(evaluate<CGAL::Mpzf>(kind, rep->in).w.sign());
    if (s == 0) return std::nullopt;
    rep->w_sign = s;
    ImplicitPoint p;
    const auto& f = rep->filtered;
    p.xyz_ = {f.x.v / f.w.v, f.y.v / f.w.v, f.z.v / f.w.v};
    p.rep_ = std::move(rep);
    return p;
  }

  Coords xyz_{0, 0, 0};
  std::shared_ptr<const Rep> rep_;
};

// The exact coordinates as rationals.
inline std::array<CGAL::Gmpq, 3> to_exact(const ImplicitPoint& p) {
  if (p.is_explicit()) return {CGAL::Gmpq(p.approx()[0]), CGAL::Gmpq(p.approx()[1]), CGAL::Gmpq(p.approx()[2])};
  const auto& h = p.exact_homogeneous();
  const CGAL::Gmpq w = CGAL::Gmpq(h.w);
  return {CGAL::Gmpq(h.x) / w, CGAL::Gmpq(h.y) / w, CGAL::Gmpq(h.z) / w};
}

// The coordinates rounded to the nearest double (ties to even), subnormals included:
// of rational coordinates, or of a point: exact for explicit points, correctly rounded
// from the exact rational for implicit ones
// (MPFR's exponent range is per thread, so this is thread-safe). Overflow gives +-inf.
inline std::array<double, 3> to_double(const std::array<CGAL::Gmpq, 3>& q) {
  std::array<double, 3> out;
  // Round once, to the double format including its subnormal range: MPFR's exponent range
  // set to double's and mpfr_subnormalize (rounding to 53 bits first and then to a
  // subnormal would round twice).
  const mpfr_exp_t old_emin = mpfr_get_emin(), old_emax = mpfr_get_emax();
  mpfr_set_emin(-1073);
  mpfr_set_emax(1024);
  mpfr_t r;
  mpfr_init2(r, 53);
  for (int k = 0; k < 3; ++k) {
    const int inexact = mpfr_set_q(r, q[k].mpq(), MPFR_RNDN);
    mpfr_subnormalize(r, inexact, MPFR_RNDN);
    out[k] = mpfr_get_d(r, MPFR_RNDN);
  }
  mpfr_clear(r);
  mpfr_set_emin(old_emin);
  mpfr_set_emax(old_emax);
  return out;
}

namespace detail {

// a / b (b != 0) rounded once to the nearest double (ties to even) into `out`, when that
// is a normal double or zero; false otherwise (subnormal or overflow: the caller rounds
// through the rational, which handles both). One MPFR division of the exact integers, in
// MPFR's default exponent range (no underflow or overflow there): no gcd of the large
// integers, which reducing the fraction x / w would take. A quotient rounded to 53 bits
// at or above 2^-1022 is also the double format's rounding: just below 2^-1022 the
// subnormals have the same spacing as the normals just above.
inline bool quotient_to_normal_double(mpz_srcptr a, mpz_srcptr b, double& out) {
  if (mpz_sgn(a) == 0) {
    out = 0.0;
    return true;
  }
  auto exact = [](mpfr_t r, mpz_srcptr z) {
    mpfr_init2(r, std::max<mpfr_prec_t>(static_cast<mpfr_prec_t>(mpz_sizeinbase(z, 2)), MPFR_PREC_MIN));
    mpfr_set_z(r, z, MPFR_RNDN);  // exact: the precision holds every bit
  };
  mpfr_t A, B, q;
  exact(A, a);
  exact(B, b);
  mpfr_init2(q, 53);
  mpfr_div(q, A, B, MPFR_RNDN);
  const mpfr_exp_t e = mpfr_get_exp(q);  // q = m 2^e, 1/2 <= |m| < 1
  const bool normal = e >= -1021 && e <= 1024;
  if (normal) out = mpfr_get_d(q, MPFR_RNDN);
  mpfr_clear(A);
  mpfr_clear(B);
  mpfr_clear(q);
  return normal;
}

// The nearest double to o + x / w, from the long double filter's values of x and w (their
// errors bounded by perm and rounding depth, filtered_value.h) and an explicit double o,
// when the filter certifies it; false otherwise (the caller rounds exactly). Why it is
// exact: the exact value lies within E of q = fl(o + fl(vx / vw)), E bounding the filter's
// errors, the division's and the sum's roundings, inflated for the roundings of E itself;
// d = q rounded to double is the nearest double to every value within E of q when E is
// below q's distance to both rounding boundaries d - gap_below / 2 and d + gap_above / 2
// (both exact in long double: q - d is, and it is a small multiple of q's last bit).
// Strict comparisons leave ties to the exact path. Only normal doubles with a margin
// (2^-1020 .. 2^1020) are certified. With o near the point (its filtered approximation)
// x / w is a tiny correction, and E is about u |q| (u = 2^-64): nearly always decisive.
inline bool certified_nearest_double(double o, const WideFilteredValue& x, int x_depth, const WideFilteredValue& w,
                                     int w_depth, double& out) {
  using L = long double;
  constexpr L u = std::numeric_limits<L>::epsilon() / 2;
  const L ex = x.perm * (x_depth * (u * (L(1) + L(0x1p-20))));
  const L ew = w.perm * (w_depth * (u * (L(1) + L(0x1p-20))));
  const L aw = w.v < 0 ? -w.v : w.v;
  if (!(aw > 2 * ew) || !std::isfinite(ex) || !std::isfinite(aw)) return false;
  const L r = x.v / w.v;
  const L ar = r < 0 ? -r : r;
  const L q = static_cast<L>(o) + r;
  const L aq = q < 0 ? -q : q;
  if (!(aq >= L(0x1p-1020) && aq <= L(0x1p1020))) return false;
  // |x/w - vx/vw| <= (ex + |vx/vw| ew) / (|vw| - ew); plus the division's and the sum's
  // roundings (u each, relative to their results).
  const L e = ((ex + ar * (1 + 2 * u) * ew) / (aw - ew) + 2 * u * ar + 2 * u * aq) * (L(1) + L(0x1p-50));
  const double d = static_cast<double>(q);
  const L delta = q - static_cast<L>(d);
  const L gap_below = static_cast<L>(d) - static_cast<L>(std::nextafter(d, -HUGE_VAL));
  const L gap_above = static_cast<L>(std::nextafter(d, HUGE_VAL)) - static_cast<L>(d);
  if (!(e < gap_above / 2 - delta && e < gap_below / 2 + delta)) return false;
  out = d;
  return true;
}

}  // namespace detail

namespace detail {
// Where certified_to_double filters at all: only x87's 64-bit long double; elsewhere long
// double is double (no gain) or software quad (slower than the exact path).
inline constexpr bool kCertifiedToDoubleRuns = kWideFilterUseful && std::numeric_limits<long double>::digits == 64;
}  // namespace detail

// to_double's fast path alone: the nearest doubles to p's coordinates when the long double
// filter certifies all three, else nullopt (also for explicit points, and where long
// double is not x87-like: detail::kWideFilterUseful). Evaluated as o + W (p - o) / W with
// o = p.approx(), so that only the small correction carries the filter's error. Cost: the
// homogeneous coordinates once in long double (about one more filtered predicate). Exact:
// a result is the correctly rounded double; ties, and points with a coordinate that is 0
// or outside [2^-1020, 2^1020] in magnitude, are declined.
inline std::optional<std::array<double, 3>> certified_to_double(const ImplicitPoint& p) {
  if constexpr (!detail::kCertifiedToDoubleRuns) return std::nullopt;
  if (p.is_explicit()) return std::nullopt;
  const std::array<double, 3>& o = p.approx();
  if (!std::isfinite(o[0]) || !std::isfinite(o[1]) || !std::isfinite(o[2])) return std::nullopt;
  const auto h = p.offset_homogeneous<detail::WideFilteredValue>(o);
  const auto depth = p.offset_homogeneous<detail::RoundingDepth>(o);
  std::array<double, 3> out;
  if (detail::certified_nearest_double(o[0], h.x, depth.x.depth, h.w, depth.w.depth, out[0]) &&
      detail::certified_nearest_double(o[1], h.y, depth.y.depth, h.w, depth.w.depth, out[1]) &&
      detail::certified_nearest_double(o[2], h.z, depth.z.depth, h.w, depth.w.depth, out[2]))
    return out;
  return std::nullopt;
}

inline std::array<double, 3> to_double(const ImplicitPoint& p) {
  if (p.is_explicit()) return p.approx();
  // Most points: the long double filter certifies the rounding, no exact arithmetic.
  if (const auto fast = certified_to_double(p)) return *fast;
  const auto& h = p.exact_homogeneous();
  // x / w = (xn wd) / (xd wn), the Mpzf values exported as fractions with power-of-two
  // denominators.
  const CGAL::Gmpq w(h.w);
  std::array<double, 3> out;
  bool done = true;
  mpz_t a, b;
  mpz_init(a);
  mpz_init(b);
  const CGAL::Mpzf* coordinate[3] = {&h.x, &h.y, &h.z};
  for (int k = 0; k < 3 && done; ++k) {
    const CGAL::Gmpq x(*coordinate[k]);
    mpz_mul(a, mpq_numref(x.mpq()), mpq_denref(w.mpq()));
    mpz_mul(b, mpq_denref(x.mpq()), mpq_numref(w.mpq()));
    done = detail::quotient_to_normal_double(a, b, out[k]);
  }
  mpz_clear(a);
  mpz_clear(b);
  return done ? out : to_double(to_exact(p));
}

}  // namespace tritri
