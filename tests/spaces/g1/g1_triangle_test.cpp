// The G1 space S¹_k on affine triangle meshes and mixed quad/triangle meshes (notes §8.1, §9):
// dimensions against the notes' formulas, Theorem 6.3 and a brute-force null space of all C0 + G1
// rows, per-entity counts, refusal below the separability degree, G1 residuals and physical C1
// continuity of every basis function, linear independence, partition of unity, polynomial
// reproduction and the Dirichlet / clamped subspaces.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <algorithm>
#include <functional>
#include <tuple>

#include "tests/spaces/g1/g1_test_support.hpp"
#include "config/errors.hpp"
#include "spaces/g1/g1_space.hpp"
#include "tests/support/patch_gradient_jump.hpp"
#include "spaces/g1/multipatch_domains.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;
using namespace iga::test;

namespace {

using P = Point2;

/// Four triangles of the square [0,2]² around `centre` (notes §8.1): T8 for (1,1), T9 for (9/10, 6/5).
PatchMesh four_triangles(const P& centre, const std::string& name) {
  return mesh_from_patches({{P(0, 0), P(2, 0), centre}, {P(2, 0), P(2, 2), centre}, {P(2, 2), P(0, 2), centre},
                            {P(0, 2), P(0, 0), centre}},
                           name);
}
PatchMesh t8() { return four_triangles(P(1, 1), "T8"); }
PatchMesh t9() { return four_triangles(P(0.9, 1.2), "T9"); }
PatchMesh mixed() { return multipatch_domain("2q2t_square"); }

std::shared_ptr<const PatchMesh> share(PatchMesh m) { return std::make_shared<const PatchMesh>(std::move(m)); }

struct Case {
  std::string name;
  std::function<PatchMesh()> mesh;
  int k;
};

/// Meshes and degrees where the local construction is complete (k >= 5 for flat triangles).
std::vector<Case> cases() {
  return {{"T8", t8, 4},
          {"T8", t8, 5},
          {"T8", t8, 6},
          {"T9", t9, 5},
          {"T9", t9, 6},
          {"2q2t_square", mixed, 5},
          {"2q2t_square level 1", [] { return mixed().refined(); }, 5},
          {"4t_star level 1", [] { return multipatch_domain("4t_star").refined(); }, 5}};
}

/// Counts of basis functions per vertex, per edge and per face.
struct EntityCounts {
  std::vector<int> vertex, edge, face;
};
EntityCounts entity_counts(const G1Space& s) {
  EntityCounts c{std::vector<int>(s.mesh().num_vertices(), 0), std::vector<int>(s.mesh().num_edges(), 0),
                 std::vector<int>(s.mesh().num_faces(), 0)};
  for (const G1FunctionInfo& i : s.basis().info)
    (i.entity == G1Entity::vertex ? c.vertex : i.entity == G1Entity::edge ? c.edge : c.face)[i.id] += 1;
  return c;
}

int vertex_at(const PatchMesh& m, const P& x) {
  for (int v = 0; v < m.num_vertices(); ++v)
    if ((m.vertex(v) - x).norm() < 1e-14) return v;
  return -1;
}

}  // namespace

TEST(G1Triangles, DimensionsOfTheNotesByBruteForceAndTheorem) {
  // Notes §9.1: T8 (crossing centre) 2k² − 2k + 4, T9 (moved centre) 2k² − 2k + 3.
  for (int k = 3; k <= 6; ++k) EXPECT_EQ(brute_force_dimension(t8(), k), 2 * k * k - 2 * k + 4) << "T8 k=" << k;
  for (int k = 4; k <= 6; ++k) EXPECT_EQ(brute_force_dimension(t9(), k), 2 * k * k - 2 * k + 3) << "T9 k=" << k;
  for (const Case& c : cases()) {
    const PatchMesh m = c.mesh();
    const G1Space s(share(m), c.k);
    const int brute = brute_force_dimension(m, c.k);
    EXPECT_EQ(s.dimension(), brute) << c.name << " k=" << c.k;
    EXPECT_EQ(theorem_dimension(m, s.gluing(), c.k), brute) << c.name << " k=" << c.k;
  }
  // Mixed square by hand (Theorem 6.3, tri–quad edges have d_τ = 2k): 2·4 + Σd 116 + 8 + 6 − 90 + 21.
  EXPECT_EQ(G1Space(share(mixed()), 5).dimension(), 69);
}

