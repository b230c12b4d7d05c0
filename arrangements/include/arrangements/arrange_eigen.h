// arrangements/arrange_eigen.h
//
// arrange(V, F, options, labels): the mesh-arrangement pipeline (arrange.h) on Eigen
// matrices: the input triangles are cut along all their intersections into a mesh whose
// triangles meet only at shared vertices and edges.
//
//   #include <arrangements/arrange_eigen.h>
//   arrangements::EigenArrangement out = arrangements::arrange(V, F, {});
//   // out.V, out.F: the arrangement; out.source(f): the row of F that face f lies in
//
// Inputs:
//   V        #V by 3 matrix of vertex coordinates, finite (they are used exactly)
//   F        #F by 3 matrix of triangle corners, indices into the rows of V (#F may be 0)
//   options  ArrangeOptions (arrange.h): classifier (Tritri or Native), threads (<= 0:
//            all cores), scale, count_predicates
//   labels   optional #F vector of labels >= 0, one per row of F (nullptr: all 0), e.g.
//            the index of the mesh each triangle came from
// Output: EigenArrangement, the OutputMesh (output_mesh.h) with its fields under the same
// names, the index lists as Eigen matrices:
//   vertices         #V_out exact output vertices (explicit input points, LPIs, TPIs);
//                    tritri::to_exact gives their rational coordinates
//   V                #V_out by 3: `vertices` rounded to the nearest double
//                    (tritri::to_double); exact for input vertices, rounded for new
//                    intersection points (see V_is_exact)
//   V_is_exact       #V_out: V.row(v) equals vertices[v] exactly
//   F                #F_out by 3: the triangles, indices into V / vertices, each oriented
//                    like the input triangle it lies in
//   source           #F_out: the row of the input F that each output face lies in (for a
//                    region where coplanar input triangles overlap, the first of them in
//                    the pipeline's order)
//   label_set        #F_out: index into label_sets of each face's label set
//   label_sets       distinct sorted label sets: the union of the labels of every input
//                    triangle that covers a face
//   stats            ArrangeStats of the run (counts, stage times)
//
// Throws std::invalid_argument for input the pipeline cannot take: V or F without 3
// columns, a NaN or infinite coordinate, an index out of range, labels of the wrong size
// or negative, more rows than int indices allow, more threads than kMaxThreads. Input with
// no triangle left after preprocessing is valid: its arrangement is empty.
//
// Exactness: the arrangement is exact (implicit points, exact predicates); only V is
// rounded, so V may show self-intersections the exact mesh does not have (V_is_exact
// tells which vertices moved). Deterministic for any number of threads.
// Complexity: that of arrange.h (candidate pairs, classification, triangulation), plus
// O(#V + #F) for the conversions; the rounding of new points is parallel (oneTBB).
//
// Exact input and output: arrange(V, F, options, labels) with V an Eigen matrix of
// CGAL::Gmpq (any #V by 3 expression, e.g. Eigen::Matrix<CGAL::Gmpq, Eigen::Dynamic, 3>;
// CGAL/Gmpq.h gives Eigen its NumTraits) runs the exact path (arrange(ExactTriangleSoup),
// every point a rational) and returns ExactEigenArrangement:
//   V                #V_out by 3 CGAL::Gmpq: the output vertices, exactly (input vertices
//                    as given, new points as rationals; first-use order like `vertices`)
//   F, source, label_set, label_sets, stats   as in EigenArrangement
// Input checks as above, plus: a coordinate beyond the largest finite double in absolute
// value is refused (std::invalid_argument), the rule of load_mesh_files for rational file
// coordinates (the pipeline needs finite bounding boxes). Use it for rational input (e.g.
// an exact arrangement arranged again); double input is faster on the double overload, and
// tritri::to_exact of its `vertices` gives the same rationals (the same point set, possibly
// numbered and triangulated differently).
#pragma once

#include <CGAL/Gmpq.h>  // before Eigen is used with it: Eigen::NumTraits<CGAL::Gmpq>
#include <Eigen/Core>
#include <tbb/parallel_for.h>

#include <tritri/implicit_point.h>

#include <array>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <tritri/detail/mesh_pairs.h>

#include "arrangements/arrange.h"
#include "arrangements/triangle_soup.h"

