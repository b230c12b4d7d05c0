// The helpers of module_common.h: numpy and "n/d" string arguments in, the result dicts of
// arrange / boolean / csg out (double path, exact path, or rounded by round_safe). Kept apart
// from the bindings so that tritri_module.cpp and boolean_bindings.cpp share one definition.
#include "module_common.h"

#include <arrangements/arrange_stats.h>
#include <arrangements/round_mesh.h>
#include <arrangements/thread_count.h>
#include <tritri/implicit_point.h>

#include "support/worker_threads.h"

#include <gmp.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace tritri_python {

Eigen::Map<const RowMajorXd> as_eigen(const Coords& a) {
  return {a.data(), static_cast<Eigen::Index>(a.shape(0)), static_cast<Eigen::Index>(a.shape(1))};
}
Eigen::Map<const RowMajorXl> as_eigen(const Indices& a) {
  return {a.data(), static_cast<Eigen::Index>(a.shape(0)), static_cast<Eigen::Index>(a.shape(1))};
}

namespace {

arrangements::Classifier classifier_named(const std::string& name, const std::string& where = "tritri.arrange") {
  if (name == "tritri") return arrangements::Classifier::Tritri;
  if (name == "native") return arrangements::Classifier::Native;
  throw std::invalid_argument(where + ": unknown classifier '" + name + "' (use 'tritri' or 'native')");
}

// The keys and values of `arrange --stats` (arrange_stats.h: one table for both).
nb::dict stats_dict(const arrangements::ArrangeStats& s) {
  nb::dict d;
  arrangements::for_each_stat(s, [&d](const char* key, const auto& value, int) { d[key] = value; });
  return d;
}

// The rational written "n/d" in base 16 (n with an optional '-'; d > 0), as the package
// writes it (base 16: linear-time conversions both ways, and no limit on the digits).
CGAL::Gmpq parse_hex_rational(const std::string& text, const std::string& where, std::size_t index) {
  CGAL::Gmpq q;
  const bool ok = text.find('/') != std::string::npos && mpq_set_str(q.mpq(), text.c_str(), 16) == 0 &&
                  mpz_sgn(mpq_denref(q.mpq())) > 0;
  if (!ok)
    throw std::invalid_argument(where + "[" + std::to_string(index / 3) + ", " + std::to_string(index % 3) +
                                "] is not a rational written \"n/d\" in base 16");
  mpq_canonicalize(q.mpq());
  return q;
}

nb::object python_int(mpz_srcptr z) {
  std::string digits(mpz_sizeinbase(z, 16) + 2, '\0');
  mpz_get_str(digits.data(), 16, z);
  PyObject* n = PyLong_FromString(digits.c_str(), nullptr, 16);
  if (!n) throw nb::python_error();
  return nb::steal(n);
}

// The result dict: V (rounded, #V x 3) and V_is_exact from `rounded` / `exact_flags`, the
// faces' fields and stats from `out` (EigenArrangement or ExactEigenArrangement).
template <class Out>
nb::dict arrangement_dict(std::vector<double>&& rounded, std::vector<std::uint8_t>&& exact_flags, const Out& out) {
  const std::size_t nv = exact_flags.size(), nf = static_cast<std::size_t>(out.F.rows());
  std::vector<std::int64_t> f(3 * nf), source(nf), label_set(nf);
  for (std::size_t i = 0; i < nf; ++i) {
    for (int c = 0; c < 3; ++c) f[3 * i + c] = out.F(i, c);
    source[i] = out.source(i);
    label_set[i] = out.label_set(i);
  }
  nb::list label_sets;
  for (const arrangements::LabelSet& set : out.label_sets) {
    nb::list labels;
    for (const std::uint32_t l : set) labels.append(l);
    label_sets.append(nb::tuple(labels));
  }
  nb::dict d;
  d["V"] = numpy_array(std::move(rounded), {nv, 3});
  d["F"] = numpy_array(std::move(f), {nf, 3});
  d["source"] = numpy_array(std::move(source), {nf});
  d["label_set"] = numpy_array(std::move(label_set), {nf});
  d["label_sets"] = label_sets;
  d["V_is_exact"] = numpy_array(std::move(exact_flags), {nv}).attr("astype")("bool");
  d["stats"] = stats_dict(out.stats);
  return d;
}

// rounding="safe": the arrangement `out` (EigenArrangement or ExactEigenArrangement) rounded
// by round_safe (round_mesh.h). The dict is that of the rounded mesh, an arrangement of
// doubles itself: V (every row exact for it, V_is_exact all true), F, source, label_set,
// label_sets, and stats with the round_* keys. RoundingError becomes RuntimeError.
template <class Out>
nb::dict safely_rounded_dict(Out&& out, int threads, double max_move_relative,
                             const arrangements::TriangleSoup* input, bool keep_closed) {
  const auto nf = static_cast<std::size_t>(out.F.rows());
  arrangements::RoundedMesh rounded;
  arrangements::RoundReport report;
  {
    nb::gil_scoped_release release;
    auto to_mesh = [&](auto& mesh) {
      mesh.triangles.resize(nf);
      mesh.source.resize(nf);
      mesh.label_set.resize(nf);
      for (std::size_t i = 0; i < nf; ++i) {
        const auto r = static_cast<Eigen::Index>(i);
        mesh.triangles[i] = {out.F(r, 0), out.F(r, 1), out.F(r, 2)};
        mesh.source[i] = out.source(r);
        mesh.label_set[i] = out.label_set(r);
      }
      mesh.label_sets = out.label_sets;
    };
    arrangements::RoundSafeOptions options;
    options.threads = threads;
    options.max_move_relative = max_move_relative;
    options.input = input;
    options.keep_closed = keep_closed;
    if constexpr (std::is_same_v<std::decay_t<Out>, arrangements::EigenArrangement>) {
      arrangements::OutputMesh mesh;
      mesh.vertices = std::move(out.vertices);
      to_mesh(mesh);
      rounded = arrangements::round_safe(mesh, options, &report);
    } else {
      arrangements::ExactOutputMesh mesh;
      mesh.vertices.resize(static_cast<std::size_t>(out.V.rows()));
      for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        const auto r = static_cast<Eigen::Index>(v);
        mesh.vertices[v] = {out.V(r, 0), out.V(r, 1), out.V(r, 2)};
      }
      to_mesh(mesh);
      rounded = arrangements::round_safe(mesh, options, &report);
    }
  }
  arrangements::EigenArrangement plain;  // the rounded mesh's faces in the dict's layout
  const auto nr = static_cast<Eigen::Index>(rounded.triangles.size());
  plain.F.resize(nr, 3);
  plain.source.resize(nr);
  plain.label_set.resize(nr);
  for (Eigen::Index i = 0; i < nr; ++i) {
    for (int c = 0; c < 3; ++c) plain.F(i, c) = rounded.triangles[static_cast<std::size_t>(i)][c];
    plain.source(i) = static_cast<int>(rounded.source[static_cast<std::size_t>(i)]);
    plain.label_set(i) = rounded.label_set[static_cast<std::size_t>(i)];
  }
  plain.label_sets = std::move(rounded.label_sets);
  plain.stats = out.stats;
  add_round_report(report, rounded, plain.stats);
  std::vector<double> v(3 * rounded.vertices.size());
  for (std::size_t i = 0; i < rounded.vertices.size(); ++i)
    for (int c = 0; c < 3; ++c) v[3 * i + c] = rounded.vertices[i][c];
  return arrangement_dict(std::move(v), std::vector<std::uint8_t>(rounded.vertices.size(), 1), plain);
}

}  // namespace

