// tritri._tritri: the Python extension behind the `tritri` package (python/tritri/__init__.py,
// which normalises the arguments to C-contiguous float64 / int64 numpy arrays, or exact
// coordinates to hexadecimal "n/d" strings, and documents the functions). Every C++
// computation runs with the GIL released; every refused input raises ValueError
// (std::invalid_argument, std::domain_error and arrangements::InputError are translated), so
// bad input never takes the interpreter down. Exact coordinates come back as
// fractions.Fraction objects (flat lists, 3 per vertex; the package shapes them).
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <CGAL/Gmpq.h>

#include <Eigen/Core>

#include <arrangements/arrange_eigen.h>
#include <arrangements/boolean.h>
#include <arrangements/boolean_eigen.h>
#include <arrangements/load_csg.h>
#include <arrangements/input_error.h>
#include <arrangements/load_triangle_soup.h>
#include <arrangements/arrange_stats.h>
#include <arrangements/round_mesh.h>
#include <arrangements/thread_count.h>
#include <tritri/classify.h>
#include <tritri/double_kernel.h>
#include <tritri/intersections.h>
#include <tritri/rational_kernel.h>
#include <tritri/result.h>
#include <tritri/self_intersections.h>

#include <climits>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace nb = nanobind;

namespace {

using Coords = nb::ndarray<const double, nb::ndim<2>, nb::c_contig, nb::device::cpu>;
using Indices = nb::ndarray<const std::int64_t, nb::ndim<2>, nb::c_contig, nb::device::cpu>;
using Labels = nb::ndarray<const std::int64_t, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using RowMajorXd = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using RowMajorXl = Eigen::Matrix<std::int64_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using LabelVector = Eigen::Map<const Eigen::Matrix<std::int64_t, Eigen::Dynamic, 1>>;
using arrangements::ExactVec3;

Eigen::Map<const RowMajorXd> as_eigen(const Coords& a) {
  return {a.data(), static_cast<Eigen::Index>(a.shape(0)), static_cast<Eigen::Index>(a.shape(1))};
}
Eigen::Map<const RowMajorXl> as_eigen(const Indices& a) {
  return {a.data(), static_cast<Eigen::Index>(a.shape(0)), static_cast<Eigen::Index>(a.shape(1))};
}

// A numpy array that owns `data`.
template <class T>
nb::object numpy_array(std::vector<T>&& data, std::initializer_list<std::size_t> shape) {
  auto* owned = new std::vector<T>(std::move(data));
  nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<std::vector<T>*>(p); });
  return nb::cast(nb::ndarray<nb::numpy, T>(owned->data(), shape, owner));
}

tritri::DoubleKernel::Point triangle_corner(const Coords& t, std::size_t row, const char* name) {
  tritri::DoubleKernel::Point p;
  for (std::size_t c = 0; c < 3; ++c) {
    p[c] = t.data()[3 * row + c];
    if (!std::isfinite(p[c]))
      throw std::invalid_argument(std::string("tritri.classify: ") + name + "[" + std::to_string(row) + ", " +
                                  std::to_string(c) + "] is not a finite coordinate");
  }
  return p;
}

tritri::Result classify(const Coords& a, const Coords& b) {
  for (const auto& [t, name] : {std::pair<const Coords&, const char*>{a, "a"}, {b, "b"}})
    if (t.shape(0) != 3 || t.shape(1) != 3)
      throw std::invalid_argument(std::string("tritri.classify: ") + name +
                                  " must be a 3 x 3 array (one vertex per row), got " + std::to_string(t.shape(0)) +
                                  " x " + std::to_string(t.shape(1)));
  const auto a0 = triangle_corner(a, 0, "a"), a1 = triangle_corner(a, 1, "a"), a2 = triangle_corner(a, 2, "a");
  const auto b0 = triangle_corner(b, 0, "b"), b1 = triangle_corner(b, 1, "b"), b2 = triangle_corner(b, 2, "b");
  return tritri::classify<tritri::DoubleKernel>(a0, a1, a2, b0, b1, b2);
}