TEST(G1Triangles, RefusesDegreesBelowSeparabilityNamingTheSmallestThatWorks) {
  // Flat triangles with constant gluing are separable from k = 5 on (notes §9.3): below, the
  // local construction is incomplete although the global dimension formula may still hold. T8's
  // interior edges are all crossing at the centre, which makes k = 4 complete there (28, above).
  for (const auto& [mesh, k, works] : {std::tuple{t9(), 4, 5}, std::tuple{t9(), 3, 5}, std::tuple{t8(), 3, 4}}) {
    try {
      G1Space(share(mesh), k);
      FAIL() << mesh.name() << " accepted at k = " << k;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("use degree >= " + std::to_string(works)), std::string::npos) << e.what();
    }
  }
}

TEST(G1Triangles, LocalCountsPerEntity) {
  // Notes §3 / §8.1 per entity, k = 5 and 6.
  for (int k : {5, 6}) {
    // T8: centre 3 + 4 − 4 + 1 = 4 (crossing vertex), corners 5, interior edges 2k − 9 + 1 (crossing
    // at the centre), boundary edges 2k − 7, triangles C(k−4, 2).
    const PatchMesh m8 = t8();
    const G1Space s8(share(m8), k);
    const EntityCounts c8 = entity_counts(s8);
    const int centre = vertex_at(m8, P(1, 1));
    for (int v = 0; v < m8.num_vertices(); ++v) EXPECT_EQ(c8.vertex[v], v == centre ? 4 : 5) << "T8 vertex " << v;
    for (int e = 0; e < m8.num_edges(); ++e)
      EXPECT_EQ(c8.edge[e], m8.edge(e).boundary() ? 2 * k - 7 : 2 * k - 8) << "T8 edge " << e;
    for (int f = 0; f < 4; ++f) EXPECT_EQ(c8.face[f], (k - 4) * (k - 5) / 2);
    // T9: the centre is not crossing: 3 + 4 = 7, interior edges 2k − 9.
    const PatchMesh m9 = t9();
    const EntityCounts c9 = entity_counts(G1Space(share(m9), k));
    for (int v = 0; v < m9.num_vertices(); ++v)
      EXPECT_EQ(c9.vertex[v], v == vertex_at(m9, P(0.9, 1.2)) ? 7 : 5) << "T9 vertex " << v;
    for (int e = 0; e < m9.num_edges(); ++e)
      EXPECT_EQ(c9.edge[e], m9.edge(e).boundary() ? 2 * k - 7 : 2 * k - 9) << "T9 edge " << e;
  }
  // Mixed square, k = 5: E 7; corners where a quad and a triangle meet 5, corners of one quad 4;
  // the straight-boundary vertices (1, 0.5), (0, 0.5) 3 + 2 − 1 = 4. Interior (tri–quad) edges
  // 2k − 9 + c': 1, or 2 where they end on the straight boundary. Boundary edges 2k − 6 (quad),
  // 2k − 7 (triangle); faces (k − 3)² on quads, 0 on triangles.
  const PatchMesh m = mixed();
  const EntityCounts c = entity_counts(G1Space(share(m), 5));
  const std::vector<std::pair<P, int>> vertices{{P(0.55, 0.45), 7}, {P(0, 0), 5}, {P(1, 1), 5}, {P(1, 0), 4},
                                                {P(0, 1), 4},       {P(1, 0.5), 4}, {P(0, 0.5), 4}};
  for (const auto& [x, n] : vertices) EXPECT_EQ(c.vertex[vertex_at(m, x)], n) << x.transpose();
  for (int e = 0; e < m.num_edges(); ++e) {
    const MeshEdge& me = m.edge(e);
    const bool straight_end = std::abs(m.vertex(me.x).y() - 0.5) < 1e-14 || std::abs(m.vertex(me.y).y() - 0.5) < 1e-14;
    const int expected = !me.boundary() ? (straight_end ? 2 : 1) : m.shape(me.first.face) == CellShape::triangle ? 3 : 4;
    EXPECT_EQ(c.edge[e], expected) << "edge " << e;
  }
  for (int f = 0; f < m.num_faces(); ++f) EXPECT_EQ(c.face[f], m.shape(f) == CellShape::triangle ? 0 : 4);
}