RationalRows rational_rows(const std::vector<std::string>& values, const std::string& where) {
  if (values.size() % 3 != 0)
    throw std::invalid_argument(where + " must hold 3 coordinates per vertex, got " + std::to_string(values.size()));
  RationalRows V(static_cast<Eigen::Index>(values.size() / 3), 3);
  for (std::size_t i = 0; i < values.size(); ++i)
    V(static_cast<Eigen::Index>(i / 3), static_cast<Eigen::Index>(i % 3)) = parse_hex_rational(values[i], where, i);
  return V;
}

// GMP's rationals are in lowest terms already: the Fractions are made without normalising
// them again (a gcd of 30,000-digit numbers took most of a call's time).
nb::list fractions_of(const std::vector<ExactVec3>& rows) {
  const nb::object Fraction = nb::module_::import_("fractions").attr("Fraction");
  const bool coprime_constructor = nb::hasattr(Fraction, "_from_coprime_ints");  // Python >= 3.12
  const nb::object from_coprime = coprime_constructor ? Fraction.attr("_from_coprime_ints") : nb::none();
  nb::list out;
  for (const ExactVec3& row : rows)
    for (const CGAL::Gmpq& x : row) {
      nb::object n = python_int(mpq_numref(x.mpq())), d = python_int(mpq_denref(x.mpq()));
      out.append(coprime_constructor ? from_coprime(n, d) : Fraction(n, d, nb::arg("_normalize") = false));
    }
  return out;
}

