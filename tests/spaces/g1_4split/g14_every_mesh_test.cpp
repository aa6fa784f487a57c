// The default gluing `lines` (spaces/g1_4split/line_gluing.hpp) on meshes where per-edge linear data
// are refused: a fan split once before use has interior crossing vertices between the centre and
// the boundary, where linear data have different slopes on opposite edges (the twist condition
// fails). Lines gluing passes it, keeps every piece linear (nested sub-edges stay linear), its
// dimension is the brute-force null space and the formula, and the clamped plate converges at the
// optimal rates k + 1 / k / k − 1 (q1 loses half an order there).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>

#include "config/config_node.hpp"
#include "mesh/read_quad_surface_mesh.hpp"
#include "spaces/g1/g1_from_config.hpp"
#include "spaces/g1_4split/fan_values.hpp"
#include "spaces/g1_4split/g1_4split_basis.hpp"
#include "spaces/g1_4split/g1_4split_meshes.hpp"
#include "spaces/g1_4split/g1_4split_space.hpp"
#include "spaces/g1_4split/line_gluing.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {

int brute_force(const QuadTopology& t, const std::vector<SplitGluing>& g, int k) {
  return nullspace_dimension(Eigen::MatrixXd(global_constraints(t, g, SplitBSpline(k, 1))));
}

/// Largest |second derivative| of a(t) over both halves of every interior edge: 0 means every piece
/// is linear, so sub-edges of nested refinements carry linear data.
double largest_curvature(const QuadTopology& t, const std::vector<SplitGluing>& g) {
  double worst = 0.0;
  for (int e = 0; e < t.num_edges(); ++e)
    if (!t.edge(e).boundary())
      for (int h = 0; h < 2; ++h)
        for (double x : {0.0, 0.25, 0.5})
          worst = std::max(worst, std::abs(g[e].eval(0.5 * h + x, 2, h)));
  return worst;
}

}  // namespace

TEST(G14EveryMesh, SplitFansLinearBreaksTheTwistConditionLinesKeepIt) {
  for (const char* name : {"fan3s", "fan5s", "fan6s"}) {
    const PatchMesh mesh = g14_domain(name);
    const QuadTopology t = quad_topology(mesh);
    const auto angles = vertex_angles(mesh);
    // A spoke midpoint sees the centre's slope on one side and the boundary's on the other.
    EXPECT_GE(twist_incompatible_vertex(t, symmetric_gluing(t, Blending::linear, angles)), 0) << name;
    const auto g = symmetric_gluing(t, Blending::lines, angles);
    EXPECT_EQ(twist_incompatible_vertex(t, g), -1) << name;
    EXPECT_EQ(largest_curvature(t, g), 0.0) << name;
    // The spoke C–M–O is one line: a goes linearly from A(C) through M to 0 at the straight
    // boundary point O, so M carries A(C)/2 on it.
    const double A = std::abs(vertex_gluing_value(name[3] - '0', false));
    int carrying = 0;
    for (int v = 0; v < t.num_vertices(); ++v)
      if (!t.vertex_on_boundary(v) && t.vertex_faces(v) == 4)
        for (int e : t.vertex_edges(v))
          if (std::abs(std::abs(g[e].eval(t.edge(e).g0 == v ? 0.0 : 1.0)) - A / 2) < 1e-14) ++carrying;
    EXPECT_EQ(carrying, 2 * (name[3] - '0')) << name;  // both halves of each spoke, at the midpoint
  }
}

TEST(G14EveryMesh, DimensionIsTheBruteForceNullSpace) {
  // fan3s at k = 4 (768 coefficients): local basis = brute-force null space = the note's formula
  // (k = 5 on every mesh of docs/spaces/g1_4split.md: 858 on fan3s). Nested: the refined gluing
  // is twist-compatible and the local basis is still separable at k = 4.
  const PatchMesh mesh = g14_domain("fan3s");
  const QuadTopology t = quad_topology(mesh);
  const auto g = symmetric_gluing(t, Blending::lines, vertex_angles(mesh));
  const int brute = brute_force(t, g, 4);
  EXPECT_EQ(g14_dimension_formula(t, g, 4, 1), brute);
  EXPECT_EQ(build_g14_basis(t, g, 4, 1).dimension(), brute);
  const QuadTopology fine = t.refined();
  const auto gf = inherited_gluing(t, g, fine);
  EXPECT_EQ(twist_incompatible_vertex(fine, gf), -1);
  EXPECT_EQ(build_g14_basis(fine, gf, 4, 1).dimension(), g14_dimension_formula(fine, gf, 4, 1));
}

