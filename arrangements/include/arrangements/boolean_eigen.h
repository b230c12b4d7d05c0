// arrangements/boolean_eigen.h
//
// boolean(V, F, op_or_tree, options): exact mesh Booleans and CSG trees (boolean.h) on
// Eigen matrices, as arrange_eigen.h does for the arrangement.
//
//   #include <arrangements/boolean_eigen.h>
//   std::vector<Eigen::MatrixXd> V{VA, VB};
//   std::vector<Eigen::MatrixXi> F{FA, FB};
//   arrangements::EigenArrangement out = arrangements::boolean(V, F, arrangements::BooleanOp::Difference, {});
//   // out.V, out.F: the boundary of A \ B, oriented outwards
//
// Inputs:
//   V        n operand meshes' vertex matrices, each #V_i by 3, finite (used exactly)
//   F        their triangle matrices, each #F_i by 3, indices into the rows of V[i]
//            (operand i has label i; V.size() == F.size(), n >= 1)
//   op       a BooleanOp applied to the operands 0 .. n-1 in order (operation_tree), or
//   tree     a CsgNode over the labels 0 .. n-1 (an operand absent from it is ignored)
//   options  ArrangeOptions (arrange.h), as for arrange
// Output: EigenArrangement (arrange_eigen.h), the fields as there, for the boundary of the
// tree's solid (boolean.h: triangles oriented outwards, unreferenced vertices dropped):
//   vertices, V, V_is_exact   the exact output vertices and their nearest doubles
//   F                         the output triangles, indices into V
//   source                    the row of the concatenation of the F[i] (operand 0's rows
//                             first, then operand 1's, ...) that each triangle lies in
//   label_set, label_sets     the operands (labels) covering each triangle
//   stats                     ArrangeStats of the run
// Exact input: V as matrices of CGAL::Gmpq (Eigen::Matrix<CGAL::Gmpq, Eigen::Dynamic, 3>)
// runs the exact path and returns ExactEigenArrangement (V exactly, as arrange's exact
// overload).
//
// Throws std::invalid_argument for input the pipeline cannot take (as arrange_eigen.h:
// V or F without 3 columns, NaN or infinite coordinates, an index out of range, more rows
// than int indices allow, bad thread counts), for no operand or V.size() != F.size(), and
// for a bad tree (boolean.h); OpenOperandError (boolean.h, a std::runtime_error) when an
// operand is not closed: its message names the operand, "operand 1 is not closed: ...".
// Deterministic for any number of threads. Cost: that of boolean.h, plus O(#V + #F) for
// the conversions.
#pragma once

#include <CGAL/Gmpq.h>
#include <Eigen/Core>
#include <tbb/parallel_for.h>

#include <array>
#include <climits>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "arrangements/arrange_eigen.h"
#include "arrangements/boolean.h"