namespace arrangements {

struct EigenArrangement {
  std::vector<tritri::ImplicitPoint> vertices;
  Eigen::MatrixXd V;
  Eigen::Matrix<bool, Eigen::Dynamic, 1> V_is_exact;
  Eigen::MatrixXi F;
  Eigen::VectorXi source;
  Eigen::VectorXi label_set;
  std::vector<LabelSet> label_sets;
  ArrangeStats stats;
};

struct ExactEigenArrangement {
  Eigen::Matrix<CGAL::Gmpq, Eigen::Dynamic, 3> V;
  Eigen::MatrixXi F;
  Eigen::VectorXi source;
  Eigen::VectorXi label_set;
  std::vector<LabelSet> label_sets;
  ArrangeStats stats;
};

namespace detail {

// label_set, label_sets and source of `soup` (its triangles already set) from labels
// (nullptr: all 0), checked; source = row of F. `where` names the function in messages.
template <class Soup, class DL>
void set_eigen_labels(Soup& soup, const Eigen::MatrixBase<DL>* labels, const std::string& where) {
  static_assert(std::is_integral_v<typename DL::Scalar>, "labels must hold integers");
  const std::size_t nf = soup.triangles.size();
  if (labels && static_cast<std::size_t>(labels->size()) != nf)
    throw std::invalid_argument(where + ": labels must have one entry per row of F (" + std::to_string(nf) + "), got " +
                                std::to_string(labels->size()));
  soup.label_set.resize(nf);
  soup.source.resize(nf);
  std::map<long long, int> set_of_label;  // label -> index of {label} in soup.label_sets
  for (std::size_t r = 0; r < nf; ++r) {
    const long long label = labels ? static_cast<long long>((*labels)(static_cast<Eigen::Index>(r))) : 0;
    if (label < 0 || label > INT_MAX)
      throw std::invalid_argument(where + ": labels(" + std::to_string(r) + ") = " + std::to_string(label) +
                                  " is not in [0, " + std::to_string(INT_MAX) + "]");
    auto [it, added] = set_of_label.try_emplace(label, static_cast<int>(soup.label_sets.size()));
    if (added) soup.label_sets.push_back({static_cast<std::uint32_t>(label)});
    soup.label_set[r] = it->second;
    soup.source[r] = static_cast<std::int64_t>(r);
  }
}

// The input as a TriangleSoup: the one place where the Eigen and Python entry points check
// it (coordinates and indices by tritri's checks, shared with the batch API; labels
// here); source = row of F. `where` names the function in messages.
template <class DV, class DF, class DL>
TriangleSoup eigen_soup(const Eigen::MatrixBase<DV>& V, const Eigen::MatrixBase<DF>& F,
                        const Eigen::MatrixBase<DL>* labels, const std::string& where) {
  TriangleSoup soup;
  soup.vertices = tritri::detail::checked_vertices(V, where + ": V");
  soup.triangles = tritri::detail::checked_triangles(F, soup.vertices.size(), where + ": F");
  set_eigen_labels(soup, labels, where);
  return soup;
}

// The same for rational V (the exact entry points): 3 columns, at most INT_MAX rows, every
// |coordinate| <= DBL_MAX (the rule of load_mesh_files).
template <class DV, class DF, class DL>
ExactTriangleSoup exact_eigen_soup(const Eigen::MatrixBase<DV>& V, const Eigen::MatrixBase<DF>& F,
                                   const Eigen::MatrixBase<DL>* labels, const std::string& where) {
  static_assert(std::is_same_v<typename DV::Scalar, CGAL::Gmpq>, "V must hold CGAL::Gmpq coordinates");
  ExactTriangleSoup soup;
  soup.vertices = tritri::detail::checked_rational_vertices(V, where + ": V");
  soup.triangles = tritri::detail::checked_triangles(F, soup.vertices.size(), where + ": F");
  set_eigen_labels(soup, labels, where);
  return soup;
}

// F, source, label_set, label_sets and stats of `out` from an arrangement's mesh and stats.
template <class Out, class Mesh>
void set_eigen_faces(Out& out, Mesh& mesh, ArrangeStats& stats) {
  const auto nf = static_cast<Eigen::Index>(mesh.triangles.size());
  out.F.resize(nf, 3);
  out.source.resize(nf);
  out.label_set.resize(nf);
  for (Eigen::Index f = 0; f < nf; ++f) {
    for (int c = 0; c < 3; ++c) out.F(f, c) = mesh.triangles[f][c];
    out.source(f) = static_cast<int>(mesh.source[f]);
    out.label_set(f) = mesh.label_set[f];
  }
  out.label_sets = std::move(mesh.label_sets);
  out.stats = std::move(stats);
}

// The EigenArrangement of a double-path result (arrange_eigen, and the Booleans of boolean_eigen.h). exact
// (optional): receives tritri::to_exact of every output vertex.
inline EigenArrangement eigen_arrangement_of(ArrangeResult&& result, std::vector<ExactVec3>* exact = nullptr) {
  OutputMesh& mesh = result.mesh;
  EigenArrangement out;
  const auto nv = static_cast<Eigen::Index>(mesh.vertices.size());
  out.V.resize(nv, 3);
  out.V_is_exact.resize(nv);
  if (exact) {
    exact->clear();
    exact->resize(mesh.vertices.size());
  }
  tbb::parallel_for(Eigen::Index{0}, nv, [&](Eigen::Index v) {
    const tritri::ImplicitPoint& p = mesh.vertices[static_cast<std::size_t>(v)];
    const std::array<double, 3> x = tritri::to_double(p);
    bool is_exact = true;
    if (!p.is_explicit() || exact) {
      const std::array<CGAL::Gmpq, 3> q = tritri::to_exact(p);
      for (int c = 0; c < 3; ++c) is_exact = is_exact && std::isfinite(x[c]) && CGAL::Gmpq(x[c]) == q[c];
      if (exact) (*exact)[static_cast<std::size_t>(v)] = q;
    }
    for (int c = 0; c < 3; ++c) out.V(v, c) = x[c];
    out.V_is_exact(v) = is_exact;
  });
  set_eigen_faces(out, mesh, result.stats);
  out.vertices = std::move(mesh.vertices);
  return out;
}

// The ExactEigenArrangement of an exact-path result.
inline ExactEigenArrangement exact_eigen_arrangement_of(ExactArrangeResult&& result) {
  ExactOutputMesh& mesh = result.mesh;
  ExactEigenArrangement out;
  out.V.resize(static_cast<Eigen::Index>(mesh.vertices.size()), 3);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    for (int c = 0; c < 3; ++c) out.V(static_cast<Eigen::Index>(v), c) = std::move(mesh.vertices[v][c]);
  set_eigen_faces(out, mesh, result.stats);
  return out;
}

// arrange() below for any Eigen matrix types (the Python module passes int64 indices and
// labels: they are range-checked before they are narrowed). exact (optional): receives
// tritri::to_exact of every output vertex (computed once, also for V_is_exact). input
// (optional): receives the soup arranged (round_safe's RoundSafeOptions::input), built once.
template <class DV, class DF, class DL>
EigenArrangement arrange_eigen(const Eigen::MatrixBase<DV>& V, const Eigen::MatrixBase<DF>& F,
                               const ArrangeOptions& options, const Eigen::MatrixBase<DL>* labels,
                               const std::string& where, std::vector<ExactVec3>* exact = nullptr,
                               TriangleSoup* input = nullptr) {
  TriangleSoup soup = eigen_soup(V, F, labels, where);
  ArrangeResult result = arrange_validated(soup, options);
  if (input) *input = std::move(soup);
  return eigen_arrangement_of(std::move(result), exact);
}

// The exact overload of arrange() below for any Eigen matrix types (as arrange_eigen).
template <class DV, class DF, class DL>
ExactEigenArrangement arrange_eigen_exact(const Eigen::MatrixBase<DV>& V, const Eigen::MatrixBase<DF>& F,
                                          const ArrangeOptions& options, const Eigen::MatrixBase<DL>* labels,
                                          const std::string& where) {
  return exact_eigen_arrangement_of(arrange_validated(exact_eigen_soup(V, F, labels, where), options));
}

}  // namespace detail

inline EigenArrangement arrange(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ArrangeOptions& options,
                                const Eigen::VectorXi* labels = nullptr) {
  return detail::arrange_eigen(V, F, options, labels, "arrangements::arrange");
}

// Exact input, exact output (see the top of this file): any matrix expression of
// CGAL::Gmpq for V (constrained, so that double expressions still pick the overload above).
template <class DV, class = std::enable_if_t<std::is_same_v<typename DV::Scalar, CGAL::Gmpq>>>
ExactEigenArrangement arrange(const Eigen::MatrixBase<DV>& V, const Eigen::MatrixXi& F, const ArrangeOptions& options,
                              const Eigen::VectorXi* labels = nullptr) {
  return detail::arrange_eigen_exact(V, F, options, labels, "arrangements::arrange");
}

}  // namespace arrangements
