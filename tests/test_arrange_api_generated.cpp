// The Eigen API arrangements::arrange(V, F, options, labels) on generated inputs (seeded
// random soups, grids, spheres): the same output as arrangements::arrange on the
// equivalent TriangleSoup, the same output for 1, 2 and all threads, and provenance and
// fields checked exactly (support/eigen_api_checks.h). Hand-made scenes, input forms and
// bad input: test_arrange_api.cpp.
#include "support/eigen_api_checks.h"

namespace {

using namespace eigen_api;

// --- generated inputs: soup API equivalence, threads, provenance ------------------------
// Random soups: integer coordinates in [0, 3] (many coplanar, touching, degenerate and
// duplicate triangles) or uniform doubles; random rows, labels in [0, 4].
Scene random_scene(unsigned seed) {
  std::mt19937 rng(seed);
  const int nv = 5 + static_cast<int>(rng() % 10), nf = 3 + static_cast<int>(rng() % 12);
  Scene s{Eigen::MatrixXd(nv, 3), Eigen::MatrixXi(nf, 3), Eigen::VectorXi(nf)};
  std::uniform_real_distribution<double> real(-1.0, 1.0);
  for (int r = 0; r < nv; ++r)
    for (int c = 0; c < 3; ++c) s.V(r, c) = seed % 2 ? real(rng) : static_cast<double>(rng() % 4);
  for (int r = 0; r < nf; ++r) {
    for (int c = 0; c < 3; ++c) s.F(r, c) = static_cast<int>(rng() % nv);
    s.labels(r) = static_cast<int>(rng() % 5);
  }
  return s;
}

std::vector<std::pair<std::string, Scene>> generated_scenes() {
  using namespace arrangements;
  std::vector<std::pair<std::string, Scene>> out;
  for (unsigned seed = 1; seed <= 40; ++seed) out.emplace_back("random " + std::to_string(seed), random_scene(seed));
  out.emplace_back("two spheres",
                   from_soup(concatenate(uv_sphere({0, 0, 0}, 1, 6, 8), uv_sphere({0.5, 0.3, 0.2}, 0.8, 5, 7))));
  out.emplace_back("grid through sphere",
                   from_soup(concatenate(grid(4, 0.5, 0.1, -1, -1), uv_sphere({0, 0, 0}, 0.9, 5, 6))));
  out.emplace_back("rotated grids", from_soup(rotated_copies(grid(3, 1.0, 0.0), 3)));
  out.emplace_back("rotated boxes", from_soup(rotated_copies(box({0, 0, 0}, {2, 1, 1}), 3)));
  out.emplace_back("cube through cube", cube_through_cube());
  out.emplace_back("coplanar", coplanar(true));
  return out;
}

// The TriangleSoup a user would build for (V, F, labels): source = row, label sets
// numbered in decreasing label order (the Eigen layer numbers them by first use).
TriangleSoup soup_of(const Scene& s) {
  TriangleSoup t;
  for (int r = 0; r < s.V.rows(); ++r) t.vertices.push_back({s.V(r, 0), s.V(r, 1), s.V(r, 2)});
  std::map<int, int, std::greater<int>> index;
  for (int r = 0; r < s.F.rows(); ++r) index[s.labels.size() ? s.labels(r) : 0] = 0;
  for (auto& [label, i] : index) {
    i = static_cast<int>(t.label_sets.size());
    t.label_sets.push_back({static_cast<std::uint32_t>(label)});
  }
  for (int r = 0; r < s.F.rows(); ++r) {
    t.triangles.push_back({s.F(r, 0), s.F(r, 1), s.F(r, 2)});
    t.label_set.push_back(index[s.labels.size() ? s.labels(r) : 0]);
    t.source.push_back(r);
  }
  return t;
}

TEST(ArrangeApi, SameOutputAsTheSoupApi) {
  for (const auto& [name, s] : generated_scenes())
    for (Classifier c : kClassifiers) {
      const std::string what = name + " (" + name_of(c) + ")";
      const EigenArrangement a = run(s, opts(c, 2));
      const arrangements::ArrangeResult r = arrangements::arrange(soup_of(s), opts(c, 2));
      const auto& m = r.mesh;
      ASSERT_TRUE(std::size_t(a.V.rows()) == m.vertices.size() && std::size_t(a.F.rows()) == m.triangles.size())
          << what;
      for (int v = 0; v < a.V.rows(); ++v) {
        EXPECT_EQ(out_point(a, v), tritri_test::exact(m.vertices[v])) << what << ": vertex " << v;
        EXPECT_EQ(a.vertices[v].kind(), m.vertices[v].kind()) << what;
      }
      for (int f = 0; f < a.F.rows(); ++f) {
        for (int k = 0; k < 3; ++k) EXPECT_EQ(a.F(f, k), m.triangles[f][k]) << what << ": face " << f;
        EXPECT_EQ(a.source(f), m.source[f]) << what << ": face " << f;
        const auto& set = m.label_sets.at(m.label_set[f]);
        EXPECT_EQ(labels_of(a, f), std::vector<int>(set.begin(), set.end())) << what << ": face " << f;
      }
      const auto counts = [](const arrangements::ArrangeStats& t) {
        return std::vector<std::size_t>{t.in_vertices,        t.in_triangles,        t.merged_vertices,
                                        t.removed_degenerate, t.removed_duplicate,   t.candidate_pairs,
                                        t.intersecting_pairs, t.coplanar_pairs,      t.intersection_points,
                                        t.segments,           t.tri_segments,        t.tpi,
                                        t.out_vertices,       t.out_edges,           t.out_triangles,
                                        std::size_t(t.euler), std::size_t(t.threads)};
      };
      EXPECT_EQ(counts(a.stats), counts(r.stats)) << what;
      EXPECT_EQ(a.stats.classifier, r.stats.classifier) << what;
    }
}

TEST(ArrangeApi, SameOutputForOneTwoAndAllThreads) {
  for (const auto& [name, s] : generated_scenes())
    for (Classifier c : kClassifiers) {
      const EigenArrangement one = run(s, opts(c, 1));
      expect_same(run(s, opts(c, 2)), one, name + ", 2 threads, " + name_of(c));
      expect_same(run(s, opts(c, 0)), one, name + ", all threads, " + name_of(c));
    }
}

TEST(ArrangeApi, ProvenanceAndFieldsOfGeneratedInputs) {
  for (const auto& [name, s] : generated_scenes()) {
    const EigenArrangement a = run(s, opts(Classifier::Tritri, 2));
    expect_well_formed(a, s, name);
    expect_provenance(a, s, name);
  }
}

}  // namespace
