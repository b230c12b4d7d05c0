#include "arrangements/check_arrangement.h"

#include <CGAL/Bbox_3.h>
#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/box_intersection_d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <tritri/box_pairs.h>
#include <tritri/direction_slabs.h>
#include <tritri/classify.h>
#include <tritri/double_kernel.h>
#include <tritri/implicit_kernel.h>
#include <tritri/projection.h>

#include "arrangements/memory_budget.h"
#include "arrangements/thread_count.h"
#include "models/exact_model.h"
#include "stages/2_candidate_pairs.h"
#include "stages/2_early_outs.h"
#include "support/pair_fault.h"

namespace arrangements {
namespace {

using Box = tritri::detail::box_pairs::Box;  // with its triangle_boxes

template <class Mesh>
std::string describe(const Mesh& m, int i, int j, const std::string& what) {
  auto tri = [&](int t) {
    std::string s = "triangle " + std::to_string(t) + " (" + std::to_string(m.triangles[t][0]) + ", " +
                    std::to_string(m.triangles[t][1]) + ", " + std::to_string(m.triangles[t][2]) + ")";
    if (static_cast<std::size_t>(t) < m.source.size()) s += " of input triangle " + std::to_string(m.source[t]);
    return s;
  };
  return tri(i) + " and " + tri(j) + ": " + what;
}

std::string points_of(const tritri::Result& r) {
  std::string s = r.coplanar ? " [coplanar]" : "";
  for (const auto& p : r.points)
    s += " " + std::to_string(static_cast<int>(p.type)) + "(" + std::to_string(p.id0) + "," + std::to_string(p.id1) +
         ")";
  return s;
}

// Whether stage 2's preconditions hold for double vertices V and triangles F, given no
// degenerate triangle: distinct positions, no two triangles with the same three vertices.
bool stage_two_applies(const std::vector<Vec3>& V, const std::vector<Tri>& F) {
  std::vector<Vec3> positions(V);
  std::sort(positions.begin(), positions.end());
  if (std::adjacent_find(positions.begin(), positions.end()) != positions.end()) return false;
  std::vector<Tri> sorted(F);
  for (Tri& f : sorted) std::sort(f.begin(), f.end());
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
}

// The check on points P (kernel K) with conservative boxes [lo, hi] per vertex; with
// `changed`, only the pairs with a triangle marked in it. With `doubles` (P's coordinates,
// when they are doubles) and no changed marks, the pairs that stage 2 (detect_pairs)
// settles, which meet only in what they share, are not classified again, where its
// preconditions hold (else every box pair is).
template <class K, class Mesh>
ArrangementCheck check_points(const Mesh& mesh, const std::vector<typename K::Point>& P,
                              const std::vector<std::array<double, 3>>& lo,
                              const std::vector<std::array<double, 3>>& hi, std::size_t max_reported,
                              const std::vector<char>* changed = nullptr,
                              const std::vector<Vec3>* doubles = nullptr) {
  ArrangementCheck out;
  const auto& F = mesh.triangles;
  auto triangle_boxes = [&] { return tritri::detail::box_pairs::triangle_boxes(lo, hi, F); };
  std::mutex m;
  auto report = [&](std::size_t& counter, std::string msg, int i = -1, int j = -1) {
    std::lock_guard<std::mutex> lock(m);
    ++counter;
    if (i >= 0) out.violating_pairs.emplace_back(i, j);
    if (out.examples.size() < max_reported) out.examples.push_back(std::move(msg));
  };
  tbb::parallel_for(std::size_t{0}, F.size(), [&](std::size_t t) {
    if (changed && !(*changed)[t]) return;
    const Tri& f = F[t];
    bool degenerate = f[0] == f[1] || f[1] == f[2] || f[0] == f[2];
    if (!degenerate) degenerate = tritri::projection(K{}, P[f[0]], P[f[1]], P[f[2]]).second == 0;
    if (degenerate) report(out.degenerate_triangles, "triangle " + std::to_string(t) + " is degenerate");
  });
  // Stage 2's early-outs, on doubles where its preconditions hold: the pairs they settle
  // meet only in what they share. Checking every pair, stage 2's search applies them (and
  // pairs the triangles around a hub by direction); checking the changed ones, each pair
  // found by the box search below.
  const bool early = doubles && out.degenerate_triangles == 0 && stage_two_applies(*doubles, F);
  std::vector<DoubleModel::PlaneCache> planes;
  if (early && changed) {
    planes.resize(F.size());
    tbb::parallel_for(std::size_t{0}, F.size(), [&](std::size_t t) {
      planes[t] = DoubleModel::plane_cache((*doubles)[F[t][0]], (*doubles)[F[t][1]], (*doubles)[F[t][2]]);
    });
  }
  // Implicit points: each triangle's source plane by construction and its orientation in
  // it, found once (pair_fault tests the pairs' sides against them, also inside classify).
  std::vector<tritri::SourcePlane> constructed;
  if constexpr (std::is_same_v<typename K::Point, tritri::ImplicitPoint>) {
    constructed.resize(F.size());
    tbb::parallel_for(std::size_t{0}, F.size(), [&](std::size_t t) {
      constructed[t] = tritri::source_plane(P[F[t][0]], P[F[t][1]], P[F[t][2]]);
    });
  }
  auto classify_pair = [&](int i, int j) {
    detail::memory_checkpoint();
    if (!planes.empty() && early_out<DoubleModel>(*doubles, F, planes, i, j).settled) return;
    const Tri& a = F[i];
    const Tri& b = F[j];
    tritri::Result r;
    const std::array<const tritri::SourcePlane*, 2> pair_planes{
        constructed.empty() ? nullptr : &constructed[i], constructed.empty() ? nullptr : &constructed[j]};
    const PairFault fault = pair_fault<K>(a, {P[a[0]], P[a[1]], P[a[2]]}, b, {P[b[0]], P[b[1]], P[b[2]]}, &r,
                                          constructed.empty() ? nullptr : &pair_planes);
    switch (fault) {
      case PairFault::none:
      case PairFault::degenerate:  // reported above
        return;
      case PairFault::same_vertices:
        return report(out.violations, describe(mesh, i, j, "same three vertices"), i, j);
      case PairFault::beyond_shared:
        return report(out.violations, describe(mesh, i, j, "they meet beyond their shared vertices:" + points_of(r)),
                      i, j);
      case PairFault::shared_not_reported:
        return report(out.violations, describe(mesh, i, j, "a shared vertex is not reported"), i, j);
      case PairFault::unexpected_segments:
        return report(out.violations, describe(mesh, i, j, "unexpected intersection segments"), i, j);
    }
  };
  // Overlapping pairs are classified in batches as the box search finds them: the list of
  // all of them can be far larger than the mesh (52M pairs for 42K triangles).
  constexpr std::size_t kBatch = std::size_t{1} << 20;
  std::vector<std::pair<int, int>> pairs;
  if (!(early && !changed)) pairs.reserve(std::min(kBatch, 16 * F.size() + 16));  // the box searches' batches
  auto flush = [&] {
    tbb::parallel_for(std::size_t{0}, pairs.size(),
                      [&](std::size_t k) { classify_pair(pairs[k].first, pairs[k].second); });
    out.pairs_checked += pairs.size();
    pairs.clear();
  };
  // The box pairs that can meet: triangles sharing a corner, or whose slabs along 10
  // diagonal directions overlap (tritri/direction_slabs.h, certified from the same boxes);
  // long thin triangles give far more box pairs than that.
  std::vector<tritri::DirectionSlabs> slabs;
  if (!(early && !changed)) slabs = tritri::triangle_slabs(lo, hi, F);
  auto found = [&](int a, int b) {
    detail::memory_checkpoint();
    if (tritri::apart_by_slabs(F[a], F[b], slabs[a], slabs[b])) return;
    pairs.emplace_back(std::min(a, b), std::max(a, b));
    if (pairs.size() == kBatch) flush();
  };
  if (early && !changed) {
    // The threads the caller allows (a global_control limit, as arrange --threads sets).
    const int threads = std::min({tbb::this_task_arena::max_concurrency(), kMaxThreads,
                                  static_cast<int>(tbb::global_control::active_value(
                                      tbb::global_control::max_allowed_parallelism))});
    const DetectedPairs detected = detect_pairs(*doubles, F, threads);
    tbb::parallel_for(std::size_t{0}, detected.pairs.size(), [&](std::size_t k) {
      classify_pair(detected.pairs[k].first, detected.pairs[k].second);
    });
    out.pairs_checked = detected.box_pairs;
  } else if (changed) {
    // The changed boxes against all: a pair of two changed triangles is found twice, keep one.
    std::vector<Box> boxes = triangle_boxes(), marked;
    for (const Box& b : boxes)
      if ((*changed)[b.info()]) marked.push_back(b);
    CGAL::box_intersection_d<CGAL::Sequential_tag>(
        marked.begin(), marked.end(), boxes.begin(), boxes.end(),
        [&](const Box& a, const Box& b) {
          if (a.info() == b.info() || ((*changed)[b.info()] && b.info() < a.info())) return;
          found(a.info(), b.info());
        },
        CGAL::Box_intersection_d::Box_traits_d<Box>(), 10, CGAL::Box_intersection_d::CLOSED);
  } else {
    std::vector<Box> boxes = triangle_boxes();
    CGAL::box_self_intersection_d<CGAL::Sequential_tag>(
        boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) { found(a.info(), b.info()); },
        CGAL::Box_intersection_d::Box_traits_d<Box>(), 10, CGAL::Box_intersection_d::CLOSED);
  }
  flush();
  std::sort(out.violating_pairs.begin(), out.violating_pairs.end());
  return out;
}

}  // namespace