/// 3 × 3 quads on [0, 3]² with the 8 boundary points between the corners pushed out by 0.15: a
/// boundary vertex with 2 faces and an angle α < π has A = 2cos(α/2) > 0, so both lines through
/// every interior (valence-4) vertex are non-zero there when linear — two at one vertex.
PatchMesh bumpy_grid() {
  std::vector<Point2> v;
  for (int j = 0; j <= 3; ++j)
    for (int i = 0; i <= 3; ++i) {
      Point2 p(i, j);
      const bool corner = (i == 0 || i == 3) && (j == 0 || j == 3);
      if (!corner) {
        if (i == 0) p.x() -= 0.15;
        if (i == 3) p.x() += 0.15;
        if (j == 0) p.y() -= 0.15;
        if (j == 3) p.y() += 0.15;
      }
      v.push_back(p);
    }
  std::vector<std::vector<int>> faces;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) faces.push_back({4 * j + i, 4 * j + i + 1, 4 * (j + 1) + i + 1, 4 * (j + 1) + i});
  return PatchMesh(v, faces, "bumpy_grid");
}

TEST(G14EveryMesh, ClosedSurfaceFilesDimensionIsTheBruteForceNullSpace) {
  // The closed surfaces of docs/spaces/g1_4split.md's table, default gluing, level 0 (k = 5 in the
  // docs: 626, 2 048 and the cube's 384; lower here to keep the dense null space cheap). The torus 8 x 4 has only
  // crossing vertices and closed mesh lines, so a = 0 on every edge and its space is the tensor
  // product of periodic C1 splines of degree k: 16 spans around times 8 across, (k - 1) functions
  // per span, 128 (k - 1)^2.
  struct Case {
    const char* file;
    int k;
  };
  for (const Case c : {Case{"g14_torus_8x4.obj", 3}, Case{"g14_trapezohedron.obj", 4}}) {
    const QuadSurfaceFile read = read_quad_surface_mesh(std::string(IGA_SOURCE_DIR) + "/configs/domains/" + c.file);
    const QuadTopology t(static_cast<int>(read.points.size()), read.quads, c.file);
    const auto g = symmetric_gluing(t, Blending::lines);
    EXPECT_EQ(twist_incompatible_vertex(t, g), -1) << c.file;
    EXPECT_EQ(largest_curvature(t, g), 0.0) << c.file;
    const int brute = brute_force(t, g, c.k);
    EXPECT_EQ(g14_dimension_formula(t, g, c.k, 1), brute) << c.file;
    EXPECT_EQ(build_g14_basis(t, g, c.k, 1).dimension(), brute) << c.file;
    if (std::string(c.file) == "g14_torus_8x4.obj") EXPECT_EQ(brute, 128 * (c.k - 1) * (c.k - 1));
  }
  const QuadTopology cube = cube_topology();  // 8 vertices of valence 3
  const auto g = symmetric_gluing(cube, Blending::lines);
  const int brute = brute_force(cube, g, 4);
  EXPECT_EQ(g14_dimension_formula(cube, g, 4, 1), brute);
  EXPECT_EQ(build_g14_basis(cube, g, 4, 1).dimension(), brute);
}

TEST(G14EveryMesh, ZigzagLinesResolveTwoNonZeroLinesAtOneVertex) {
  const PatchMesh mesh = bumpy_grid();
  const QuadTopology t = quad_topology(mesh);
  const std::vector<double> A = symmetric_vertex_values(t, vertex_angles(mesh));
  EXPECT_GT(A[1], 0.1);  // a bumped boundary point
  LineGluingReport report;
  const auto g = line_gluing(t, A, &report);
  EXPECT_EQ(report.lines, 4);         // 2 horizontal, 2 vertical
  EXPECT_GE(report.zigzag_lines, 1);  // the 4 conflicts need at least one zigzag line
  EXPECT_EQ(twist_incompatible_vertex(t, g), -1);
  EXPECT_EQ(largest_curvature(t, g), 0.0);
  const int brute = brute_force(t, g, 4);
  EXPECT_EQ(g14_dimension_formula(t, g, 4, 1), brute);
  EXPECT_EQ(build_g14_basis(t, g, 4, 1).dimension(), brute);
  const QuadTopology fine = t.refined();
  const auto gf = inherited_gluing(t, g, fine);
  EXPECT_EQ(twist_incompatible_vertex(fine, gf), -1);
  EXPECT_EQ(build_g14_basis(fine, gf, 4, 1).dimension(), g14_dimension_formula(fine, gf, 4, 1));
}