// (pairs as a k x 2 int64 array, results as a list of Result).
nb::tuple pairs_and_results(std::vector<tritri::IntersectingPair>&& found) {
  std::vector<std::int64_t> ij(2 * found.size());
  nb::list results;
  for (std::size_t k = 0; k < found.size(); ++k) {
    ij[2 * k] = found[k].i;
    ij[2 * k + 1] = found[k].j;
    results.append(nb::cast(found[k].result));
  }
  const std::size_t rows = found.size();
  return nb::make_tuple(numpy_array(std::move(ij), {rows, 2}), results);
}

nb::tuple self_intersections(const Coords& V, const Indices& F) {
  std::vector<tritri::IntersectingPair> found;
  {
    nb::gil_scoped_release release;
    found = tritri::self_intersections(as_eigen(V), as_eigen(F));
  }
  return pairs_and_results(std::move(found));
}

nb::tuple intersections(const Coords& V1, const Indices& F1, const Coords& V2, const Indices& F2) {
  std::vector<tritri::IntersectingPair> found;
  {
    nb::gil_scoped_release release;
    found = tritri::intersections(as_eigen(V1), as_eigen(F1), as_eigen(V2), as_eigen(F2));
  }
  return pairs_and_results(std::move(found));
}

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

// --- exact coordinates: hexadecimal "n/d" strings in, fractions.Fraction out ------------

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

// 3n such strings, row after row, as an n x 3 matrix; `where` names the argument.
using RationalRows = Eigen::Matrix<CGAL::Gmpq, Eigen::Dynamic, 3>;
RationalRows rational_rows(const std::vector<std::string>& values, const std::string& where) {
  if (values.size() % 3 != 0)
    throw std::invalid_argument(where + " must hold 3 coordinates per vertex, got " + std::to_string(values.size()));
  RationalRows V(static_cast<Eigen::Index>(values.size() / 3), 3);
  for (std::size_t i = 0; i < values.size(); ++i)
    V(static_cast<Eigen::Index>(i / 3), static_cast<Eigen::Index>(i % 3)) = parse_hex_rational(values[i], where, i);
  return V;
}

// The exact entries of classify, self_intersections and intersections (RationalKernel):
// coordinates as such strings, checked by the Python layer (shapes, |x| <= DBL_MAX).
tritri::Result classify_exact(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  const RationalRows A = rational_rows(a, "tritri.classify: a"), B = rational_rows(b, "tritri.classify: b");
  if (A.rows() != 3 || B.rows() != 3)
    throw std::invalid_argument("tritri.classify: a and b must be 3 x 3 arrays (one vertex per row)");
  auto p = [](const RationalRows& M, Eigen::Index r) {
    return tritri::RationalKernel::Point(M(r, 0), M(r, 1), M(r, 2));
  };
  return tritri::classify<tritri::RationalKernel>(p(A, 0), p(A, 1), p(A, 2), p(B, 0), p(B, 1), p(B, 2));
}

nb::tuple self_intersections_exact(const std::vector<std::string>& V, const Indices& F) {
  std::vector<tritri::IntersectingPair> found;
  {
    nb::gil_scoped_release release;
    found = tritri::self_intersections(rational_rows(V, "tritri.self_intersections: V"), as_eigen(F));
  }
  return pairs_and_results(std::move(found));
}

nb::tuple intersections_exact(const std::vector<std::string>& V1, const Indices& F1, const std::vector<std::string>& V2,
                              const Indices& F2) {
  std::vector<tritri::IntersectingPair> found;
  {
    nb::gil_scoped_release release;
    found = tritri::intersections(rational_rows(V1, "tritri.intersections: V1"), as_eigen(F1),
                                  rational_rows(V2, "tritri.intersections: V2"), as_eigen(F2));
  }
  return pairs_and_results(std::move(found));
}

nb::object python_int(mpz_srcptr z) {
  std::string digits(mpz_sizeinbase(z, 16) + 2, '\0');
  mpz_get_str(digits.data(), 16, z);
  PyObject* n = PyLong_FromString(digits.c_str(), nullptr, 16);
  if (!n) throw nb::python_error();
  return nb::steal(n);
}

