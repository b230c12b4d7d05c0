// tritri/detail/expansion.h
//
// Exact floating-point expansion arithmetic (after Priest and Shewchuk, "Adaptive
// precision floating-point arithmetic and fast robust geometric predicates", 1997): a real number is
// held as a sum of floating-point numbers of increasing magnitude that do not overlap. Used by the
// double backend's exact stage, on doubles and, for inputs outside the range below, on
// long doubles (double_predicates.h). Every routine takes any binary floating-point type F
// with round-to-nearest-even (the component type of the expansions).
//
// Exactness: every operation here is exact provided no intermediate product overflows or
// loses bits to underflow. double_predicates.h calls it on doubles only for inputs whose
// nonzero coordinates have magnitudes in [2^-280, 2^280], which guarantees this: every
// component is then a multiple of 2^-332 and every product of three is a multiple of
// 2^-996 and smaller than 2^845. Other inputs run on long doubles where those have
// exponents to +-4096 (x87 extended precision): every component is then a multiple of
// 2^-1074 below 2^1026 and every product of three a multiple of 2^-3222 below 2^3110,
// far inside that range (kLongDoubleExpansionsExact in double_predicates.h); elsewhere
// they go to the GMP path (detail/gmp_orient.h).
#pragma once

#include <cstddef>
#include <limits>

namespace tritri::detail {

// A fixed-capacity expansion: v[0..n) in increasing magnitude, no zero components.
template <std::size_t N, class F = double>
struct Expansion {
  F v[N];
  std::size_t n = 0;
  void push(F x) noexcept { v[n++] = x; }
  static constexpr std::size_t capacity() noexcept { return N; }
  // The sign of an expansion is the sign of its largest component.
  int sign() const noexcept { return n == 0 ? 0 : (v[n - 1] > 0 ? 1 : (v[n - 1] < 0 ? -1 : 0)); }
};

// x + y == a + b exactly, with x = fl(a + b).
template <class F>
inline void two_sum(F a, F b, F& x, F& y) noexcept {
  x = a + b;
  const F bv = x - a;
  const F av = x - bv;
  y = (a - av) + (b - bv);
}

// x + y == a + b exactly; requires |a| >= |b| or a == 0.
template <class F>
inline void fast_two_sum(F a, F b, F& x, F& y) noexcept {
  x = a + b;
  y = b - (x - a);
}

// x + y == a - b exactly, with x = fl(a - b).
template <class F>
inline void two_diff(F a, F b, F& x, F& y) noexcept {
  x = a - b;
  const F bv = a - x;
  const F av = x + bv;
  y = (a - av) + (bv - b);
}

// hi + lo == a, each with at most half of F's significant bits (Veltkamp split; for
// double 26 bits with splitter 2^27 + 1, for x87 long double 32 bits with 2^32 + 1).
template <class F>
inline void split(F a, F& hi, F& lo) noexcept {
  constexpr F splitter = F(1ULL << ((std::numeric_limits<F>::digits + 1) / 2)) + 1;
  const F c = splitter * a;
  const F big = c - a;
  hi = c - big;
  lo = a - hi;
}

// x + y == a * b exactly, with x = fl(a * b) (Dekker's product, no FMA needed).
template <class F>
inline void two_product(F a, F b, F& x, F& y) noexcept {
  x = a * b;
  F ahi, alo, bhi, blo;
  split(a, ahi, alo);
  split(b, bhi, blo);
  const F e1 = x - ahi * bhi;
  const F e2 = e1 - alo * bhi;
  const F e3 = e2 - ahi * blo;
  y = alo * blo - e3;
}

// The exact difference a - b as an expansion of one or two components.
template <class F = double>
Expansion<2, F> diff(F a, F b) noexcept {
  Expansion<2, F> e;
  F x, y;
  two_diff(a, b, x, y);
  if (y != 0) e.push(y);
  if (x != 0) e.push(x);
  return e;
}

// h = e * b (Shewchuk's scale_expansion with zero elimination).
template <std::size_t N, class F>
Expansion<2 * N, F> scale(const Expansion<N, F>& e, F b) noexcept {
  Expansion<2 * N, F> h;
  if (e.n == 0 || b == 0) return h;
  F q, hh;
  two_product(e.v[0], b, q, hh);
  if (hh != 0) h.push(hh);
  for (std::size_t i = 1; i < e.n; ++i) {
    F p1, p0, sum;
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
template <class F>
std::size_t merge_sum(const F* e, std::size_t en, const F* f, std::size_t fn, F* out) noexcept {
  if (en == 0 || fn == 0) {
    const F* src = en ? e : f;
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
  F q = take();
  F qnew, hh;
  if (i < en && j < fn) {
    const F x = take();
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
template <std::size_t C, std::size_t M, class F>
void add_to(Expansion<C, F>& acc, const Expansion<M, F>& f) noexcept {
  F tmp[C];
  const std::size_t n = merge_sum(acc.v, acc.n, f.v, f.n, tmp);
  for (std::size_t i = 0; i < n; ++i) acc.v[i] = tmp[i];
  acc.n = n;
}

// h = e + f.
template <std::size_t N, std::size_t M, class F>
Expansion<N + M, F> sum(const Expansion<N, F>& e, const Expansion<M, F>& f) noexcept {
  Expansion<N + M, F> h;
  h.n = merge_sum(e.v, e.n, f.v, f.n, h.v);
  return h;
}

template <std::size_t N, class F>
Expansion<N, F> negate(Expansion<N, F> e) noexcept {
  for (std::size_t i = 0; i < e.n; ++i) e.v[i] = -e.v[i];
  return e;
}

// h = e * f.
template <std::size_t N, std::size_t M, class F>
Expansion<2 * N * M, F> product(const Expansion<N, F>& e, const Expansion<M, F>& f) noexcept {
  Expansion<2 * N * M, F> h;
  if (f.n == 1) {
    const Expansion<2 * N, F> s = scale(e, f.v[0]);
    h.n = s.n;
    for (std::size_t i = 0; i < s.n; ++i) h.v[i] = s.v[i];
    return h;
  }
  for (std::size_t j = 0; j < f.n; ++j) add_to(h, scale(e, f.v[j]));
  return h;
}

// The exact sign of det[u; v] for 2-vectors given as exact difference expansions of at
// most N components each (N = 1 when the differences were exact in double).
template <std::size_t N, class F>
int det2_sign(const Expansion<N, F>& ux, const Expansion<N, F>& uy, const Expansion<N, F>& vx,
              const Expansion<N, F>& vy) noexcept {
  return sum(product(ux, vy), negate(product(uy, vx))).sign();
}

// The exact sign of det[u; v; w] for 3-vectors given as exact difference expansions of at
// most N components each.
template <std::size_t N, class F>
int det3_sign(const Expansion<N, F> (&u)[3], const Expansion<N, F> (&v)[3], const Expansion<N, F> (&w)[3]) noexcept {
  const auto m0 = sum(product(v[1], w[2]), negate(product(v[2], w[1])));
  const auto m1 = sum(product(v[2], w[0]), negate(product(v[0], w[2])));
  const auto m2 = sum(product(v[0], w[1]), negate(product(v[1], w[0])));
  auto t = product(m0, u[0]);
  Expansion<3 * decltype(t){}.capacity(), F> total;
  add_to(total, t);
  add_to(total, product(m1, u[1]));
  add_to(total, product(m2, u[2]));
  return total.sign();
}

}  // namespace tritri::detail
