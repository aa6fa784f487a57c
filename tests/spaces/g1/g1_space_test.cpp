// The G1 space S¹_k on bilinear multipatch meshes (notes §9): dimensions against Theorem 6.3 and
// a brute-force null space of all C0 + G1 rows, local counts, physical C1 continuity of every
// basis function, linear independence, partition of unity and polynomial reproduction.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>

#include "config/errors.hpp"
#include "config/config_node.hpp"
#include "spaces/g1/g1_from_config.hpp"
#include "spaces/g1/g1_space.hpp"
#include "spaces/g1/multipatch_domains.hpp"
#include "tests/spaces/g1/g1_test_support.hpp"

using namespace iga;
using namespace iga::test;

namespace {

using P = Point2;

PatchMesh grid_mesh(const std::vector<P>& pts, const std::string& name) {
  // pts indexed i*3 + j for (i,j) in {0,1,2}^2, faces ((i,j),(i+1,j),(i+1,j+1),(i,j+1)).
  std::vector<PatchCorners> patches;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      patches.push_back({pts[i * 3 + j], pts[(i + 1) * 3 + j], pts[(i + 1) * 3 + j + 1], pts[i * 3 + j + 1]});
  return mesh_from_patches(patches, name);
}

PatchMesh star_mesh(const std::vector<P>& d, const std::vector<P>& e, const std::string& name) {
  std::vector<PatchCorners> patches;
  const int n = static_cast<int>(d.size());
  for (int i = 0; i < n; ++i) patches.push_back({P(0, 0), d[i], e[i], d[(i + 1) % n]});
  return mesh_from_patches(patches, name);
}

PatchMesh t3() {
  std::vector<P> p;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) p.push_back(P(i, j));
  return grid_mesh(p, "T3");
}
PatchMesh t4() {
  return grid_mesh({P(0, 0), P(0, 21.0 / 19), P(0, 2), P(1, 0), P(15.0 / 17, 17.0 / 19), P(18.0 / 17, 2), P(2, 0),
                    P(2, 20.0 / 19), P(2, 2)},
                   "T4");
}
PatchMesh t5() { return star_mesh({P(1, 0), P(-1, 1), P(0, -1)}, {P(0, 1), P(-1, 0), P(1, -1)}, "T5"); }
PatchMesh t6() {
  return star_mesh({P(1, 0), P(-1, 1), P(0, -1)}, {P(0.2, 1.2), P(-1.2, 0.1), P(1, -1.5)}, "T6");
}
PatchMesh t7() {
  return star_mesh({P(1, 0), P(0.3, 1), P(-0.8, 0.6), P(-0.8, -0.6), P(0.3, -1)},
                   {P(1.17, 0.9), P(-0.43, 499.0 / 350), P(-1.4, -1.0 / 35), P(-0.39, -519.0 / 350), P(1.25, -67.0 / 70)},
                   "T7");
}

struct Case {
  std::string name;
  std::function<PatchMesh()> mesh;
  int k;
  int expected;  ///< dimension from notes §9.1 (brute force, exact arithmetic); -1: not tabulated
};

std::vector<Case> cases() {
  return {
      {"T3", t3, 4, 64},
      {"T3", t3, 5, 100},
      {"T4", t4, 4, 59},  // every interface straight at one end: k = 4 suffices (notes §0, §9.2)
      {"T4", t4, 5, 95},
      {"T5", t5, 5, 75},
      {"T6", t6, 5, 72},
      {"T6", t6, 6, 105},
      {"T7", t7, 5, 118},
      {"3p_square", [] { return multipatch_domain("3p_square"); }, 5, -1},
      {"5p_square", [] { return multipatch_domain("5p_square"); }, 5, -1},
      {"pentagon", [] { return multipatch_domain("pentagon"); }, 4, 73},  // 5k² - 7 as T7
      {"pentagon", [] { return multipatch_domain("pentagon"); }, 5, -1},
      {"3p_square level 1", [] { return multipatch_domain("3p_square").refined(); }, 5, -1},
      {"5p_pentagon", [] { return multipatch_domain("5p_pentagon"); }, 5, -1},
      {"3p_hexagon", [] { return multipatch_domain("3p_hexagon"); }, 5, 75},  // parallelograms: 3k² as T5
      {"lshape_8p", [] { return multipatch_domain("lshape_8p"); }, 5, -1},
  };
}

}  // namespace