// Every coordinate of `rows` as a fractions.Fraction, row after row (3 per row).
nb::list fractions_of(const std::vector<ExactVec3>& rows) {
  const nb::object Fraction = nb::module_::import_("fractions").attr("Fraction");
  nb::list out;
  for (const ExactVec3& row : rows)
    for (const CGAL::Gmpq& x : row)
      out.append(Fraction(python_int(mpq_numref(x.mpq())), python_int(mpq_denref(x.mpq()))));
  return out;
}

// --- arrange ----------------------------------------------------------------------------

arrangements::ArrangeOptions arrange_options(const std::string& classifier, int threads,
                                             const std::string& where = "tritri.arrange") {
  if (!arrangements::valid_thread_count(threads))
    throw std::invalid_argument(where + ": threads must be an integer from 0 to " +
                                std::to_string(arrangements::kMaxThreads) + ", got " + std::to_string(threads));
  arrangements::ArrangeOptions options;
  options.classifier = classifier_named(classifier, where);
  options.threads = threads;
  return options;
}

std::optional<LabelVector> label_vector(const std::optional<Labels>& labels) {
  std::optional<LabelVector> Le;
  if (labels) Le.emplace(labels->data(), static_cast<Eigen::Index>(labels->shape(0)));
  return Le;
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
                             const arrangements::TriangleSoup* input = nullptr) {
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
  add_round_report(report, plain.stats);
  std::vector<double> v(3 * rounded.vertices.size());
  for (std::size_t i = 0; i < rounded.vertices.size(); ++i)
    for (int c = 0; c < 3; ++c) v[3 * i + c] = rounded.vertices[i][c];
  return arrangement_dict(std::move(v), std::vector<std::uint8_t>(rounded.vertices.size(), 1), plain);
}

nb::dict double_path_dict(arrangements::EigenArrangement&& out, std::vector<ExactVec3>* exact, int threads,
                          bool round_safe, double round_max_move, const arrangements::TriangleSoup* input);
nb::dict exact_path_dict(arrangements::ExactEigenArrangement&& out, int threads, bool round_safe,
                         double round_max_move);

// The double path; exact_output adds V_exact (the exact output vertices as Fractions).
nb::dict arrange(const Coords& V, const Indices& F, std::optional<Labels> labels, const std::string& classifier,
                 int threads, bool exact_output, bool round_safe, double round_max_move) {
  const arrangements::ArrangeOptions options = arrange_options(classifier, threads);
  arrangements::EigenArrangement out;
  std::vector<ExactVec3> exact;
  arrangements::TriangleSoup input;  // for round_safe's last resort
  {
    nb::gil_scoped_release release;
    // Checked once, by the Eigen entry point (int64 indices and labels are range-checked
    // there before they are narrowed).
    const std::optional<LabelVector> Le = label_vector(labels);
    out = arrangements::detail::arrange_eigen(as_eigen(V), as_eigen(F), options, Le ? &*Le : nullptr, "tritri.arrange",
                                              exact_output ? &exact : nullptr, round_safe ? &input : nullptr);
  }
  return double_path_dict(std::move(out), exact_output ? &exact : nullptr, threads, round_safe, round_max_move,
                          round_safe ? &input : nullptr);
}

