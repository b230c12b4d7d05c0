// What the translation units of tritri._tritri share (tritri_module.cpp: classify,
// intersections, arrange, load_mesh; boolean_bindings.cpp: boolean, csg): the numpy argument
// types, their Eigen views, the parsing of exact "n/d" coordinates and the result dicts of
// the double and exact paths, defined once in module_common.cpp, so that both entry points
// build the same dicts.
#pragma once

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/optional.h>  // the same type casters in every file of the module
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <CGAL/Gmpq.h>  // before Eigen is used with it

#include <Eigen/Core>

#include <arrangements/arrange_eigen.h>

#include <tbb/global_control.h>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace tritri_python {

namespace nb = nanobind;

using Coords = nb::ndarray<const double, nb::ndim<2>, nb::c_contig, nb::device::cpu>;
using Indices = nb::ndarray<const std::int64_t, nb::ndim<2>, nb::c_contig, nb::device::cpu>;
using RowMajorXd = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using RowMajorXl = Eigen::Matrix<std::int64_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using RationalRows = Eigen::Matrix<CGAL::Gmpq, Eigen::Dynamic, 3>;
using arrangements::ExactVec3;

Eigen::Map<const RowMajorXd> as_eigen(const Coords& a);
Eigen::Map<const RowMajorXl> as_eigen(const Indices& a);

// A numpy array that owns `data`.
template <class T>
nb::object numpy_array(std::vector<T>&& data, std::initializer_list<std::size_t> shape) {
  auto* owned = new std::vector<T>(std::move(data));
  nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<std::vector<T>*>(p); });
  return nb::cast(nb::ndarray<nb::numpy, T>(owned->data(), shape, owner));
}

// 3n hexadecimal "n/d" strings, row after row, as an n x 3 matrix; `where` names the argument.
RationalRows rational_rows(const std::vector<std::string>& values, const std::string& where);

// Every coordinate of `rows` as a fractions.Fraction, row after row (3 per row).
nb::list fractions_of(const std::vector<ExactVec3>& rows);

// The worker threads of one call, started before the pipeline runs (construct it with the
// GIL released, first in the call's computation, and keep it for the call): a
// tbb::global_control of the call's thread count (threads, 0: every core) under which
// arrangements::detail::start_worker_threads starts oneTBB's workers where a refusal can be
// reported, as the arrange tool does (support/worker_threads.h). When the system refuses the
// threads (ulimit -v or -u, a container's pids limit) it throws WorkerThreadsError, which the
// module raises as tritri.ThreadError (a RuntimeError), instead of oneTBB ending the
// interpreter with SIGABRT from a worker.
class CallWorkers {
 public:
  explicit CallWorkers(int threads);

 private:
  tbb::global_control limit_;
};

// The options of the arrangement: classifier "tritri" or "native", threads checked;
// `where` names the Python function in the messages.
arrangements::ArrangeOptions arrange_options(const std::string& classifier, int threads,
                                             const std::string& where = "tritri.arrange");

// The dict of a double-path result `out` (arrange, boolean, csg): rounded by round_safe
// when round_safe (input: round_safe's last resort, may be null; keep_closed: a Boolean's,
// RoundSafeOptions::keep_closed), else V, V_is_exact and, when exact is given (the exact
// output vertices), V_exact.
nb::dict double_path_dict(arrangements::EigenArrangement&& out, std::vector<ExactVec3>* exact, int threads,
                          bool round_safe, double round_max_move, const arrangements::TriangleSoup* input,
                          bool keep_closed = false);

// The dict of an exact-path result `out` (arrange, boolean, csg): rounded by round_safe
// when round_safe, else V (V_exact rounded to the nearest doubles), V_is_exact, V_exact.
nb::dict exact_path_dict(arrangements::ExactEigenArrangement&& out, int threads, bool round_safe,
                         double round_max_move, bool keep_closed = false);

// Adds boolean, boolean_exact and csg to the module (boolean_bindings.cpp).
void bind_booleans(nb::module_& m);

}  // namespace tritri_python
