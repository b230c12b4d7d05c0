// arrange: the mesh-arrangement pipeline from the command line (classification stage).
// See --help.
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <exception>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "arrangements/arrange.h"
#include "arrangements/arrange_stats.h"
#include "arrangements/boolean.h"
#include "arrangements/check_arrangement.h"
#include "arrangements/input_error.h"
#include "arrangements/load_csg.h"
#include "arrangements/memory_budget.h"
#include "io/mesh_format.h"
#include "io/standard_output.h"
#include "support/command_line.h"
#include "support/kept_until_exit.h"
#include "support/process_usage.h"
#include "support/worker_threads.h"
#include "arrangements/load_triangle_soup.h"
#include "arrangements/round_mesh.h"
#include "arrangements/thread_count.h"
#include "arrangements/write_mesh.h"
#include "memory_budget.h"

namespace {

// The help text: kUsage, the JSON keys (generated from arrange_stats.h), kUsageEnd.
const char* kUsage = R"(usage: arrange INPUT... [-o OUTPUT] [options]

Computes the mesh arrangement of one or more triangle soups exactly (after Cherchi et al.
2020): every triangle is split along its intersections with the others, so that the output
triangles meet only at shared vertices and shared edges. Each INPUT (.obj .off .stl .ply,
ASCII or binary) is labelled by its position: the first file has label 0, the second 1, ...
OBJ and OFF coordinates may be exact rationals N/D (what --exact writes): input with any
coordinate that is not a double is arranged on the exact path (every point rational), so
an exact arrangement can be arranged again, with more meshes, as often as wanted.

Stages: load, exact preprocessing (merge duplicate vertices, remove degenerate and
duplicate triangles), candidate pairs (bounding boxes), classification of every candidate
pair (implicit points, never rounded), exact triangulation of every intersected triangle
(new TPIs where constraints cross; each region shared by coplanar triangles once).

options:
  -o, --output FILE       write the arrangement (.obj .off .ply by extension), atomically.
                          Provenance: for every output triangle the input triangle it lies
                          in (index in the input files' concatenated triangle lists, an
                          n-gon as n - 2 consecutive triangles) and its label set: PLY face properties, or the
                          side file FILE.provenance.csv for OBJ/OFF
  --exact                 write exact rational coordinates (OBJ/OFF; see
                          docs/FILE_FORMATS.md) instead of coordinates rounded to doubles
  --round MODE            how the output is rounded to doubles (not with --exact):
                          nearest (the default): every vertex to the nearest double; the
                          result may self-intersect where rounding moved a vertex through
                          a nearby triangle;
                          safe: rounded, re-arranged and rounded again until the rounded
                          mesh is itself an arrangement (its triangles meet only in shared
                          vertices and edges, decided exactly); if that does not
                          settle, vertices kept at their nearest doubles and triangles
                          rerouted through vertices within an ulp (in cycles of
                          re-arranging while few conflicts are left), then input
                          vertices a few ulps apart merged and the input arranged
                          again, nearly coplanar faces snapped onto one plane, then
                          corners within a few ulps of a face they touch too, then
                          a grid of 2^8 ulps, then vertices of the conflicts nudged by
                          ulps (in cycles); no vertex
                          moves by more than a 64th of the model's diagonal (see
                          --round-max-move); provenance kept; exit status 4 if nothing
                          settles within 384 passes. Stats round_*
  --round-max-move F      with --round safe: the largest move accepted, as a fraction F
                          of the diagonal (a finite number above 0; default 0.015625, a
                          64th). A model only a few hundred ulps wide (tiny and far from
                          the origin) settles only with moves of a fifth of its size or
                          more: F = 1 accepts them
  --round-without STEPS   with --round safe, for studies of the ladder: leave out these
                          steps (comma-separated names, listed at the end); a mesh
                          that only a left-out step settles is refused (exit status 4)
  --check                 verify the arrangement exactly: every pair of triangles with
                          overlapping boxes meets only in shared vertices and edges
                          (tritri on the implicit points; with --round safe, on the rounded
                          mesh that is written); exit status 3 if not
  --boolean OP            the Boolean of the inputs instead of their arrangement, exactly:
                          union, intersection, difference (the first input minus the
                          others) or xor (inside an odd number); each input a closed,
                          consistently oriented solid (self-intersecting allowed; inside
                          where its winding number is not 0); the output is the closed
                          boundary of the result, normals out, with the same provenance
                          and output options. An input that is not closed: exit 1,
                          naming it, its unbalanced edges and the first one
  --csg FILE              the Boolean of a CSG tree instead (OpenSCAD CSG subset: union,
                          difference, intersection, group, multmatrix applied exactly,
                          import of mesh files relative to FILE; docs/FILE_FORMATS.md);
                          no INPUT then
  --stats                 print one JSON object with counts and stage times on stdout
  --classifier NAME       pair classifier: tritri (tritri::classify through the adapter;
                          default) or native (the 2020 case analysis)
  --threads N             worker threads: 0 (the default: all cores) to )" ARRANGEMENTS_MAX_THREADS_STR R"(;
                          larger values are refused (oneTBB cannot run them safely)
  --scale                 scale coordinates by a power of two into a safe range (exact)
  --max-memory MB         end the run (exit 1, "needs more than MB MB") when its heap
                          (C++ allocations and GMP numbers) would pass MB megabytes
  --help                  this text
An option that takes a value may be given once; counts are plain decimal digits.

)";

