// bench/cgal_boolean.cpp
//
// A peer for bench/boolean_bench.py: CGAL's corefinement Boolean of two closed meshes.
//
// usage: cgal_boolean A B union|intersection|difference OUT [--kernel epick|epeck] [--no-volume]
//
// A and B: OFF/OBJ/STL/PLY, read with CGAL::IO::read_polygon_mesh into a Surface_mesh
// (polygons triangulated; coordinates read as doubles, also with epeck). Operands that are
// not closed, do not bound a volume or self-intersect are refused (CGAL's preconditions; the
// check is timed as t_check_s).
// OUT is written by extension (OFF/OBJ/STL/PLY, 17 significant digits).
// One JSON line on stdout:
//   {"ok":true,"kernel":..,"seconds":..,"triangles":..,"volume":..,"t_load_s":..,
//    "t_check_s":..,"peak_rss_mb":..}
// seconds: corefine_and_compute_<op> alone. volume: of the result; with epeck the exact
// rational "num/den" (sum of the exact tetrahedron volumes against the origin, added
// pairwise so that operands stay balanced), with epick the double PMP::volume as a decimal
// string; null with --no-volume (timing runs: the exact sum is not part of the Boolean).
// peak_rss_mb: this process's own (getrusage).
// Exit status: 0 done; 1 the Boolean failed (CGAL: the result would not be a 2-manifold);
// 2 bad command line or unreadable input; 3 refused operand ("refused: ..." on stderr).
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Clock = std::chrono::steady_clock;

[[noreturn]] void usage(int status) {
  std::fputs("usage: cgal_boolean A B union|intersection|difference OUT [--kernel epick|epeck] [--no-volume]\n",
             status ? stderr : stdout);
  std::exit(status);
}

[[noreturn]] void fail(int status, const std::string& message) {
  std::fprintf(stderr, "%s\n", message.c_str());
  std::printf("{\"ok\":false,\"error\":\"%s\"}\n", message.c_str());
  std::exit(status);
}

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

struct Options {
  std::string a, b, op, out, kernel = "epick";
  bool volume = true;
};

Options parse(int argc, char** argv) {
  Options o;
  std::vector<std::string> positional;
  bool kernel_given = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") usage(0);
    if (arg == "--kernel") {
      if (i + 1 >= argc || kernel_given) usage(2);
      o.kernel = argv[++i];
      kernel_given = true;
    } else if (arg == "--no-volume") {
      o.volume = false;
    } else if (!arg.empty() && arg[0] == '-') {
      usage(2);
    } else {
      positional.push_back(arg);
    }
  }
  if (positional.size() != 4 || (o.kernel != "epick" && o.kernel != "epeck")) usage(2);
  o.a = positional[0], o.b = positional[1], o.op = positional[2], o.out = positional[3];
  if (o.op != "union" && o.op != "intersection" && o.op != "difference") usage(2);
  return o;
}

// Read as doubles, then converted: Epeck's own reader takes "0.1" as the decimal 1/10, while
// every other tool (ours, manifold) works on the double nearest to it.
template <class Mesh>
Mesh read_operand(const std::string& file) {
  CGAL::Surface_mesh<CGAL::Epick::Point_3> doubles;
  if (!CGAL::IO::read_polygon_mesh(file, doubles) || doubles.number_of_faces() == 0)
    fail(2, "cannot read " + file + " as a polygon mesh");
  if (!CGAL::is_triangle_mesh(doubles)) PMP::triangulate_faces(doubles);
  if constexpr (std::is_same_v<Mesh, decltype(doubles)>) {
    return doubles;
  } else {
    Mesh mesh;
    CGAL::copy_face_graph(doubles, mesh);  // points through Cartesian_converter: exact
    return mesh;
  }
}

template <class Mesh>
void check_operand(const Mesh& mesh, const std::string& file) {
  if (!CGAL::is_closed(mesh)) fail(3, "refused: operand not closed (" + file + ")");
  if (PMP::does_self_intersect(mesh)) fail(3, "refused: self-intersecting operand (" + file + ")");
  if (!PMP::does_bound_a_volume(mesh)) fail(3, "refused: operand does not bound a volume (" + file + ")");
}

// The exact volume as "num/den": sum of det(a, b, c) / 6 over the faces, added pairwise.
template <class Mesh>
std::string exact_volume(const Mesh& mesh) {
  using ET = CGAL::Epeck_ft;
  std::vector<ET> terms;
  terms.reserve(mesh.number_of_faces());
  for (auto f : mesh.faces()) {
    std::vector<typename CGAL::Epeck::Exact_kernel::Point_3> p;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) p.push_back(CGAL::exact(mesh.point(v)));
    const auto &a = p[0], &b = p[1], &c = p[2];
    terms.push_back(a.x() * (b.y() * c.z() - b.z() * c.y()) - a.y() * (b.x() * c.z() - b.z() * c.x()) +
                    a.z() * (b.x() * c.y() - b.y() * c.x()));
  }
  if (terms.empty()) return "0/1";
  while (terms.size() > 1) {  // pairwise: the operands of each addition grow together
    std::vector<ET> next;
    next.reserve(terms.size() / 2 + 1);
    for (std::size_t i = 0; i + 1 < terms.size(); i += 2) next.push_back(terms[i] + terms[i + 1]);
    if (terms.size() % 2) next.push_back(terms.back());
    terms.swap(next);
  }
  std::ostringstream text;
  text << terms[0] / ET(6);
  std::string s = text.str();
  return s.find('/') == std::string::npos ? s + "/1" : s;
}

template <class Kernel>
int run(const Options& o) {
  using Mesh = CGAL::Surface_mesh<typename Kernel::Point_3>;
  auto start = Clock::now();
  Mesh a = read_operand<Mesh>(o.a), b = read_operand<Mesh>(o.b), result;
  const double t_load = since(start);
  start = Clock::now();
  check_operand(a, o.a);
  check_operand(b, o.b);
  const double t_check = since(start);
  start = Clock::now();
  const bool ok = o.op == "union"          ? PMP::corefine_and_compute_union(a, b, result)
                  : o.op == "intersection" ? PMP::corefine_and_compute_intersection(a, b, result)
                                           : PMP::corefine_and_compute_difference(a, b, result);
  const double seconds = since(start);
  if (!ok) fail(1, "failed: CGAL corefinement: the result would not be a 2-manifold");
  if (!CGAL::IO::write_polygon_mesh(o.out, result, CGAL::parameters::stream_precision(17)))
    fail(2, "cannot write " + o.out);
  std::string volume = "null";
  if (o.volume) {
    if constexpr (std::is_same_v<Kernel, CGAL::Epeck>) {
      volume = "\"" + exact_volume(result) + "\"";
    } else {
      char text[64];
      std::snprintf(text, sizeof text, "\"%.17g\"", CGAL::to_double(PMP::volume(result)));
      volume = text;
    }
  }
  std::printf("{\"ok\":true,\"kernel\":\"%s\",\"seconds\":%.6f,\"triangles\":%zu,\"volume\":%s,"
              "\"t_load_s\":%.6f,\"t_check_s\":%.6f,\"peak_rss_mb\":%.1f}\n",
              o.kernel.c_str(), seconds, static_cast<std::size_t>(result.number_of_faces()), volume.c_str(), t_load,
              t_check, peak_rss_mb());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  try {
    return o.kernel == "epeck" ? run<CGAL::Epeck>(o) : run<CGAL::Epick>(o);
  } catch (const std::exception& e) {
    fail(1, std::string("failed: ") + e.what());
  }
}