TEST(G14EveryMesh, GmshRecombinationDimensionIsTheBruteForceNullSpace) {
  // The Gmsh row of docs/spaces/g1_4split.md (configs/domains/g1_pentagon_quads.geo at mesh size
  // 0.8, recombined: 13 quads, interior valence 3 and 4), default planar gluing, level 0, k = 4
  // (the docs' 910 is k = 5).
  const PatchMesh mesh = patch_mesh_from_config(ConfigNode::load_string(
      "{type: mesh_file, file: " + std::string(IGA_SOURCE_DIR) +
          "/configs/domains/g1_pentagon_quads.geo, mesh_size: 0.8, recombine: true}",
      "test.yaml"));
  const QuadTopology t = quad_topology(mesh);
  ASSERT_EQ(t.num_faces(), 13);
  const auto g = planar_line_gluing(mesh, t);
  EXPECT_EQ(twist_incompatible_vertex(t, g), -1);
  EXPECT_EQ(largest_curvature(t, g), 0.0);
  const int brute = brute_force(t, g, 4);
  EXPECT_EQ(g14_dimension_formula(t, g, 4, 1), brute);
  EXPECT_EQ(build_g14_basis(t, g, 4, 1).dimension(), brute);
}

TEST(G14EveryMesh, MeshFanValuesRegularFansAreSymmetric) {
  // Odd valence: the equal-area fan is unique, any 3-fan is an affine image of the regular one
  // (a = −1); on the regular fans the values are 2cos(2π/n).
  for (const char* name : {"fan3", "fan5", "fan6"}) {
    const PatchMesh mesh = g14_domain(name);
    const QuadTopology t = quad_topology(mesh);
    const auto fan = fan_gluing_values(mesh, t);
    const double A = vertex_gluing_value(name[3] - '0', false);
    ASSERT_EQ(fan[0].size(), static_cast<std::size_t>(name[3] - '0')) << name;  // the centre
    for (const auto& [e, x] : fan[0]) EXPECT_NEAR(x, A, 1e-13) << name;
  }
}

TEST(G14EveryMesh, PlanarDefaultGluingDimensionAndTwist) {
  // The default gluing of a planar mesh (mesh fans, linear per edge, chains through crossings):
  // Condition 1 holds at every vertex (the dimension is the brute-force null space and the
  // formula, which counts H(γ) from Condition 1), the twist condition at every crossing, every
  // piece linear; on the split fans it is the symmetric lines gluing (the bilinear map is in it).
  const PatchMesh grid = bumpy_grid();
  for (const PatchMesh& mesh : {g14_domain("fan3s"), g14_domain("fan5s"), g14_domain("fan6s"), grid}) {
    const QuadTopology t = quad_topology(mesh);
    LineGluingReport report;
    const auto g = planar_line_gluing(mesh, t, &report);
    EXPECT_TRUE(report.mesh_fans) << mesh.name();
    EXPECT_EQ(twist_incompatible_vertex(t, g), -1) << mesh.name();
    EXPECT_EQ(largest_curvature(t, g), 0.0) << mesh.name();
    const int brute = brute_force(t, g, 4);
    EXPECT_EQ(g14_dimension_formula(t, g, 4, 1), brute) << mesh.name();
    EXPECT_EQ(build_g14_basis(t, g, 4, 1).dimension(), brute) << mesh.name();
  }
  const PatchMesh split = g14_domain("fan3s");
  const QuadTopology t = quad_topology(split);
  const auto fans = planar_line_gluing(split, t);
  const auto lines = symmetric_gluing(t, Blending::lines, vertex_angles(split));
  for (int e = 0; e < t.num_edges(); ++e)
    if (!t.edge(e).boundary())
      for (double x : {0.0, 0.5, 1.0}) EXPECT_NEAR(fans[e].eval(x), lines[e].eval(x), 1e-12) << e;
}

TEST(G14EveryMesh, SplitHexagonPlateOptimalRates) {
  // Clamped plate, k = 5, levels 0..2 on the hexagon split once (DOFs 1 626 / 6 246 / 24 486): the
  // rates of levels 1 → 2 are within 0.35 of 6 / 5 / 4 (H2: q1 gives 3.4 here, its traces along the
  // spokes have degree k − 1 = 4: rate k − 3/2).
  const test::Rates r = test::last_rates(
      "problem: {pde: biharmonic, exact: \"sin(2*x+0.3)*cos(3*y)\", boundary: {all: clamped}}\n"
      "domain: {type: multipatch, name: fan6s}\nspace: {type: g1_4split, degree: 5}\n",
      3);
  EXPECT_GT(r.h2, 3.7);
  EXPECT_GT(r.h1, 4.7);
  EXPECT_GT(r.l2, 5.5);
}

namespace {

PatchMesh mesh_file(const std::string& domain) {
  return patch_mesh_from_config(ConfigNode::load_string("{type: mesh_file, file: " + std::string(IGA_SOURCE_DIR) +
                                                            "/configs/domains/" + domain + "}",
                                                        "test.yaml"));
}

}  // namespace

