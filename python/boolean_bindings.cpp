// The Boolean entries of tritri._tritri: tritri.boolean (double and exact paths) and
// tritri.csg, over boolean_eigen.h and load_csg.h. Apart from tritri_module.cpp so that each
// file holds one idea; the arguments and result dicts are those of arrange (module_common.h).
#include "module_common.h"

#include <arrangements/boolean.h>
#include <arrangements/boolean_eigen.h>
#include <arrangements/load_csg.h>
#include <arrangements/round_mesh.h>

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace tritri_python {

namespace {

arrangements::BooleanOp boolean_op_named(const std::string& name) {
  if (name == "union") return arrangements::BooleanOp::Union;
  if (name == "intersection") return arrangements::BooleanOp::Intersection;
  if (name == "difference") return arrangements::BooleanOp::Difference;
  if (name == "xor") return arrangements::BooleanOp::Xor;
  throw std::invalid_argument("tritri.boolean: unknown op '" + name +
                              "' (use 'union', 'intersection', 'difference' or 'xor')");
}

// The double path of tritri.boolean: operand i is (V[i], F[i]), label i (boolean_eigen.h).
// OpenOperandError becomes ValueError (the translator in tritri_module.cpp).
nb::dict boolean(const std::vector<Coords>& V, const std::vector<Indices>& F, const std::string& op,
                 const std::string& classifier, int threads, bool exact_output, bool round_safe,
                 double round_max_move) {
  const arrangements::ArrangeOptions options = arrange_options(classifier, threads, "tritri.boolean");
  const arrangements::BooleanOp boolean_op = boolean_op_named(op);
  arrangements::EigenArrangement out;
  std::vector<ExactVec3> exact;
  {
    nb::gil_scoped_release release;
    const CallWorkers workers(threads);
    std::vector<Eigen::Map<const RowMajorXd>> Ve;
    std::vector<Eigen::Map<const RowMajorXl>> Fe;
    for (const Coords& v : V) Ve.push_back(as_eigen(v));
    for (const Indices& f : F) Fe.push_back(as_eigen(f));
    const arrangements::CsgNode tree = arrangements::operation_tree(boolean_op, static_cast<int>(V.size()));
    out = arrangements::detail::boolean_eigen(Ve, Fe, tree, options, "tritri.boolean", exact_output ? &exact : nullptr);
  }
  return double_path_dict(std::move(out), exact_output ? &exact : nullptr, threads, round_safe, round_max_move,
                          nullptr, true);
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
    const CallWorkers workers(threads);
    std::vector<RationalRows> Ve;
    std::vector<Eigen::Map<const RowMajorXl>> Fe;
    for (std::size_t i = 0; i < V.size(); ++i)
      Ve.push_back(rational_rows(V[i], "tritri.boolean: meshes[" + std::to_string(i) + "] V"));
    for (const Indices& f : F) Fe.push_back(as_eigen(f));
    out = arrangements::detail::boolean_eigen_exact(
        Ve, Fe, arrangements::operation_tree(boolean_op, static_cast<int>(V.size())), options, "tritri.boolean");
  }
  return exact_path_dict(std::move(out), threads, round_safe, round_max_move, true);
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
    const CallWorkers workers(threads);  // after the file, as the arrange tool does
    if (const auto* soup = std::get_if<arrangements::TriangleSoup>(&scene.soup))
      plain = arrangements::detail::eigen_arrangement_of(arrangements::boolean(*soup, scene.tree, options),
                                                         exact_output ? &exact : nullptr);
    else
      rational = arrangements::detail::exact_eigen_arrangement_of(
          arrangements::boolean(std::get<arrangements::ExactTriangleSoup>(scene.soup), scene.tree, options));
  }
  if (plain)
    return double_path_dict(std::move(*plain), exact_output ? &exact : nullptr, threads, round_safe, round_max_move,
                            nullptr, true);
  return exact_path_dict(std::move(*rational), threads, round_safe, round_max_move, true);
}

}  // namespace

void bind_booleans(nb::module_& m) {
  m.def("boolean", &boolean, nb::arg("V"), nb::arg("F"), nb::arg("op"), nb::arg("classifier"), nb::arg("threads"),
        nb::arg("exact_output") = false, nb::arg("round_safe") = false,
        nb::arg("round_max_move") = arrangements::RoundSafeOptions{}.max_move_relative);
  m.def("boolean_exact", &boolean_exact, nb::arg("V"), nb::arg("F"), nb::arg("op"), nb::arg("classifier"),
        nb::arg("threads"), nb::arg("round_safe") = false,
        nb::arg("round_max_move") = arrangements::RoundSafeOptions{}.max_move_relative);
  m.def("csg", &csg, nb::arg("path"), nb::arg("classifier"), nb::arg("threads"), nb::arg("exact_output") = false,
        nb::arg("round_safe") = false, nb::arg("round_max_move") = arrangements::RoundSafeOptions{}.max_move_relative);
}

}  // namespace tritri_python