namespace arrangements {

namespace detail {

using LongRows = Eigen::Matrix<long long, Eigen::Dynamic, Eigen::Dynamic>;

// The operands concatenated into one V, F and labels (operand i: label i), checked for
// count and total size. Scalar: double or CGAL::Gmpq.
template <class Scalar, class MV, class MF>
void concatenate_operands(const std::vector<MV>& V, const std::vector<MF>& F, const std::string& where,
                          Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& Vall, LongRows& Fall,
                          Eigen::Matrix<long long, Eigen::Dynamic, 1>& labels) {
  if (V.empty()) throw std::invalid_argument(where + ": no operand (V and F are empty)");
  if (V.size() != F.size())
    throw std::invalid_argument(where + ": V and F must hold as many matrices (" + std::to_string(V.size()) + " and " +
                                std::to_string(F.size()) + ")");
  if (V.size() > static_cast<std::size_t>(INT_MAX)) throw std::invalid_argument(where + ": too many operands");
  long long nv = 0, nf = 0;
  for (std::size_t i = 0; i < V.size(); ++i) {
    const std::string name = "[" + std::to_string(i) + "]";
    if (V[i].cols() != 3 && V[i].rows() > 0)
      throw std::invalid_argument(where + ": V" + name + " must have 3 columns, got " + std::to_string(V[i].cols()));
    if (F[i].cols() != 3 && F[i].rows() > 0)
      throw std::invalid_argument(where + ": F" + name + " must have 3 columns, got " + std::to_string(F[i].cols()));
    nv += V[i].rows();
    nf += F[i].rows();
    if (nv > INT_MAX || nf > INT_MAX)
      throw std::invalid_argument(where + ": the operands together have more than " + std::to_string(INT_MAX) +
                                  " vertices or triangles");
  }
  Vall.resize(nv, 3);
  Fall.resize(nf, 3);
  labels.resize(nf);
  Eigen::Index v0 = 0, f0 = 0;
  for (std::size_t i = 0; i < V.size(); ++i) {
    for (Eigen::Index r = 0; r < V[i].rows(); ++r)
      for (Eigen::Index c = 0; c < 3; ++c) Vall(v0 + r, c) = V[i](r, c);
    for (Eigen::Index r = 0; r < F[i].rows(); ++r) {
      for (Eigen::Index c = 0; c < 3; ++c) {
        const long long x = static_cast<long long>(F[i](r, c));
        // An index out of its operand's range must not land in another operand's rows.
        if (x < 0 || x >= V[i].rows())
          throw std::invalid_argument(where + ": F[" + std::to_string(i) + "](" + std::to_string(r) + ", " +
                                      std::to_string(c) + ") = " + std::to_string(x) + " is not a row of V[" +
                                      std::to_string(i) + "] (0 .. " + std::to_string(V[i].rows() - 1) + ")");
        Fall(f0 + r, c) = x + v0;
      }
      labels(f0 + r) = static_cast<long long>(i);
    }
    v0 += V[i].rows();
    f0 += F[i].rows();
  }
}

// boolean() below for any Eigen matrix types of doubles (the Python module passes row-major
// maps with int64 indices). exact (optional): receives the exact output vertices.
template <class MV, class MF>
EigenArrangement boolean_eigen(const std::vector<MV>& V, const std::vector<MF>& F, const CsgNode& tree,
                               const ArrangeOptions& options, const std::string& where,
                               std::vector<ExactVec3>* exact = nullptr) {
  Eigen::MatrixXd Vall;
  LongRows Fall;
  Eigen::Matrix<long long, Eigen::Dynamic, 1> labels;
  concatenate_operands<double>(V, F, where, Vall, Fall, labels);
  const TriangleSoup soup = eigen_soup(Vall, Fall, &labels, where);
  return eigen_arrangement_of(boolean_validated(soup, tree, options), exact);
}

// The exact overload for any Eigen matrix types of CGAL::Gmpq.
template <class MV, class MF>
ExactEigenArrangement boolean_eigen_exact(const std::vector<MV>& V, const std::vector<MF>& F, const CsgNode& tree,
                                          const ArrangeOptions& options, const std::string& where) {
  Eigen::Matrix<CGAL::Gmpq, Eigen::Dynamic, Eigen::Dynamic> Vall;
  LongRows Fall;
  Eigen::Matrix<long long, Eigen::Dynamic, 1> labels;
  concatenate_operands<CGAL::Gmpq>(V, F, where, Vall, Fall, labels);
  const ExactTriangleSoup soup = exact_eigen_soup(Vall, Fall, &labels, where);
  return exact_eigen_arrangement_of(boolean_validated(soup, tree, options));
}

}  // namespace detail

inline EigenArrangement boolean(const std::vector<Eigen::MatrixXd>& V, const std::vector<Eigen::MatrixXi>& F,
                                const CsgNode& tree, const ArrangeOptions& options) {
  return detail::boolean_eigen(V, F, tree, options, "arrangements::boolean");
}

inline EigenArrangement boolean(const std::vector<Eigen::MatrixXd>& V, const std::vector<Eigen::MatrixXi>& F,
                                BooleanOp op, const ArrangeOptions& options) {
  return detail::boolean_eigen(V, F, operation_tree(op, static_cast<int>(V.size())), options,
                               "arrangements::boolean");
}

using ExactOperandMatrix = Eigen::Matrix<CGAL::Gmpq, Eigen::Dynamic, 3>;

inline ExactEigenArrangement boolean(const std::vector<ExactOperandMatrix>& V, const std::vector<Eigen::MatrixXi>& F,
                                     const CsgNode& tree, const ArrangeOptions& options) {
  return detail::boolean_eigen_exact(V, F, tree, options, "arrangements::boolean");
}

inline ExactEigenArrangement boolean(const std::vector<ExactOperandMatrix>& V, const std::vector<Eigen::MatrixXi>& F,
                                     BooleanOp op, const ArrangeOptions& options) {
  return detail::boolean_eigen_exact(V, F, operation_tree(op, static_cast<int>(V.size())), options,
                                     "arrangements::boolean");
}

}  // namespace arrangements