TEST(G1Space, DimensionMatchesTheoremAndBruteForce) {
  for (const Case& c : cases()) {
    const PatchMesh m = c.mesh();
    const G1Space s(std::make_shared<const PatchMesh>(m), c.k);
    const int brute = brute_force_dimension(m, c.k);
    EXPECT_EQ(s.dimension(), brute) << c.name << " k=" << c.k;
    EXPECT_EQ(theorem_dimension(m, s.gluing(), c.k), brute) << c.name << " k=" << c.k;
    if (c.expected > 0) EXPECT_EQ(brute, c.expected) << c.name << " k=" << c.k;
  }
}

TEST(G1Space, BenchmarkDomainDimensions) {
  // Generic bilinear data everywhere (d_τ = 2k), no crossing vertex: Theorem 6.3 by hand.
  // 3p_square, k = 5: 3*4 + 3*10 + 6*13 + 12 - 81 + 21 = 72 (= 3k² - 3, like T6).
  EXPECT_EQ(G1Space(std::make_shared<const PatchMesh>(multipatch_domain("3p_square")), 5).dimension(), 72);
  // pentagon, k = 5: 5*4 + 5*10 + 10*13 + 20 - 9*15 + 3*11 = 118 (= 5k² - 7, like T7).
  EXPECT_EQ(G1Space(std::make_shared<const PatchMesh>(multipatch_domain("pentagon")), 5).dimension(), 118);
}

TEST(G1Space, LocalCountsPerEntity) {
  // T7 at k = 5 (notes §9.2): centre 8, boundary d_i 5, e_i 4, interior edges 1, boundary edges 4.
  const PatchMesh m = t7();
  const G1Space s(std::make_shared<const PatchMesh>(m), 5);
  std::vector<int> per_vertex(m.num_vertices(), 0), per_edge(m.num_edges(), 0);
  int faces = 0;
  for (const G1FunctionInfo& i : s.basis().info) {
    if (i.entity == G1Entity::vertex) ++per_vertex[i.id];
    if (i.entity == G1Entity::edge) ++per_edge[i.id];
    if (i.entity == G1Entity::face) ++faces;
  }
  EXPECT_EQ(faces, 5 * 4);
  for (int v = 0; v < m.num_vertices(); ++v) {
    const VertexFan& fan = m.fan(v);
    const int expected = !fan.boundary ? 8 : (fan.face.size() == 2 ? 5 : 4);
    EXPECT_EQ(per_vertex[v], expected) << "vertex " << v;
  }
  for (int e = 0; e < m.num_edges(); ++e) EXPECT_EQ(per_edge[e], m.edge(e).boundary() ? 4 : 1) << "edge " << e;
}

TEST(G1Space, RefusesDegreesBelowSeparabilityNamingTheSmallestThatWorks) {
  // T5 at k = 4: the local construction gives 45 of 48 (notes §9.2); T6 likewise 42 of 45.
  for (auto mesh : {t5(), t6()}) {
    try {
      G1Space(std::make_shared<const PatchMesh>(mesh), 4);
      FAIL() << mesh.name() << " accepted at k = 4";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("use degree >= 5"), std::string::npos) << e.what();
    }
  }
  // The straight 2x2 grid is fine at k = 4 (all edges crossing).
  EXPECT_EQ(G1Space(std::make_shared<const PatchMesh>(t3()), 4).dimension(), 64);
}

TEST(G1Space, DegreeThreeOnQuadrilateralsIsAnInputErrorNamingTheKey) {
  // At k = 3 the 2x2 corner coefficient sets fill both rows along every quadrilateral edge, so no
  // edge coefficient is left (this used to run an SVD of an empty matrix and crash).
  for (auto mesh : {t3(), t5(), t6()}) {
    try {
      G1Space(std::make_shared<const PatchMesh>(mesh), 3);
      FAIL() << mesh.name() << " accepted at k = 3";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("quadrilaterals needs degree >= 4"), std::string::npos) << m;
      EXPECT_NE(m.find("use degree >= "), std::string::npos) << m;
    }
  }
  const ConfigNode root = ConfigNode::load_string(
      "domain: {type: multipatch, name: 3p_square}\nspace: {type: g1, degree: 3}\n", "run.yaml");
  try {
    make_g1_space(root["domain"], root["space"], 0);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("run.yaml:2:27: space.degree: G1 space of degree 3", 0), 0u) << e.what();
  }
}

TEST(G1Space, EveryBasisFunctionIsC1AcrossInterfaces) {
  for (const Case& c : cases())
    expect_c1(G1Space(std::make_shared<const PatchMesh>(c.mesh()), c.k), c.name + " k=" + std::to_string(c.k));
}