const char* kUsageEnd = R"(
exit status: 0 success, 1 bad input (unreadable, unknown format, malformed, NaN/Inf,
out-of-range indices, vertices without faces), failed output (a file, or standard
output), worker threads the system refuses ("cannot start N worker threads": ulimit
-u or -v; --threads sets fewer), or memory (--max-memory, or the system's), 2 bad command line (unknown option, missing, empty or
out-of-range value, option given twice), 3 --check found a violation, 4 --round safe did
not converge (or, for a Boolean, its rounded output is not closed).
)";

std::string usage() {
  std::string steps;
  for (const auto name : arrangements::kRoundStepNames) steps += (steps.empty() ? "  " : ", ") + std::string(name);
  return kUsage + std::string("Steps of --round safe that --round-without takes, in the order they are tried:\n") +
         steps + "\n\nJSON keys (--stats), in this order:\n" + arrangements::stats_key_list(2, 26, 90) + kUsageEnd;
}

// The RoundSafeOptions::without bits of a comma-separated list of step names.
unsigned round_steps(const std::string& list, const arrangements::detail::CommandLine& args) {
  using arrangements::kRoundStepNames;
  unsigned bits = 0;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t end = std::min(list.find(',', begin), list.size());
    const std::string name = list.substr(begin, end - begin);
    const auto found = std::find(kRoundStepNames.begin(), kRoundStepNames.end(), name);
    if (found == kRoundStepNames.end()) {
      std::string known;
      for (const auto n : kRoundStepNames) known += (known.empty() ? "" : ", ") + std::string(n);
      args.usage_error("unknown rounding step '" + name + "' in --round-without (known: " + known + ")");
    }
    const unsigned bit = arrangements::round_step_bit(static_cast<arrangements::RoundStep>(found - kRoundStepNames.begin()));
    if (bits & bit) args.usage_error("rounding step '" + name + "' given twice in --round-without");
    bits |= bit;
    if (end == list.size()) return bits;
    begin = end + 1;
  }
}