TEST(G1Triangles, GluingDataDegreesAndCrossings) {
  // Triangle–triangle data are constant, triangle–quad data linear (notes §7.2); crossing exactly
  // where the two cross edges are collinear.
  const PatchMesh m8 = t8();
  const auto g8 = gluing_from_geometry(m8);
  const int centre = vertex_at(m8, P(1, 1));
  for (int e = 0; e < m8.num_edges(); ++e) {
    if (m8.edge(e).boundary()) continue;
    EXPECT_LT(g8[e].a.tail(2).norm() + g8[e].b.tail(2).norm() + g8[e].c.tail(2).norm(), 1e-14);
    EXPECT_TRUE(crossing_at(m8, g8, e, centre));
    EXPECT_FALSE(crossing_at(m8, g8, e, m8.edge(e).x == centre ? m8.edge(e).y : m8.edge(e).x));
    EXPECT_EQ(syzygy_dimension(g8[e], 5), 10);  // d_τ = 2k for flat triangles
  }
  const auto g9 = gluing_from_geometry(t9());
  for (const EdgeGluing& g : g9) EXPECT_FALSE(g.crossing_x || g.crossing_y);
  const PatchMesh mm = mixed();
  const auto gm = gluing_from_geometry(mm);
  int crossings = 0;
  for (int e = 0; e < mm.num_edges(); ++e) {
    if (mm.edge(e).boundary()) continue;
    EXPECT_NE(gm[e].triangle1, gm[e].triangle2);
    EXPECT_LT(std::abs(gm[e].a[2]) + std::abs(gm[e].b[2]) + std::abs(gm[e].c[2]), 1e-14);
    EXPECT_GT(std::max({std::abs(gm[e].a[1]), std::abs(gm[e].b[1]), std::abs(gm[e].c[1])}), 1e-3);  // not constant
    EXPECT_EQ(syzygy_dimension(gm[e], 5), 10);
    crossings += (gm[e].crossing_x ? 1 : 0) + (gm[e].crossing_y ? 1 : 0);
  }
  EXPECT_EQ(crossings, 2);  // at (1, 0.5) and (0, 0.5)
}

TEST(G1Triangles, EveryBasisFunctionSatisfiesTheG1RowsAndIsPhysicallyC1) {
  for (const Case& c : cases()) expect_c1(G1Space(share(c.mesh()), c.k), c.name + " k=" + std::to_string(c.k));
}

TEST(G1Triangles, LinearlyIndependentPartitionOfUnityAndReproduction) {
  for (const Case& c : cases()) {
    const G1Space s(share(c.mesh()), c.k);
    const std::string name = c.name + " k=" + std::to_string(c.k);
    expect_linearly_independent(s, name);
    expect_partition_of_unity(s, name);
    expect_reproduces_degree_k(s, name);
  }
}

TEST(G1Triangles, BoundaryAdaptedFunctionsSpanTheDirichletAndClampedSubspaces) {
  // The basis functions vanishing on the boundary (to first order) are as many as the brute-force
  // Dirichlet (clamped) subspaces: the generic boundary projection only touches the others.
  for (const Case& c : cases()) {
    if (c.name == "4t_star level 1") continue;  // the mixed level 1 covers refined meshes (and costs less)
    const PatchMesh m = c.mesh();
    const G1Space s(share(m), c.k);
    const auto [dirichlet, clamped] = boundary_subspace_counts(s);
    EXPECT_EQ(dirichlet, brute_force_dimension(m, c.k, 1)) << c.name;
    EXPECT_EQ(clamped, brute_force_dimension(m, c.k, 2)) << c.name;
    EXPECT_GT(clamped, 0) << c.name;
  }
  // T8 at k = 5 by hand: every corner coefficient of a boundary vertex lies in rows 0–1 of a
  // boundary edge, so only interior entities are clamped: centre 4 + interior edges 4 · 2 = 12.
  EXPECT_EQ(boundary_subspace_counts(G1Space(share(t8()), 5)).second, 12);
}