TEST(G1Space, LinearlyIndependent) {
  for (const Case& c : cases())
    expect_linearly_independent(G1Space(std::make_shared<const PatchMesh>(c.mesh()), c.k),
                                c.name + " k=" + std::to_string(c.k));
}

TEST(G1Space, PartitionOfUnityThroughVertexValueFunctions) {
  for (const Case& c : cases())
    expect_partition_of_unity(G1Space(std::make_shared<const PatchMesh>(c.mesh()), c.k), c.name);
}

TEST(G1Space, ReproducesPolynomialsUpToDegreeK) {
  for (const Case& c : cases())
    expect_reproduces_degree_k(G1Space(std::make_shared<const PatchMesh>(c.mesh()), c.k), c.name);
}

TEST(G1Space, BoundaryAdaptedVertexFunctionsGiveTheBoundarySubspaces) {
  // Functions vanishing on the boundary (row 0 of every boundary edge) and vanishing to first
  // order (rows 0 and 1): their counts are the dimensions of the Dirichlet and clamped subspaces
  // (notes §9.4; pentagon from g1-routeA-evidence: 38 and 228 clamped DOFs at levels 0 and 1).
  struct Expect {
    std::string name;
    std::function<PatchMesh()> mesh;
    int dirichlet, clamped;
  };
  const std::vector<Expect> list{
      {"T3", t3, 64, 36},
      {"T4", t4, 59, 31},
      {"T5", t5, 45, 24},
      {"T6", t6, 42, 21},
      {"T7", t7, 68, 33},
      {"pentagon", [] { return multipatch_domain("pentagon"); }, -1, 38},
      {"pentagon level 1", [] { return multipatch_domain("pentagon").refined(); }, -1, 228},
  };
  for (const Expect& c : list) {
    const G1Space s(std::make_shared<const PatchMesh>(c.mesh()), 5);
    const auto [dirichlet, clamped] = boundary_subspace_counts(s);
    if (c.dirichlet >= 0) EXPECT_EQ(dirichlet, c.dirichlet) << c.name;
    EXPECT_EQ(clamped, c.clamped) << c.name;
  }
}

TEST(G1Space, PhysicalDerivativesMatchFiniteDifferencesOnBilinearPatches) {
  // Central differences along reference directions through the (non-affine) bilinear maps:
  // F(x+) - F(x-) = ∇F·(x+ - x-) and ∇F(x+) - ∇F(x-) = D²F (x+ - x-), both up to O(δ³).
  const G1Space s(std::make_shared<const PatchMesh>(multipatch_domain("3p_square")), 5);
  auto ev = s.make_evaluator();
  const double delta = 1e-4;
  double worst_grad = 0.0, worst_hess = 0.0;
  for (int f = 0; f < s.num_elements(); ++f)
    for (int dir = 0; dir < 2; ++dir) {
      const P xi(0.37, 0.61), step = dir == 0 ? P(delta, 0) : P(0, delta);
      QuadratureRule r;
      r.points = {xi, xi + step, xi - step};
      r.weights = {1, 1, 1};
      PointValues v;
      ev->evaluate(f, r, update_values | update_gradients | update_hessians, v);
      const Eigen::Vector2d dx = v.x.col(1) - v.x.col(2);
      for (int i = 0; i < v.num_functions(); ++i) {
        const double scale_g = std::abs(v.dx(i, 0)) + std::abs(v.dy(i, 0)) + 1.0;
        const double df = v.value(i, 1) - v.value(i, 2);
        worst_grad = std::max(worst_grad, std::abs(df - (v.dx(i, 0) * dx.x() + v.dy(i, 0) * dx.y())) / (scale_g * dx.norm()));
        const double gx = v.dx(i, 1) - v.dx(i, 2), gy = v.dy(i, 1) - v.dy(i, 2);
        const double hx = v.dxx(i, 0) * dx.x() + v.dxy(i, 0) * dx.y(), hy = v.dxy(i, 0) * dx.x() + v.dyy(i, 0) * dx.y();
        const double scale_h = std::abs(v.dxx(i, 0)) + std::abs(v.dxy(i, 0)) + std::abs(v.dyy(i, 0)) + 1.0;
        worst_hess = std::max(worst_hess, std::hypot(gx - hx, gy - hy) / (scale_h * dx.norm()));
      }
    }
  EXPECT_LT(worst_grad, 1e-6);
  EXPECT_LT(worst_hess, 1e-6);
  EXPECT_GT(worst_hess, 0.0);  // the differences were computed
}
