#include "stages/3_classify_tritri.h"

#include <tritri/classify.h>
#include <tritri/counting_kernel.h>
#include <tritri/double_kernel.h>
#include <tritri/plane_filter.h>

#include "models/exact_model.h"

namespace arrangements {

template <class K>
bool classify_pair_tritri(const K& k, const std::vector<typename K::Point>& V, const std::vector<Tri>& F, int ta,
                          int tb, PairIntersection& out) {
  const Tri& a = F[ta];
  const Tri& b = F[tb];
  const tritri::Result r = tritri::classify(k, V[a[0]], V[a[1]], V[a[2]], V[b[0]], V[b[1]], V[b[2]]);
  bool only_shared = true;
  for (const auto& p : r.points) only_shared &= p.type == tritri::Type::VA_ON_VB;
  if (!r.intersects() || only_shared) return false;

  out = PairIntersection{};
  out.tri[0] = ta;
  out.tri[1] = tb;
  out.coplanar = r.coplanar;
  using T = tritri::Type;
  using L = Location;
  auto loc = [](Location::Kind kind, int id) { return Location{kind, static_cast<std::int8_t>(id)}; };
  auto next = [](int i) { return (i + 1) % 3; };
  // Does edge e of triangle t lie in the plane of triangle o? Both orient3d always run (no
  // short cut): the stage counts two orient3d per question, whatever the first one says.
  auto edge_in_plane = [&](const Tri& t, int e, const Tri& o) {
    const bool first = k.orient3d(V[o[0]], V[o[1]], V[o[2]], V[t[e]]) == tritri::Sign::Zero;
    const bool second = k.orient3d(V[o[0]], V[o[1]], V[o[2]], V[t[next(e)]]) == tritri::Sign::Zero;
    return first && second;
  };
  for (const auto& p : r.points) {
    PairPoint q;
    const int i = p.id0, j = p.id1;
    switch (p.type) {
      case T::VA_ON_VB:
        q.vertex = a[i];
        q.in[0] = loc(L::Vertex, i);
        q.in[1] = loc(L::Vertex, j);
        break;
      case T::VA_ON_EB:
        q.vertex = a[i];
        q.in[0] = loc(L::Vertex, i);
        q.in[1] = loc(L::Edge, j);
        break;
      case T::VB_ON_EA:
        q.vertex = b[i];
        q.in[0] = loc(L::Edge, j);
        q.in[1] = loc(L::Vertex, i);
        break;
      case T::VA_ON_TB:
        q.vertex = a[i];
        q.in[0] = loc(L::Vertex, i);
        q.in[1] = loc(L::Interior, -1);
        break;
      case T::VB_ON_TA:
        q.vertex = b[i];
        q.in[0] = loc(L::Interior, -1);
        q.in[1] = loc(L::Vertex, i);
        break;
      case T::EA_CROSS_TB:
        q.lpi = make_lpi_key(a[i], a[next(i)], b[0], b[1], b[2]);
        q.in[0] = loc(L::Edge, i);
        q.in[1] = loc(L::Interior, -1);
        break;
      case T::EB_CROSS_TA:
        q.lpi = make_lpi_key(b[i], b[next(i)], a[0], a[1], a[2]);
        q.in[0] = loc(L::Interior, -1);
        q.in[1] = loc(L::Edge, i);
        break;
      case T::EA_CROSS_EB:
        if (r.coplanar)
          q.lpi = make_lpi_key(a[i], a[next(i)], b[j], b[next(j)], -1 - tb);
        else if (!edge_in_plane(a, i, b))
          q.lpi = make_lpi_key(a[i], a[next(i)], b[0], b[1], b[2]);
        else
          q.lpi = make_lpi_key(b[j], b[next(j)], a[0], a[1], a[2]);
        q.in[0] = loc(L::Edge, i);
        q.in[1] = loc(L::Edge, j);
        break;
    }
    out.points.push_back(q);
  }
  for (const auto& s : r.segments) out.segments.push_back(s);
  return true;
}

template bool classify_pair_tritri(const tritri::DoubleKernel&, const std::vector<Vec3>&, const std::vector<Tri>&, int,
                                   int, PairIntersection&);
template bool classify_pair_tritri(const tritri::PlaneCachedKernel&, const std::vector<Vec3>&, const std::vector<Tri>&,
                                   int, int, PairIntersection&);
template bool classify_pair_tritri(const tritri::CountingKernel<tritri::DoubleKernel>&, const std::vector<Vec3>&,
                                   const std::vector<Tri>&, int, int, PairIntersection&);
template bool classify_pair_tritri(const ExactModel::Kernel&, const std::vector<ExactModel::Vertex>&,
                                   const std::vector<Tri>&, int, int, PairIntersection&);
template bool classify_pair_tritri(const tritri::CountingKernel<ExactModel::Kernel>&,
                                   const std::vector<ExactModel::Vertex>&, const std::vector<Tri>&, int, int,
                                   PairIntersection&);

}  // namespace arrangements
