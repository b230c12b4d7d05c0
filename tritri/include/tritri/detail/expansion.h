// tritri/detail/expansion.h
//
// Exact floating-point expansion arithmetic (after Priest and Shewchuk, "Adaptive
// precision floating-point arithmetic and fast robust geometric predicates", 1997): a real number is
// held as a sum of doubles of increasing magnitude that do not overlap. Used by the
// double backend's exact stage.
//
// Exactness: every operation here is exact provided no intermediate product overflows or
// loses bits to underflow. double_predicates.h only calls it on inputs whose nonzero
// coordinates have magnitudes in [2^-280, 2^280], which guarantees this: every component
// is then a multiple of 2^-332 and every product of three is a multiple of 2^-996 and
// smaller than 2^845. Other inputs go to the GMP path (detail/gmp_orient.h).
#pragma once

#include <cstddef>

namespace tritri::detail {

// A fixed-capacity expansion: v[0..n) in increasing magnitude, no zero components.
template <std::size_t N>
struct Expansion {
  double v[N];
  std::size_t n = 0;
  void push(double x) noexcept { v[n++] = x; }
  static constexpr std::size_t capacity() noexcept { return N; }
  // The sign of an expansion is the sign of its largest component.
  int sign() const noexcept { return n == 0 ? 0 : (v[n - 1] > 0 ? 1 : (v[n - 1] < 0 ? -1 : 0)); }
};

// x + y == a + b exactly, with x = fl(a + b).
inline void two_sum(double a, double b, double& x, double& y) noexcept {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

// x + y == a + b exactly; requires |a| >= |b| or a == 0.
inline void fast_two_sum(double a, double b, double& x, double& y) noexcept {
  x = a + b;
  y = b - (x - a);
}

// x + y == a - b exactly, with x = fl(a - b).
inline void two_diff(double a, double b, double& x, double& y) noexcept {
  x = a - b;
  const double bv = a - x;
  const double av = x + bv;
  y = (a - av) + (bv - b);
}

// hi + lo == a, each with at most 26 significant bits (Veltkamp split).
inline void split(double a, double& hi, double& lo) noexcept {
  constexpr double splitter = 134217729.0;  // 2^27 + 1
  const double c = splitter * a;
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}

// x + y == a * b exactly, with x = fl(a * b) (Dekker's product, no FMA needed).
inline void two_product(double a, double b, double& x, double& y) noexcept {
  x = a * b;
  double ahi, alo, bhi, blo;
  split(a, ahi, alo);
  split(b, bhi, blo);
  const double e1 = x - ahi * bhi;
  const double e2 = e1 - alo * bhi;
  const double e3 = e2 - ahi * blo;
  y = alo * blo - e3;
}

// The exact difference a - b as an expansion of one or two components.
inline Expansion<2> diff(double a, double b) noexcept {
  Expansion<2> e;
  double x, y;
  two_diff(a, b, x, y);
  if (y != 0) e.push(y);
  if (x != 0) e.push(x);
  return e;
}

// h = e * b (Shewchuk's scale_expansion with zero elimination).
template <std::size_t N>
Expansion<2 * N> scale(const Expansion<N>& e, double b) noexcept {
  Expansion<2 * N> h;
  if (e.n == 0 || b == 0) return h;
  double q, hh;
  two_product(e.v[0], b, q, hh);
  if (hh != 0) h.push(hh);
  for (std::size_t i = 1; i < e.n; ++i) {
    double p1, p0, sum;
    two_product(e.v[i], b, p1, p0);
    two_sum(q, p0, sum, hh);
    if (hh != 0) h.push(hh);
    fast_two_sum(p1, sum, q, hh);
    if (hh != 0) h.push(hh);
  }
  if (q != 0) h.push(q);
  return h;
}

// out = e + f by merging components in order of magnitude (Shewchuk's
// fast_expansion_sum_zeroelim; exact for strongly nonoverlapping inputs under
// round-to-nearest-even, which every routine here produces). Returns out's length.
// out may not alias e or f.
inline std::size_t merge_sum(const double* e, std::size_t en, const double* f, std::size_t fn, double* out) noexcept {
  if (en == 0 || fn == 0) {
    const double* src = en ? e : f;
    const std::size_t n = en ? en : fn;
    for (std::size_t i = 0; i < n; ++i) out[i] = src[i];
    return n;
  }
  std::size_t i = 0, j = 0, n = 0;
  // Takes the next component of smaller magnitude.
  auto take = [&]() noexcept {
    if (j >= fn || (i < en && ((f[j] > e[i]) == (f[j] > -e[i])))) return e[i++];
    return f[j++];
  };
  double q = take();
  double qnew, hh;
  if (i < en && j < fn) {
    const double x = take();
    fast_two_sum(x, q, qnew, hh);
    q = qnew;
    if (hh != 0) out[n++] = hh;
  }
  while (i < en || j < fn) {
    two_sum(q, take(), qnew, hh);
    q = qnew;
    if (hh != 0) out[n++] = hh;
  }
  if (q != 0 || n == 0) out[n++] = q;
  if (n == 1 && out[0] == 0) n = 0;
  return n;
}

// Adds f to the expansion acc in place; acc's capacity C must hold the result.
template <std::size_t C, std::size_t M>
void add_to(Expansion<C>& acc, const Expansion<M>& f) noexcept {
  double tmp[C];
  const std::size_t n = merge_sum(acc.v, acc.n, f.v, f.n, tmp);
  for (std::size_t i = 0; i < n; ++i) acc.v[i] = tmp[i];
  acc.n = n;
}

// h = e + f.
template <std::size_t N, std::size_t M>
Expansion<N + M> sum(const Expansion<N>& e, const Expansion<M>& f) noexcept {
  Expansion<N + M> h;
  h.n = merge_sum(e.v, e.n, f.v, f.n, h.v);
  return h;
}

template <std::size_t N>
Expansion<N> negate(Expansion<N> e) noexcept {
  for (std::size_t i = 0; i < e.n; ++i) e.v[i] = -e.v[i];
  return e;
}

// h = e * f.
template <std::size_t N, std::size_t M>
Expansion<2 * N * M> product(const Expansion<N>& e, const Expansion<M>& f) noexcept {
  Expansion<2 * N * M> h;
  if (f.n == 1) {
    const Expansion<2 * N> s = scale(e, f.v[0]);
    h.n = s.n;
    for (std::size_t i = 0; i < s.n; ++i) h.v[i] = s.v[i];
    return h;
  }
  for (std::size_t j = 0; j < f.n; ++j) add_to(h, scale(e, f.v[j]));
  return h;
}

// The exact sign of det[u; v] for 2-vectors given as exact difference expansions of at
// most N components each (N = 1 when the differences were exact in double).
template <std::size_t N>
int det2_sign(const Expansion<N>& ux, const Expansion<N>& uy, const Expansion<N>& vx, const Expansion<N>& vy) noexcept {
  return sum(product(ux, vy), negate(product(uy, vx))).sign();
}

// The exact sign of det[u; v; w] for 3-vectors given as exact difference expansions of at
// most N components each.
template <std::size_t N>
int det3_sign(const Expansion<N> (&u)[3], const Expansion<N> (&v)[3], const Expansion<N> (&w)[3]) noexcept {
  const auto m0 = sum(product(v[1], w[2]), negate(product(v[2], w[1])));
  const auto m1 = sum(product(v[2], w[0]), negate(product(v[0], w[2])));
  const auto m2 = sum(product(v[0], w[1]), negate(product(v[1], w[0])));
  auto t = product(m0, u[0]);
  Expansion<3 * decltype(t){}.capacity()> total;
  add_to(total, t);
  add_to(total, product(m1, u[1]));
  add_to(total, product(m2, u[2]));
  return total.sign();
}

}  // namespace tritri::detail