int run(int argc, char** argv) {
  using namespace arrangements;
  std::vector<std::string> inputs;
  bool stats = false, scale = false, exact = false, check = false;
  std::optional<std::string> output;
  int threads = 0;
  std::string classifier = "tritri";
  std::string round = "nearest";
  std::optional<BooleanOp> boolean_op;
  std::optional<std::string> csg;
  double round_max_move = RoundSafeOptions{}.max_move_relative;
  unsigned round_without = 0;
  long long max_memory_mb = 0;  // 0: no budget
  constexpr long long kMaxMemoryMb = 1LL << 30;  // 1 PB: beyond any machine, no overflow in bytes
  detail::CommandLine args("arrange", argc, argv);
  while (args.next()) {
    const std::string& a = args.current();
    if (a == "--help" || a == "-h") {
      std::fputs(usage().c_str(), stdout);
      return 0;
    } else if (a == "--stats") {
      stats = true;
    } else if (a == "-o" || a == "--output") {
      output = args.value("--output");
      if (output->empty()) args.usage_error("--output needs a file name, got ''");
    } else if (a == "--check") {
      check = true;
    } else if (a == "--exact") {
      exact = true;
    } else if (a == "--round") {
      round = args.value("--round");
      if (round != "nearest" && round != "safe")
        args.usage_error("unknown rounding '" + round + "' (known: nearest, safe)");
    } else if (a == "--round-max-move") {
      round_max_move = args.positive_number("--round-max-move");
    } else if (a == "--round-without") {
      round_without = round_steps(args.value("--round-without"), args);
    } else if (a == "--boolean") {
      const std::string op = args.value("--boolean");
      if (op == "union") boolean_op = BooleanOp::Union;
      else if (op == "intersection") boolean_op = BooleanOp::Intersection;
      else if (op == "difference") boolean_op = BooleanOp::Difference;
      else if (op == "xor") boolean_op = BooleanOp::Xor;
      else args.usage_error("unknown Boolean operation '" + op + "' (known: union, intersection, difference, xor)");
    } else if (a == "--csg") {
      csg = args.value("--csg");
      if (csg->empty()) args.usage_error("--csg needs a file name, got ''");
    } else if (a == "--scale") {
      scale = true;
    } else if (a == "--classifier") {
      classifier = args.value("--classifier");
      if (classifier != "native" && classifier != "tritri")
        args.usage_error("unknown classifier '" + classifier + "' (known: native, tritri)");
    } else if (a == "--threads") {
      threads = static_cast<int>(args.count("--threads", 0, kMaxThreads));
    } else if (a == "--max-memory") {
      max_memory_mb = args.count("--max-memory", 1, kMaxMemoryMb);
    } else {
      inputs.push_back(args.operand("an input file name"));
    }
  }
  if (csg && !inputs.empty()) args.usage_error("--csg takes its operands from the CSG file, not from INPUT");
  if (csg && boolean_op) args.usage_error("--csg and --boolean exclude each other");
  if (inputs.empty() && !csg) args.usage_error("no input file");
  if (exact && args.given("--round"))
    args.usage_error("--round and --exact exclude each other (--exact does not round)");
  if (args.given("--round-max-move") && round != "safe") args.usage_error("--round-max-move needs --round safe");
  if (args.given("--round-without") && round != "safe") args.usage_error("--round-without needs --round safe");
  if (output) {
    using arrangements::detail::kWriteFormats;
    const auto format = arrangements::detail::format_of(*output, kWriteFormats);
    if (!format)
      args.usage_error("unknown output format '" + *output + "' (known: " +
                       arrangements::detail::extension_list(kWriteFormats) + ")");
    if (exact && *format == arrangements::detail::MeshFormat::ply)
      args.usage_error("--exact needs an .obj or .off output");
  }
  tools::set_memory_budget(static_cast<std::size_t>(max_memory_mb) << 20);
  const int workers = threads > 0 ? threads : tbb::info::default_concurrency();
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, workers);
  detail::exit_on_worker_failure("arrange", workers, 1);

  try {
    const auto t0 = std::chrono::steady_clock::now();
    // Double input takes the fast path; any rational coordinate the exact one.
    std::optional<CsgNode> tree;
    AnyTriangleSoup input;
    if (csg) {
      CsgScene scene = load_csg_file(*csg);
      tree = std::move(scene.tree);
      input = std::move(scene.soup);
      inputs = std::move(scene.operand_files);  // names operands in messages
    } else {
      input = load_mesh_files(inputs);
      if (boolean_op) tree = operation_tree(*boolean_op, static_cast<int>(inputs.size()));
    }
    const double t_load = seconds_since(t0);
    // The workers now, so that a refused thread is a message, not SIGABRT inside oneTBB.
    detail::start_worker_threads(workers);
    ArrangeOptions options;
    options.classifier = classifier == "tritri" ? Classifier::Tritri : Classifier::Native;
    options.threads = workers;
    options.scale = scale;
    return std::visit(
        [&](const auto& soup) {
          // The loader checked every fact about the input as it read it (validate once).
          // Never destroyed: the process ends with it (support/kept_until_exit.h).
          auto& result = detail::kept_until_exit(tree ? detail::boolean_validated(soup, *tree, options)
                                                      : detail::arrange_validated(soup, options));
          ArrangeStats& s = result.stats;
          add_load_time(s, t_load);
          std::optional<RoundedMesh> rounded;
          if (round == "safe") {
            const auto tr = std::chrono::steady_clock::now();
            RoundSafeOptions ro;
            ro.threads = workers;
            ro.max_move_relative = round_max_move;
            ro.without = round_without;
            // The input-level steps re-arrange the input: not for a Boolean (its output is not
            // the input's arrangement).
            if constexpr (std::is_same_v<std::decay_t<decltype(soup)>, TriangleSoup>)
              if (!tree) ro.input = &soup;
            // A Boolean's rounded output must still be a closed solid.
            ro.keep_closed = tree.has_value();
            RoundReport report;
            try {
              rounded = round_safe(result.mesh, ro, &report);
            } catch (const RoundingError& e) {
              std::fprintf(stderr,
                           "arrange: %s%s\narrange: --round-max-move accepts larger moves; --exact writes the "
                           "%s without rounding\n",
                           e.what(), tree ? " (a Boolean's rounding must also stay closed)" : "",
                           tree ? "Boolean" : "arrangement");
              return 4;
            }
            add_round_report(report, *rounded, s);
            add_write_time(s, seconds_since(tr));
          }
          if (output) {
            const auto tw = std::chrono::steady_clock::now();
            WriteOptions wo;
            wo.exact = exact;
            if (rounded)
              write_mesh(*output, *rounded, wo);
            else
              write_mesh(*output, result.mesh, wo);
            add_write_time(s, seconds_since(tw));
          }
          if (stats) std::printf("%s\n", stats_json(s).c_str());
          if (check) {
            const ArrangementCheck c = rounded ? check_arrangement(*rounded) : check_arrangement(result.mesh);
            std::fprintf(stderr,
                         "arrange: check: %zu output pairs checked, %zu violations, %zu degenerate triangles\n",
                         c.pairs_checked, c.violations, c.degenerate_triangles);
            for (const auto& e : c.examples) std::fprintf(stderr, "  %s\n", e.c_str());
            if (!c.ok()) return 3;
          }
          return 0;
        },
        input);
  } catch (const OpenOperandError& e) {
    const std::string file = e.operand >= 0 && e.operand < static_cast<int>(inputs.size()) ? inputs[e.operand] : "?";
    std::fprintf(stderr, "arrange: %s: %s\n", file.c_str(), e.what());
    return 1;
  } catch (const InputError& e) {
    std::fprintf(stderr, "arrange: %s\n", e.what());
    return 1;
  } catch (const detail::WorkerThreadsError& e) {
    std::fprintf(stderr, "arrange: %s (--threads sets fewer)\n", e.what());
    return 1;
  } catch (const MemoryBudgetExhausted&) {
    std::fprintf(stderr, "arrange: needs more than %lld MB of memory (--max-memory %lld)\n",
                 max_memory_mb, max_memory_mb);
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "arrange: out of memory (the system refused an allocation)\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "arrange: error: %s\n", e.what());
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  arrangements::tools::install_gmp_counting();
  arrangements::detail::keep_standard_streams_open();
  const int status = run(argc, argv);
  return arrangements::detail::finish_standard_output("arrange", status, 1);
}