TEST(G1Triangles, MeshValidationNamesTheTriangle) {
  auto message = [](std::vector<Point2> v, std::vector<std::vector<int>> f) {
    try {
      PatchMesh(std::move(v), std::move(f), "tri");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message({{0, 0}, {1, 0}, {0, 1}, {1, 1}}, {{1, 3, 2}, {0, 2, 1}}).find("tri: patch 1 is inverted"),
            std::string::npos);
  EXPECT_NE(message({{0, 0}, {1, 0}, {2, 0}}, {{0, 1, 2}}).find("patch 0 is degenerate"), std::string::npos);
  EXPECT_NE(message({{0, 0}, {1, 0}, {2, 1}, {1, 2}, {0, 1}}, {{0, 1, 2, 3, 4}}).find("patch 0 has 5 corners"),
            std::string::npos);
}

TEST(G1Triangles, RefinementSplitsTrianglesIntoFourWithTheSameGeometry) {
  const PatchMesh m = mixed();
  const PatchMesh r = m.refined();
  EXPECT_EQ(r.num_faces(), 4 * m.num_faces());
  double area = 0.0;
  for (int f = 0; f < r.num_faces(); ++f) {
    const QuadratureRule q = r.shape(f) == CellShape::triangle ? triangle_rule(2) : tensor_gauss(2);
    for (int i = 0; i < q.size(); ++i) area += q.weights[i] * r.map(f, q.points[i]).jacobian.determinant();
    EXPECT_EQ(r.num_corners(f), m.num_corners(f / 4));
  }
  EXPECT_NEAR(area, 1.0, 1e-14);
  // The corner child of a triangle maps its corners to the parent's corner and edge midpoints.
  const int tri = m.shape(1) == CellShape::triangle ? 1 : 0;
  ASSERT_EQ(m.shape(tri), CellShape::triangle);
  EXPECT_LT((r.map(4 * tri, P(1, 0)).x - m.map(tri, P(0.5, 0)).x).norm(), 1e-15);
  EXPECT_LT((r.map(4 * tri + 3, P(1.0 / 3, 1.0 / 3)).x - m.map(tri, P(1.0 / 3, 1.0 / 3)).x).norm(), 1e-15);
}

TEST(G1Triangles, GradientJumpOfTentIsExactAndOfDiscreteSolutionsRoundOff) {
  // Two triangles of the unit square meeting on the diagonal x + y = 1: u = 0 below, x + y − 1
  // above, gradient jump |(1, 1)| = √2 along the whole diagonal; the smooth x·y has none.
  const PatchMesh m = mesh_from_patches({{P(0, 0), P(1, 0), P(0, 1)}, {P(1, 0), P(1, 1), P(0, 1)}}, "two");
  const int k = 5;
  auto coefficients = [&](const std::function<double(P)>& fn) {
    std::vector<P> pts;
    for (int j = 0; j <= k; ++j)
      for (int i = 0; i + j <= k; ++i) pts.push_back(P(double(i) / k, double(j) / k));
    Eigen::MatrixXd b(pts.size(), pts.size());
    for (size_t p = 0; p < pts.size(); ++p) b.row(static_cast<Eigen::Index>(p)) = bernstein_jet(CellShape::triangle, k, pts[p]).row(0);
    std::vector<Eigen::VectorXd> out;
    for (int f = 0; f < 2; ++f) {
      Eigen::VectorXd v(pts.size());
      for (size_t p = 0; p < pts.size(); ++p) v[static_cast<Eigen::Index>(p)] = fn(m.map(f, pts[p]).x);
      out.push_back(b.partialPivLu().solve(v));
    }
    return out;
  };
  const double tent = max_gradient_jump(m, k, coefficients([](P x) { return std::max(0.0, x.x() + x.y() - 1.0); }));
  EXPECT_NEAR(tent, std::sqrt(2.0), 1e-12);
  EXPECT_LT(max_gradient_jump(m, k, coefficients([](P x) { return x.x() * x.y(); })), 1e-12);
  // A discrete clamped-plate solution on the triangle config's mesh (level 1): round-off.
  const std::string text =
      "problem: {pde: biharmonic, exact: \"(cos(2*pi*x)-1)*(cos(2*pi*y)-1)\", boundary: {all: clamped}}\n"
      "domain: {type: multipatch, name: 4t_star}\nspace: {type: g1, degree: 5}\n";
  const LevelResult r =
      solve_problem(*test::space_from_yaml(text, 1), test::problem_from_yaml(text), SolverKind::cholmod).result;
  ASSERT_TRUE(r.g1_jump.has_value());
  EXPECT_LT(*r.g1_jump, 1e-11);
}