ArrangementCheck check_arrangement(const OutputMesh& mesh, std::size_t max_reported) {
  const auto& P = mesh.vertices;
  // Conservative boxes: to_double is correctly rounded, so the exact coordinate lies
  // within one ulp of it.
  std::vector<std::array<double, 3>> lo(P.size()), hi(P.size());
  tbb::parallel_for(std::size_t{0}, P.size(), [&](std::size_t v) {
    const auto d = tritri::to_double(P[v]);
    for (int k = 0; k < 3; ++k) {
      lo[v][k] = std::nextafter(d[k], -std::numeric_limits<double>::infinity());
      hi[v][k] = std::nextafter(d[k], std::numeric_limits<double>::infinity());
    }
  });
  return check_points<tritri::ImplicitKernel>(mesh, P, lo, hi, max_reported);
}

ArrangementCheck check_arrangement(const ExactOutputMesh& mesh, std::size_t max_reported) {
  std::vector<ExactModel::Point> P(mesh.vertices.size());
  std::vector<std::array<double, 3>> lo(P.size()), hi(P.size());
  tbb::parallel_for(std::size_t{0}, P.size(), [&](std::size_t v) {
    P[v] = ExactModel::vertex(mesh.vertices[v]);
    ExactModel::bounds(P[v], lo[v], hi[v]);
  });
  return check_points<ExactModel::Kernel>(mesh, P, lo, hi, max_reported);
}

namespace {

ArrangementCheck check_rounded(const RoundedMesh& mesh, std::size_t max_reported, const std::vector<char>* changed) {
  // Doubles: tritri's double kernel (exact adaptive predicates), and their own exact boxes.
  return check_points<tritri::DoubleKernel>(mesh, mesh.vertices, mesh.vertices, mesh.vertices, max_reported, changed,
                                            &mesh.vertices);
}

}  // namespace

ArrangementCheck check_arrangement(const RoundedMesh& mesh, std::size_t max_reported) {
  return check_rounded(mesh, max_reported, nullptr);
}

ArrangementCheck check_arrangement_touching(const RoundedMesh& mesh, const std::vector<char>& changed,
                                            std::size_t max_reported) {
  if (changed.size() != mesh.triangles.size())
    throw std::invalid_argument("check_arrangement_touching: " + std::to_string(changed.size()) + " marks for " +
                                std::to_string(mesh.triangles.size()) + " triangles");
  return check_rounded(mesh, max_reported, &changed);
}

}  // namespace arrangements