// The dict of a double-path result `out` (arrange, boolean, csg): rounded by round_safe
// when round_safe (input: round_safe's last resort, may be null), else V, V_is_exact and,
// when exact is given (the exact output vertices), V_exact.
nb::dict double_path_dict(arrangements::EigenArrangement&& out, std::vector<ExactVec3>* exact, int threads,
                          bool round_safe, double round_max_move, const arrangements::TriangleSoup* input) {
  if (round_safe) return safely_rounded_dict(std::move(out), threads, round_max_move, input);
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

// The exact path: V as 3 #V hexadecimal "n/d" strings, row after row. The dict of arrange
// plus V_exact; V is V_exact rounded to the nearest double (ties to even).
nb::dict arrange_exact(const std::vector<std::string>& V, const Indices& F, std::optional<Labels> labels,
                       const std::string& classifier, int threads, bool round_safe, double round_max_move) {
  const arrangements::ArrangeOptions options = arrange_options(classifier, threads);
  arrangements::ExactEigenArrangement out;
  {
    nb::gil_scoped_release release;
    const RationalRows Ve = rational_rows(V, "tritri.arrange: V");
    const std::optional<LabelVector> Le = label_vector(labels);
    out = arrangements::detail::arrange_eigen_exact(Ve, as_eigen(F), options, Le ? &*Le : nullptr, "tritri.arrange");
  }
  return exact_path_dict(std::move(out), threads, round_safe, round_max_move);
}

// The dict of an exact-path result `out` (arrange, boolean, csg): rounded by round_safe
// when round_safe, else V (V_exact rounded to the nearest doubles), V_is_exact, V_exact.
nb::dict exact_path_dict(arrangements::ExactEigenArrangement&& out, int threads, bool round_safe,
                         double round_max_move) {
  if (round_safe) return safely_rounded_dict(std::move(out), threads, round_max_move);
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

// A mesh file as plain arrays (the pipeline's loader load_mesh_files: OBJ, OFF, STL, PLY;
// polygons triangulated by the loader; vertices unmerged): V (float64) when every
// coordinate is a double, else V_exact (Fractions, 3 per vertex); F. Bad files raise
// ValueError (InputError).
nb::dict load_mesh(const std::string& path) {
  if (path.find('\0') != std::string::npos)  // the loader would open the path up to it
    throw std::invalid_argument("tritri.load_mesh: the path contains a NUL character");
  arrangements::AnyTriangleSoup any;
  {
    nb::gil_scoped_release release;
    any = arrangements::load_mesh_files({path});
  }
  nb::dict d;
  const std::vector<arrangements::Tri>& triangles =
      std::visit([](const auto& soup) -> const std::vector<arrangements::Tri>& { return soup.triangles; }, any);
  if (const auto* soup = std::get_if<arrangements::TriangleSoup>(&any)) {
    const std::size_t nv = soup->vertices.size();
    std::vector<double> v(3 * nv);
    for (std::size_t i = 0; i < nv; ++i)
      for (int c = 0; c < 3; ++c) v[3 * i + c] = soup->vertices[i][c];
    d["V"] = numpy_array(std::move(v), {nv, 3});
  } else {
    d["V_exact"] = fractions_of(std::get<arrangements::ExactTriangleSoup>(any).vertices);
  }
  const std::size_t nf = triangles.size();
  std::vector<std::int64_t> f(3 * nf);
  for (std::size_t i = 0; i < nf; ++i)
    for (int c = 0; c < 3; ++c) f[3 * i + c] = triangles[i][c];
  d["F"] = numpy_array(std::move(f), {nf, 3});
  return d;
}

// --- boolean and csg ----------------------------------------------------------------------

arrangements::BooleanOp boolean_op_named(const std::string& name) {
  if (name == "union") return arrangements::BooleanOp::Union;
  if (name == "intersection") return arrangements::BooleanOp::Intersection;
  if (name == "difference") return arrangements::BooleanOp::Difference;
  if (name == "xor") return arrangements::BooleanOp::Xor;
  throw std::invalid_argument("tritri.boolean: unknown op '" + name +
                              "' (use 'union', 'intersection', 'difference' or 'xor')");
}

// The double path of tritri.boolean: operand i is (V[i], F[i]), label i (boolean_eigen.h).
// OpenOperandError becomes ValueError (the translator below).
nb::dict boolean(const std::vector<Coords>& V, const std::vector<Indices>& F, const std::string& op,
                 const std::string& classifier, int threads, bool exact_output, bool round_safe,
                 double round_max_move) {
  const arrangements::ArrangeOptions options = arrange_options(classifier, threads, "tritri.boolean");
  const arrangements::BooleanOp boolean_op = boolean_op_named(op);
  arrangements::EigenArrangement out;
  std::vector<ExactVec3> exact;
  {
    nb::gil_scoped_release release;
    std::vector<Eigen::Map<const RowMajorXd>> Ve;
    std::vector<Eigen::Map<const RowMajorXl>> Fe;
    for (const Coords& v : V) Ve.push_back(as_eigen(v));
    for (const Indices& f : F) Fe.push_back(as_eigen(f));
    out = arrangements::detail::boolean_eigen(Ve, Fe, arrangements::operation_tree(boolean_op, static_cast<int>(V.size())),
                                              options, "tritri.boolean", exact_output ? &exact : nullptr);
  }
  return double_path_dict(std::move(out), exact_output ? &exact : nullptr, threads, round_safe, round_max_move,
                          nullptr);
}

// The exact path of tritri.boolean: each operand's V as hexadecimal "n/d" strings.
nb::dict boolean_exact(const std::vector<std::vector<std::string>>& V, const std::vector<Indices>& F,
                       const std::string& op, const std::string& classifier, int threads, bool round_safe,
                       double round_max_move) {
  const arrangements::ArrangeOptions options = arrange_options(classifier, threads, "tritri.boolean");
  const arrangements::BooleanOp boolean_op = boolean_op_named(op);
  arrangements::ExactEigenArrangement out;
  {
    nb::gil_scoped_release release;
    std::vector<RationalRows> Ve;
    std::vector<Eigen::Map<const RowMajorXl>> Fe;
    for (std::size_t i = 0; i < V.size(); ++i)
      Ve.push_back(rational_rows(V[i], "tritri.boolean: meshes[" + std::to_string(i) + "] V"));
    for (const Indices& f : F) Fe.push_back(as_eigen(f));
    out = arrangements::detail::boolean_eigen_exact(
        Ve, Fe, arrangements::operation_tree(boolean_op, static_cast<int>(V.size())), options, "tritri.boolean");
  }
  return exact_path_dict(std::move(out), threads, round_safe, round_max_move);
}

// tritri.csg: a .csg file (load_csg_file) evaluated by boolean(); the double path when its
// operands are doubles (V_exact with exact_output), else the exact path (V_exact always).
nb::dict csg(const std::string& path, const std::string& classifier, int threads, bool exact_output, bool round_safe,
             double round_max_move) {
  if (path.find('\0') != std::string::npos)
    throw std::invalid_argument("tritri.csg: the path contains a NUL character");
  const arrangements::ArrangeOptions options = arrange_options(classifier, threads, "tritri.csg");
  std::optional<arrangements::EigenArrangement> plain;
  std::optional<arrangements::ExactEigenArrangement> rational;
  std::vector<ExactVec3> exact;
  {
    nb::gil_scoped_release release;
    arrangements::CsgScene scene = arrangements::load_csg_file(path);
    if (const auto* soup = std::get_if<arrangements::TriangleSoup>(&scene.soup))
      plain = arrangements::detail::eigen_arrangement_of(arrangements::boolean(*soup, scene.tree, options),
                                                         exact_output ? &exact : nullptr);
    else
      rational = arrangements::detail::exact_eigen_arrangement_of(
          arrangements::boolean(std::get<arrangements::ExactTriangleSoup>(scene.soup), scene.tree, options));
  }
  if (plain)
    return double_path_dict(std::move(*plain), exact_output ? &exact : nullptr, threads, round_safe, round_max_move,
                            nullptr);
  return exact_path_dict(std::move(*rational), threads, round_safe, round_max_move);
}

}  // namespace

NB_MODULE(_tritri, m) {
  m.doc() = "Exact triangle-triangle intersection classification and mesh arrangements (see tritri/__init__.py).";

  nb::register_exception_translator([](const std::exception_ptr& p, void*) {
    try {
      std::rethrow_exception(p);
    } catch (const arrangements::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const arrangements::OpenOperandError& e) {  // an operand of boolean / csg that is not closed
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  nb::class_<tritri::Result>(m, "Result", "The exact classification of the intersection of two triangles A and B.")
      .def_prop_ro(
          "points",
          [](const tritri::Result& r) {
            nb::list l;
            for (const auto& p : r.points) l.append(nb::make_tuple(tritri::to_string(p.type), int(p.id0), int(p.id1)));
            return l;
          },
          "Every corner of A ∩ B as (type, id0, id1), type one of VA_ON_VB, VA_ON_EB, VB_ON_EA, VA_ON_TB, "
          "VB_ON_TA, EA_CROSS_EB, EA_CROSS_TB, EB_CROSS_TA; sorted by (type, id0, id1).")
      .def_prop_ro(
          "segments",
          [](const tritri::Result& r) {
            nb::list l;
            for (const auto& s : r.segments) l.append(nb::make_tuple(int(s.p0), int(s.p1)));
            return l;
          },
          "Segments of the intersection as pairs of indices into points.")
      .def_ro("coplanar", &tritri::Result::coplanar, "The triangles lie in one plane (and were classified).")
      .def_ro("degenerate", &tritri::Result::degenerate,
              "A triangle is degenerate and the pair was not classified (points is empty).")
      .def_prop_ro("intersects", &tritri::Result::intersects, "At least one point.")
      .def(
          "__eq__", [](const tritri::Result& a, const tritri::Result& b) { return a == b; }, nb::is_operator())
      .def("__repr__", [](const tritri::Result& r) {
        std::ostringstream s;
        s << r;
        return s.str();
      });

  m.attr("MAX_THREADS") = arrangements::kMaxThreads;
  m.def("classify", &classify, nb::arg("a"), nb::arg("b"));
  m.def("self_intersections", &self_intersections, nb::arg("V"), nb::arg("F"));
  m.def("intersections", &intersections, nb::arg("V1"), nb::arg("F1"), nb::arg("V2"), nb::arg("F2"));
  m.def("classify_exact", &classify_exact, nb::arg("a"), nb::arg("b"));
  m.def("self_intersections_exact", &self_intersections_exact, nb::arg("V"), nb::arg("F"));
  m.def("intersections_exact", &intersections_exact, nb::arg("V1"), nb::arg("F1"), nb::arg("V2"), nb::arg("F2"));
  m.def("load_mesh", &load_mesh, nb::arg("path"));
  // The stats keys with their meanings, as text (for the docstring of tritri.arrange).
  m.def("_stats_key_list", &arrangements::stats_key_list, nb::arg("indent"), nb::arg("column"), nb::arg("width"));
  m.def("arrange", &arrange, nb::arg("V"), nb::arg("F"), nb::arg("labels").none(), nb::arg("classifier"),
        nb::arg("threads"), nb::arg("exact_output") = false, nb::arg("round_safe") = false,
        nb::arg("round_max_move") = arrangements::RoundSafeOptions{}.max_move_relative);
  m.def("boolean", &boolean, nb::arg("V"), nb::arg("F"), nb::arg("op"), nb::arg("classifier"), nb::arg("threads"),
        nb::arg("exact_output") = false, nb::arg("round_safe") = false,
        nb::arg("round_max_move") = arrangements::RoundSafeOptions{}.max_move_relative);
  m.def("boolean_exact", &boolean_exact, nb::arg("V"), nb::arg("F"), nb::arg("op"), nb::arg("classifier"),
        nb::arg("threads"), nb::arg("round_safe") = false,
        nb::arg("round_max_move") = arrangements::RoundSafeOptions{}.max_move_relative);
  m.def("csg", &csg, nb::arg("path"), nb::arg("classifier"), nb::arg("threads"), nb::arg("exact_output") = false,
        nb::arg("round_safe") = false, nb::arg("round_max_move") = arrangements::RoundSafeOptions{}.max_move_relative);
  m.def("arrange_exact", &arrange_exact, nb::arg("V"), nb::arg("F"), nb::arg("labels").none(), nb::arg("classifier"),
        nb::arg("threads"), nb::arg("round_safe") = false,
        nb::arg("round_max_move") = arrangements::RoundSafeOptions{}.max_move_relative);
}
