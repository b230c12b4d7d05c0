// tritri._tritri: the Python extension behind the `tritri` package (python/tritri/__init__.py,
// which normalises the arguments to C-contiguous float64 / int64 numpy arrays, or exact
// coordinates to hexadecimal "n/d" strings, and documents the functions). Every C++
// computation runs with the GIL released; every refused input raises ValueError
// (std::invalid_argument, std::domain_error and arrangements::InputError are translated), so
// bad input never takes the interpreter down; worker threads the system refuses raise
// tritri.ThreadError (a RuntimeError; CallWorkers in module_common.h). Exact coordinates
// come back as fractions.Fraction objects (flat lists, 3 per vertex; the package shapes them).
// This file: classify, intersections, arrange, load_mesh and the module itself; boolean and
// csg are in boolean_bindings.cpp, the shared conversions and result dicts in module_common.cpp.
#include "module_common.h"

#include "support/worker_threads.h"

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <CGAL/Gmpq.h>

#include <Eigen/Core>

#include <arrangements/arrange_eigen.h>
#include <arrangements/boolean.h>  // OpenOperandError, for the exception translator
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
#include <variant>
#include <vector>

namespace nb = nanobind;

namespace tritri_python {

namespace {

using Labels = nb::ndarray<const std::int64_t, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using LabelVector = Eigen::Map<const Eigen::Matrix<std::int64_t, Eigen::Dynamic, 1>>;

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

// --- exact coordinates: hexadecimal "n/d" strings in, fractions.Fraction out ------------

// The exact entries of classify, self_intersections and intersections (RationalKernel):
// coordinates as hexadecimal "n/d" strings (rational_rows), checked by the Python layer
// (shapes, |x| <= DBL_MAX).
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

// --- arrange ----------------------------------------------------------------------------

std::optional<LabelVector> label_vector(const std::optional<Labels>& labels) {
  std::optional<LabelVector> Le;
  if (labels) Le.emplace(labels->data(), static_cast<Eigen::Index>(labels->shape(0)));
  return Le;
}

// The double path; exact_output adds V_exact (the exact output vertices as Fractions).
nb::dict arrange(const Coords& V, const Indices& F, std::optional<Labels> labels, const std::string& classifier,
                 int threads, bool exact_output, bool round_safe, double round_max_move) {
  const arrangements::ArrangeOptions options = arrange_options(classifier, threads);
  arrangements::EigenArrangement out;
  std::vector<ExactVec3> exact;
  arrangements::TriangleSoup input;  // for round_safe's last resort
  {
    nb::gil_scoped_release release;
    const CallWorkers workers(threads);
    // Checked once, by the Eigen entry point (int64 indices and labels are range-checked
    // there before they are narrowed).
    const std::optional<LabelVector> Le = label_vector(labels);
    out = arrangements::detail::arrange_eigen(as_eigen(V), as_eigen(F), options, Le ? &*Le : nullptr, "tritri.arrange",
                                              exact_output ? &exact : nullptr, round_safe ? &input : nullptr);
  }
  return double_path_dict(std::move(out), exact_output ? &exact : nullptr, threads, round_safe, round_max_move,
                          round_safe ? &input : nullptr);
}

// The exact path: V as 3 #V hexadecimal "n/d" strings, row after row. The dict of arrange
// plus V_exact; V is V_exact rounded to the nearest double (ties to even).
nb::dict arrange_exact(const std::vector<std::string>& V, const Indices& F, std::optional<Labels> labels,
                       const std::string& classifier, int threads, bool round_safe, double round_max_move) {
  const arrangements::ArrangeOptions options = arrange_options(classifier, threads);
  arrangements::ExactEigenArrangement out;
  {
    nb::gil_scoped_release release;
    const CallWorkers workers(threads);
    const RationalRows Ve = rational_rows(V, "tritri.arrange: V");
    const std::optional<LabelVector> Le = label_vector(labels);
    out = arrangements::detail::arrange_eigen_exact(Ve, as_eigen(F), options, Le ? &*Le : nullptr, "tritri.arrange");
  }
  return exact_path_dict(std::move(out), threads, round_safe, round_max_move);
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

}  // namespace

}  // namespace tritri_python

NB_MODULE(_tritri, m) {
  using namespace tritri_python;
  m.doc() = "Exact triangle-triangle intersection classification and mesh arrangements (see tritri/__init__.py).";

  // A refused worker thread (CallWorkers, module_common.h): tritri.ThreadError, a RuntimeError.
  nb::exception<arrangements::detail::WorkerThreadsError>(m, "ThreadError", PyExc_RuntimeError);
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
  bind_booleans(m);
  m.def("arrange_exact", &arrange_exact, nb::arg("V"), nb::arg("F"), nb::arg("labels").none(), nb::arg("classifier"),
        nb::arg("threads"), nb::arg("round_safe") = false,
        nb::arg("round_max_move") = arrangements::RoundSafeOptions{}.max_move_relative);
}
