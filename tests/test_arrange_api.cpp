// Specification of the Eigen API arrangements::arrange(V, F, options, labels)
// (arrangements/arrange_eigen.h) as a user relies on it, checked exactly (rationals from
// tritri::to_exact, no tolerance): hand-made scenes with answers derived by hand (in the
// comments); every output field and input form; options; bad input throws
// std::invalid_argument. Generated inputs: test_arrange_api_generated.cpp.
#include "support/eigen_api_checks.h"

namespace {

using namespace eigen_api;

struct HandCase {
  std::string name;
  Scene scene;
  int V, E, F;
  std::vector<int> per_source;
  std::set<Q3> fresh;  // the new (implicit) vertices, exactly
};

std::vector<HandCase> hand_cases() {
  std::vector<int> cube(24, 1);
  cube[2] = cube[3] = 9;
  std::fill(cube.begin() + 16, cube.end(), 3);
  std::set<Q3> loop;
  for (double y : {0.5, 1.0, 1.5})
    for (double z : {0.5, 1.0, 1.5})
      if (y != 1.0 || z != 1.0) loop.insert(q3(2, y, z));
  return {{"crossing", crossing(), 8, 15, 8, {5, 3}, {q3(1, 1, 0), {Q(5, 3), Q(1), Q(0)}}},
          {"pierced", pierced(), 8, 15, 8, {4, 4}, {q3(1, 1, 0), q3(3, 1, 0)}},
          {"touching", touching(), 6, 9, 4, {3, 1}, {}},
          {"cube through cube", cube_through_cube(), 24, 76, 56, cube, loop},
          {"shared vertices", shared_vertices(), 6, 9, 5, {1, 1, 1, 1, 1}, {}}};
}

TEST(ArrangeApi, HandScenesCountsPointsAndTiling) {
  for (const HandCase& h : hand_cases())
    for (Classifier c : kClassifiers) {
      const std::string what = h.name + " (" + name_of(c) + ")";
      const EigenArrangement a = run(h.scene, opts(c));
      expect_well_formed(a, h.scene, what);
      expect_provenance(a, h.scene, what, true);
      EXPECT_EQ((std::array<long long, 3>{a.V.rows(), (long long)a.stats.out_edges, a.F.rows()}),
                (std::array<long long, 3>{h.V, h.E, h.F}))
          << what << ": V, E, F";
      std::vector<int> per_source(h.scene.F.rows(), 0);
      for (int f = 0; f < a.F.rows(); ++f) ++per_source.at(a.source(f));
      EXPECT_EQ(per_source, h.per_source) << what;
      std::set<Q3> fresh;
      for (int v = 0; v < a.V.rows(); ++v)
        if (!a.vertices[v].is_explicit()) {
          EXPECT_EQ(a.vertices[v].kind(), tritri::ImplicitPoint::Kind::LPI) << what;
          fresh.insert(out_point(a, v));
        }
      EXPECT_EQ(fresh, h.fresh) << what;
      EXPECT_TRUE(a.stats.intersection_points == h.fresh.size() && a.stats.tpi == 0) << what;
      EXPECT_EQ(a.stats.classifier, name_of(c));
      if (h.scene.labels.size() == 0) {
        for (int f = 0; f < a.F.rows(); ++f)
          EXPECT_EQ(labels_of(a, f), std::vector<int>{0}) << what;  // no labels: all 0
      }
    }
}

// Crossing: p = (1,1,0) is a double, q = (5/3,1,0) is rounded in V; pq is an edge of both.
TEST(ArrangeApi, CrossingSegmentEndpoints) {
  const EigenArrangement a = run(crossing());
  int ip = -1, iq = -1;
  for (int v = 0; v < a.V.rows(); ++v) {
    if (out_point(a, v) == q3(1, 1, 0)) ip = v;
    if (out_point(a, v) == Q3{Q(5, 3), Q(1), Q(0)}) iq = v;
  }
  ASSERT_TRUE(ip >= 0 && iq >= 0);
  EXPECT_TRUE(a.V_is_exact(ip) && !a.V_is_exact(iq));
  EXPECT_TRUE((a.V.row(ip) == Eigen::RowVector3d(1, 1, 0)));
  EXPECT_TRUE((a.V.row(iq) == Eigen::RowVector3d(5.0 / 3.0, 1, 0)));
  EXPECT_EQ(a.V_is_exact.count(), 7);
  std::set<int> sides;
  for (int f = 0; f < a.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (std::minmax(a.F(f, k), a.F(f, (k + 1) % 3)) == std::minmax(ip, iq)) sides.insert(a.source(f));
  EXPECT_EQ(sides, (std::set<int>{0, 1}));
  EXPECT_EQ(a.stats.intersecting_pairs, 1u);
}

// Cube: labels by box; shared vertices: the apex is one vertex of rows 1-4, duplicates
// merged.
TEST(ArrangeApi, CubeLabelsAndSharedApex) {
  const EigenArrangement a = run(cube_through_cube());
  for (int f = 0; f < a.F.rows(); ++f) EXPECT_EQ(labels_of(a, f), std::vector<int>{a.source(f) < 12 ? 0 : 1});
  const EigenArrangement b = run(shared_vertices());
  EXPECT_TRUE(b.stats.merged_vertices == 1 && b.stats.intersection_points == 0);
  std::set<int> users;
  for (int f = 0; f < b.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (out_point(b, b.F(f, k)) == q3(0, 0, 1)) users.insert(b.source(f));
  EXPECT_EQ(users, (std::set<int>{1, 2, 3, 4}));
}

TEST(ArrangeApi, CoplanarOverlapUnitesLabels) {
  for (bool b_first : {false, true})
    for (Classifier c : kClassifiers) {
      const std::string what = std::string(name_of(c)) + (b_first ? ", B first" : "");
      const Scene s = coplanar(b_first);  // labels: A 7, B 3
      const EigenArrangement a = run(s, opts(c));
      expect_well_formed(a, s, what);
      expect_provenance(a, s, what);
      EXPECT_TRUE(a.V.rows() == 8 && a.stats.out_edges == 14 && a.F.rows() == 7) << what;
      EXPECT_EQ(a.stats.coplanar_pairs, 1u) << what;
      struct Region {
        int triangles = 0;
        Q area2 = 0;  // z component of the normals: twice the area in z = 0
        std::set<int> sources;
      };
      std::map<std::vector<int>, Region> regions;
      for (int f = 0; f < a.F.rows(); ++f) {
        Region& r = regions[labels_of(a, f)];
        const Q z = out_normal(a, f)[2];
        EXPECT_GT(z, 0) << what;  // oriented like the input, counter-clockwise
        ++r.triangles, r.area2 += z, r.sources.insert(a.source(f));
      }
      const int rowA = b_first ? 1 : 0, rowB = b_first ? 0 : 1;
      ASSERT_EQ(regions.size(), 3u) << what;
      // {3, 7}: the overlap, owned by the first row covering it (row 0).
      const std::tuple<std::vector<int>, int, int, int> want[] = {
          {{3, 7}, 1, 4, 0}, {{7}, 4, 12, rowA}, {{3}, 2, 12, rowB}};  // labels, triangles, twice area, source
      for (const auto& [labels, triangles, area2, row] : want) {
        const Region& r = regions[labels];
        EXPECT_TRUE(r.triangles == triangles && r.area2 == area2 && r.sources == std::set<int>{row})
            << what << ", labels " << labels.back() << " (" << labels.size() << "): " << r.triangles << " " << r.area2;
      }
    }
}

// A duplicate of a triangle (any corner order) is removed and gives its labels to the
// first one; labels are any non-negative ints.
TEST(ArrangeApi, DuplicateTrianglesUniteLabels) {
  Scene s = coplanar(false);
  s.F.conservativeResize(3, 3);
  s.F.row(2) << 1, 2, 0;  // A again
  s.labels.conservativeResize(3);
  s.labels(2) = INT_MAX;
  const EigenArrangement a = run(s);
  expect_well_formed(a, s, "duplicate");
  EXPECT_EQ(a.stats.removed_duplicate, 1u);
  std::set<std::vector<int>> sets;
  for (int f = 0; f < a.F.rows(); ++f) sets.insert(labels_of(a, f));
  EXPECT_EQ(sets, (std::set<std::vector<int>>{{7, INT_MAX}, {3, 7, INT_MAX}, {3}}));
  for (int f = 0; f < a.F.rows(); ++f) EXPECT_NE(a.source(f), 2);
}

// Nothing intersects: the output is the input (vertices in first-use order, each
// triangle the same up to a rotation of its corners, source = row).
TEST(ArrangeApi, DisjointTrianglesAreOutputUnchanged) {
  const Scene s = scene({{0, 0, 0},
                         {1, 0, 0},
                         {0, 1, 0},
                         {5, 5, 5},
                         {6, 5, 5.5},
                         {5, 7, 6},
                         {0.1, 0.2, 9},
                         {0.3, 0.1, 9.5},
                         {0.2, 0.7, 9}},
                        {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}}, {4, 1, 4});
  const EigenArrangement a = run(s);
  expect_well_formed(a, s, "disjoint");
  EXPECT_TRUE(a.V == s.V && a.V_is_exact.all());
  ASSERT_EQ(a.F.rows(), 3);
  for (int f = 0; f < 3; ++f) {
    EXPECT_TRUE(a.source(f) == f && labels_of(a, f) == std::vector<int>{s.labels(f)}) << f;
    bool rotated = false;
    for (int k = 0; k < 3; ++k)
      rotated = rotated || a.F.row(f) == Eigen::RowVector3i(s.F(f, k), s.F(f, (k + 1) % 3), s.F(f, (k + 2) % 3));
    EXPECT_TRUE(rotated) << "face " << f;
  }
  EXPECT_TRUE(a.stats.intersecting_pairs == 0 && a.stats.euler == 3);
}

// Nothing left to arrange (all triangles degenerate, or none) is an empty arrangement, not
// an error.
TEST(ArrangeApi, DegenerateOrEmptyInputGivesAnEmptyArrangement) {
  const Scene degenerate = scene({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {5, 0, 0}, {0, 0, 0}},
                                 {{0, 1, 2}, {3, 3, 0}, {0, 4, 3}}, {1, 2, 3});  // collinear, repeated, coincident
  const Scene no_rows{Eigen::MatrixXd(0, 3), Eigen::MatrixXi(0, 3), Eigen::VectorXi()};
  const Scene no_faces{Eigen::MatrixXd::Ones(2, 3), Eigen::MatrixXi(0, 3), Eigen::VectorXi(0)};
  const Scene sizeless{Eigen::MatrixXd(), Eigen::MatrixXi(), Eigen::VectorXi()};
  for (const Scene* s : {&degenerate, &no_rows, &no_faces, &sizeless}) {
    EigenArrangement a;
    EXPECT_NO_THROW(a = arrangements::arrange(s->V, s->F, opts(), s == &no_faces ? &s->labels : nullptr));
    EXPECT_TRUE(a.V.rows() == 0 && a.V.cols() == 3 && a.F.rows() == 0 && a.F.cols() == 3 && a.source.size() == 0 &&
                a.label_set.size() == 0 && a.vertices.empty() && a.V_is_exact.size() == 0);
    EXPECT_TRUE(a.stats.out_triangles == 0 && a.stats.out_vertices == 0 && a.stats.euler == 0);
  }
  EXPECT_EQ(run(degenerate).stats.removed_degenerate, 3u);
}

// --- input forms and options ------------------------------------------------------------
TEST(ArrangeApi, OtherEigenMatrixTypesGiveTheSameOutput) {
  const Scene s = crossing();
  const EigenArrangement ref = run(s);
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> Vr = s.V;
  const Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor> Fr = s.F;
  const Eigen::Matrix<double, 6, 3> Vf = s.V;
  const Eigen::Matrix<int, 2, 3> Ff = s.F;
  std::vector<double> vbuf(Vr.data(), Vr.data() + Vr.size());
  std::vector<int> fbuf(Fr.data(), Fr.data() + Fr.size());
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> Vm(vbuf.data(), 6, 3);
  const Eigen::Map<const Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> Fm(fbuf.data(), 2, 3);
  expect_same(arrangements::arrange(Vr, Fr, opts()), ref, "row-major");
  expect_same(arrangements::arrange(Vf, Ff, opts()), ref, "fixed size");
  expect_same(arrangements::arrange(Vm, Fm, opts()), ref, "maps");
  expect_same(arrangements::arrange(s.V, s.F, {}), ref, "default options");
  const Eigen::VectorXi zeros = Eigen::VectorXi::Zero(2);
  expect_same(arrangements::arrange(s.V, s.F, opts(), &zeros), ref, "labels all 0 = no labels");
}

TEST(ArrangeApi, OptionsAreHonoured) {
  const Scene s = crossing();
  const EigenArrangement ref = run(s);
  for (int t : {1, 2}) EXPECT_EQ(run(s, opts(Classifier::Tritri, t)).stats.threads, t);
  EXPECT_GE(run(s, opts(Classifier::Tritri, 0)).stats.threads, 1);
  EXPECT_EQ(run(s, opts(Classifier::Native)).stats.classifier, "native");
  ArrangeOptions o = opts();
  EXPECT_EQ(ref.stats.orient3d_calls, 0u);
  o.count_predicates = true;
  const EigenArrangement counted = run(s, o);
  expect_same(counted, ref, "count_predicates");
  EXPECT_GT(counted.stats.orient3d_calls, 0u);
}

// scale: the same exact output in the input's coordinates, whatever the magnitude (also
// when scaling would round a coordinate: the model is then kept unscaled, no error).
TEST(ArrangeApi, ScaleGivesTheSameOutput) {
  const Scene base = crossing();
  for (double k : {0.1, std::ldexp(1.0, -700), 1e300}) {
    Scene s = base;
    s.V *= k;
    if (k == 1e300) s.V(0, 0) = 1e-300;  // a dynamic range no power of two can scale exactly
    ArrangeOptions o = opts();
    o.scale = true;  // exact power-of-two scaling inside, undone on output
    EigenArrangement scaled;
    ASSERT_NO_THROW(scaled = run(s, o)) << k;
    expect_same(scaled, run(s), "scale " + std::to_string(k));
    expect_provenance(scaled, s, "scale");
  }
}

// --- bad input --------------------------------------------------------------------------
TEST(ArrangeApi, BadInputThrowsInvalidArgument) {
  const Scene s = crossing();
  std::vector<std::pair<std::string, std::function<void()>>> cases;
  auto with = [&](const std::string& name, Scene t) { cases.emplace_back(name, [t] { run(t); }); };
  for (int cols : {1, 2, 4}) {
    with("V with " + std::to_string(cols) + " columns", Scene{Eigen::MatrixXd::Zero(6, cols), s.F, {}});
    with("F with " + std::to_string(cols) + " columns", Scene{s.V, Eigen::MatrixXi::Zero(2, cols), {}});
  }
  auto change = [&](auto edit) {
    Scene t = s;
    edit(t);
    return t;
  };
  for (double bad : {NAN, INFINITY, -INFINITY})
    for (int r : {0, 5})
      with(std::to_string(bad) + " in row " + std::to_string(r), change([&](Scene& t) { t.V(r, r % 3) = bad; }));
  with("NaN in an unreferenced row", change([](Scene& t) { t.V.conservativeResize(7, 3), t.V.row(6) << 0, NAN, 0; }));
  for (int i : {6, 1000, -1, INT_MIN}) with("index " + std::to_string(i), change([&](Scene& t) { t.F(1, 2) = i; }));
  with("indices into an empty V", Scene{Eigen::MatrixXd(0, 3), s.F, Eigen::VectorXi()});
  for (int n : {1, 3}) with(std::to_string(n) + " labels for 2 rows", Scene{s.V, s.F, Eigen::VectorXi::Zero(n)});
  with("negative label", Scene{s.V, s.F, Eigen::Vector2i(0, -1)});
  const Eigen::VectorXi none(0);
  cases.emplace_back("empty labels vector", [&] { arrangements::arrange(s.V, s.F, opts(), &none); });
  for (const auto& [name, call] : cases) EXPECT_THROW(call(), std::invalid_argument) << name;
  expect_same(run(s), run(s), "after the errors");  // still usable
}

}  // namespace