namespace {
int worker_count(int threads) { return threads > 0 ? threads : tbb::info::default_concurrency(); }
}  // namespace

CallWorkers::CallWorkers(int threads)
    : limit_(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(worker_count(threads))) {
  arrangements::detail::start_worker_threads(worker_count(threads));
}

arrangements::ArrangeOptions arrange_options(const std::string& classifier, int threads, const std::string& where) {
  if (!arrangements::valid_thread_count(threads))
    throw std::invalid_argument(where + ": threads must be an integer from 0 to " +
                                std::to_string(arrangements::kMaxThreads) + ", got " + std::to_string(threads));
  arrangements::ArrangeOptions options;
  options.classifier = classifier_named(classifier, where);
  options.threads = threads;
  return options;
}

nb::dict double_path_dict(arrangements::EigenArrangement&& out, std::vector<ExactVec3>* exact, int threads,
                          bool round_safe, double round_max_move, const arrangements::TriangleSoup* input,
                          bool keep_closed) {
  if (round_safe) return safely_rounded_dict(std::move(out), threads, round_max_move, input, keep_closed);
  const auto nv = static_cast<std::size_t>(out.V.rows());
  std::vector<double> v(3 * nv);
  std::vector<std::uint8_t> flags(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    for (int c = 0; c < 3; ++c) v[3 * i + c] = out.V(i, c);
    flags[i] = out.V_is_exact(i) ? 1 : 0;
  }
  nb::dict d = arrangement_dict(std::move(v), std::move(flags), out);
  if (exact) d["V_exact"] = fractions_of(*exact);
  return d;
}

nb::dict exact_path_dict(arrangements::ExactEigenArrangement&& out, int threads, bool round_safe,
                         double round_max_move, bool keep_closed) {
  if (round_safe) return safely_rounded_dict(std::move(out), threads, round_max_move, nullptr, keep_closed);
  std::vector<ExactVec3> exact;
  std::vector<double> rounded;
  std::vector<std::uint8_t> flags;
  {
    nb::gil_scoped_release release;
    const auto nv = static_cast<std::size_t>(out.V.rows());
    exact.resize(nv);
    rounded.resize(3 * nv);
    flags.resize(nv);
    tbb::parallel_for(std::size_t{0}, nv, [&](std::size_t i) {
      const auto r = static_cast<Eigen::Index>(i);
      exact[i] = {out.V(r, 0), out.V(r, 1), out.V(r, 2)};
      const std::array<double, 3> x = tritri::to_double(exact[i]);
      bool is_exact = true;
      for (int c = 0; c < 3; ++c) {
        rounded[3 * i + c] = x[c];
        is_exact = is_exact && CGAL::Gmpq(x[c]) == exact[i][c];  // finite: |x| <= DBL_MAX
      }
      flags[i] = is_exact ? 1 : 0;
    });
  }
  nb::dict d = arrangement_dict(std::move(rounded), std::move(flags), out);
  d["V_exact"] = fractions_of(exact);
  return d;
}

}  // namespace tritri_python