TEST(G14EveryMesh, FairDefaultGluingIsSymmetricLinesWithTheBruteForceDimension) {
  // With the fair map (the default fit) the planar default gluing takes the vertex values whose
  // fair map spreads the faces' area more evenly (docs/spaces/g1_4split.md, "Which gluing
  // values"): on the Gmsh recombination and on the two 3 × 3 grids of the docs the symmetric ones
  // (lines gluing); its dimension is the brute-force null space and the formula (k = 4, level 0),
  // the twist condition holds and every piece of a(t) is linear.
  G14Options o;
  o.degree = 4;
  for (const char* domain : {"g1_pentagon_quads.geo, mesh_size: 0.8, recombine: true", "g14_grid3_moved.obj",
                             "g14_grid3_bumped.obj"}) {
    const PatchMesh mesh = mesh_file(domain);
    const G14Space s(mesh, o);
    const QuadTopology& t = s.topology();
    const auto lines = line_gluing(t, symmetric_vertex_values(t, vertex_angles(mesh)));
    for (int e = 0; e < t.num_edges(); ++e)
      if (!t.edge(e).boundary())
        for (double x : {0.0, 0.25, 0.5, 0.75, 1.0}) EXPECT_EQ(s.gluing()[e].eval(x), lines[e].eval(x)) << domain;
    EXPECT_EQ(twist_incompatible_vertex(t, s.gluing()), -1) << domain;
    EXPECT_EQ(largest_curvature(t, s.gluing()), 0.0) << domain;
    const int brute = brute_force(t, s.gluing(), 4);
    EXPECT_EQ(g14_dimension_formula(t, s.gluing(), 4, 1), brute) << domain;
    EXPECT_EQ(s.dimension(), brute) << domain;
  }
}

TEST(G14EveryMesh, MovedGridPlateNearTheG1SpaceAtEqualDofs) {
  // configs/domains/g14_grid3_moved.obj (straight boundary, the 4 inner points moved): every
  // boundary vertex is straight, so the symmetric lines gluing is a ≡ 0 and the fair map only
  // has to make det J continuous. Clamped plate, k = 5, H2 at equal DOFs (the 4-split level l
  // against g1 level l + 1): measured 10.7× at level 0 (676 / 636 DOFs), 33–41× with the
  // mesh-fan values the default used before (docs/spaces/g1_4split.md).
  const std::string plate =
      "problem: {pde: biharmonic, exact: \"sin(2*x+0.3)*cos(3*y)\", boundary: {all: clamped}}\n"
      "domain: {type: mesh_file, file: " +
      std::string(IGA_SOURCE_DIR) + "/configs/domains/g14_grid3_moved.obj}\n";
  const LevelResult split = test::level_result(plate + "space: {type: g1_4split, degree: 5}\n", 0);
  const LevelResult g1 = test::level_result(plate + "space: {type: g1, degree: 5}\n", 1);
  std::printf("H2: g1_4split %.3e (%d DOFs), g1 %.3e (%d DOFs)\n", *split.h2, split.dofs, *g1.h2, g1.dofs);
  EXPECT_LT(*split.h2, 12.0 * *g1.h2);
}

TEST(G14EveryMesh, FairDefaultTakesTheVertexValuesWithTheEvenerJacobian) {
  // Of the two fair maps (mesh fans, symmetric values) the one with the smaller largest
  // det J ratio inside a face is taken, said in the facts: on `5p_square` the fans (3.16 against
  // 16.8; the plate's H2 at level 1 1.26e-4 against 1.31e-3 with the symmetric values), on the
  // moved 3 × 3 grid the symmetric values (2.20 against 2.41; 4.8e-6 against 1.7e-5 at level 2),
  // on the split hexagon, where both maps are the bilinear one, the fans.
  struct Case {
    std::string domain, values;
  };
  for (const Case& c : {Case{"{type: multipatch, name: 5p_square}", "mesh fans ("},
                        Case{"{type: mesh_file, file: " + std::string(IGA_SOURCE_DIR) +
                                 "/configs/domains/g14_grid3_moved.obj}",
                             "symmetric ("},
                        Case{"{type: multipatch, name: fan6s}", "mesh fans ("}}) {
    const SpacePtr s = test::space_from_yaml("domain: " + c.domain + "\nspace: {type: g1_4split, degree: 5}\n");
    std::string values;
    for (const auto& [key, value] : s->facts().parameters)
      if (key == "gluing_values") values = value;
    EXPECT_EQ(values.substr(0, c.values.size()), c.values) << c.domain << ": " << values;
  }
}
