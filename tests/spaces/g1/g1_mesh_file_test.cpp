// G1 spaces on meshes read from files (mesh/): the shipped OBJ mesh (quads and
// triangles around a valence-5 vertex) and Gmsh .geo meshes (recombined quads, plain triangles),
// dimensions against Theorem 6.3 and the brute-force null space, a patch test through a config,
// and bad meshes rejected with messages naming the file, the cell and the config place.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/spaces/g1/g1_test_support.hpp"
#include "config/errors.hpp"
#include "spaces/g1/patch_mesh_from_file.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {

const std::string kDomains = std::string(IGA_SOURCE_DIR) + "/configs/domains/";

std::string write_temp(const std::string& name, const std::string& text) { return test::scratch_file(name, text); }

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

std::string yaml_for(const std::string& domain, int k = 5) {
  return "domain: " + domain + "\nspace: {type: g1, degree: " + std::to_string(k) + "}\n";
}

}  // namespace

TEST(G1MeshFile, ShippedObjMeshMixesQuadsAndTrianglesAroundAValence5Vertex) {
  const PatchMesh m = patch_mesh_from_file(kDomains + "g1_valence5_plate.obj", {});
  ASSERT_EQ(m.num_faces(), 5);
  int triangles = 0, interior_valence5 = 0;
  for (int f = 0; f < m.num_faces(); ++f) triangles += m.shape(f) == CellShape::triangle ? 1 : 0;
  for (int v = 0; v < m.num_vertices(); ++v) interior_valence5 += !m.fan(v).boundary && m.fan(v).valence() == 5;
  EXPECT_EQ(triangles, 2);
  EXPECT_EQ(interior_valence5, 1);
  const G1Space s(std::make_shared<const PatchMesh>(m), 5);
  EXPECT_EQ(s.dimension(), test::brute_force_dimension(m, 5));
  EXPECT_EQ(s.dimension(), theorem_dimension(m, s.gluing(), 5));
  test::expect_c1(s, "g1_valence5_plate.obj");
  test::expect_reproduces_degree_k(s, "g1_valence5_plate.obj");
}

TEST(G1MeshFile, GmshRecombinedQuadsAndPlainTriangles) {
  // The shipped .geo at h = 0.8: 13 bilinear quads with recombine, triangles without.
  const PatchMesh quads = patch_mesh_from_file(kDomains + "g1_pentagon_quads.geo", {0.8, true});
  EXPECT_EQ(quads.num_faces(), 13);
  EXPECT_FALSE(quads.has_triangles());
  const G1Space sq(std::make_shared<const PatchMesh>(quads), 5);
  EXPECT_EQ(sq.dimension(), test::brute_force_dimension(quads, 5));
  EXPECT_EQ(sq.dimension(), theorem_dimension(quads, sq.gluing(), 5));
  const PatchMesh tris = patch_mesh_from_file(kDomains + "g1_pentagon_quads.geo", {0.8, false});
  for (int f = 0; f < tris.num_faces(); ++f) EXPECT_EQ(tris.shape(f), CellShape::triangle);
  const G1Space st(std::make_shared<const PatchMesh>(tris), 5);
  EXPECT_EQ(st.dimension(), test::brute_force_dimension(tris, 5));
  // Morgan–Scott (notes §3): ½(k+2)(k+1) F_Δ − (2k+1) F₁° + 3 F₀° + F₊ with no crossing vertex.
  int interior_edges = 0, interior_vertices = 0;
  for (int e = 0; e < tris.num_edges(); ++e) interior_edges += tris.edge(e).boundary() ? 0 : 1;
  for (int v = 0; v < tris.num_vertices(); ++v) interior_vertices += tris.fan(v).boundary ? 0 : 1;
  EXPECT_EQ(st.dimension(), 21 * tris.num_faces() - 11 * interior_edges + 3 * interior_vertices);
}

TEST(G1MeshFile, ConfigSolvesOnTheObjMeshWithPathsRelativeToTheConfig) {
  // The config sits next to configs/domains/: a relative path resolves from its folder.
  const std::string config = std::string(IGA_SOURCE_DIR) + "/configs/g1-biharmonic-obj.yaml";
  const ConfigNode root = ConfigNode::load_file(config);
  const SpacePtr s = make_space(root["domain"], root["space"], 1);
  EXPECT_EQ(s->num_elements(), 20);
  // Patch test: a polynomial of degree 5 is reproduced by the clamped plate solve.
  const std::string text = yaml_for("{type: mesh_file, file: " + kDomains + "g1_valence5_plate.obj}") +
                           "problem: {pde: biharmonic, exact: \"x^3*y^2 - x^5 + y^5 + x*y\", boundary: {all: clamped}}\n";
  const LevelResult r =
      solve_problem(*test::space_from_yaml(text, 1), test::problem_from_yaml(text), SolverKind::cholmod).result;
  EXPECT_LT(*r.l2, 1e-10);
  EXPECT_LT(*r.h2, 1e-8);
}

TEST(G1MeshFile, BadMeshesAreRejectedNamingTheFileAndTheCell) {
  // A quad folded at its 4th corner (not convex).
  const std::string folded = write_temp("folded.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0.8 0.2 0\nf 1 2 3 4\n");
  EXPECT_NE(error_of([&] { patch_mesh_from_file(folded, {}); }).find("folded.obj: cell 0"), std::string::npos);
  EXPECT_NE(error_of([&] { patch_mesh_from_file(folded, {}); }).find("is folded or not convex"), std::string::npos);
  // Three cells on one edge (non-manifold).
  const std::string three = write_temp(
      "three.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\nv 1.5 2 0\nf 1 2 3 4\nf 2 5 6 3\nf 3 2 7\n");
  EXPECT_NE(error_of([&] { patch_mesh_from_file(three, {}); }).find("is shared by 3 cells"), std::string::npos);
  // Inconsistent orientation: the second patch is listed clockwise, the first counterclockwise.
  const std::string turned =
      write_temp("turned.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\nf 1 2 3 4\nf 2 3 6 5\n");
  EXPECT_NE(error_of([&] { patch_mesh_from_file(turned, {}); })
                .find("turned.obj: cell 1 (line 8: quadrilateral (1, 0), (1, 1), (2, 1), (2, 0)) is listed clockwise"),
            std::string::npos);
  // A mesh folding over itself: two cells on the same side of their common edge.
  const std::string overlap =
      write_temp("overlap.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0\n4 0 1 2 3\n3 0 1 4\n");
  EXPECT_NE(error_of([&] { patch_mesh_from_file(overlap, {}); }).find("lie on the same side of their common edge"),
            std::string::npos);
  // An inverted (clockwise) patch of a mesh built in code.
  PlanarMesh cw;
  cw.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  cw.cells = {{0, 3, 2, 1}};
  cw.source = "cw";
  EXPECT_NE(error_of([&] { patch_mesh_from_planar(cw); }).find("cw: cell 0"), std::string::npos);
  EXPECT_NE(error_of([&] { patch_mesh_from_planar(cw); }).find("is clockwise (inverted)"), std::string::npos);
  // Boundary groups: "all" is reserved, and a group edge must be a boundary edge.
  const std::vector<Point2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
  const std::vector<std::vector<int>> fan{{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  EXPECT_NE(error_of([&] { PatchMesh(square, fan, "g", {{"all", {{0, 1}}}}); }).find("'all' is reserved"),
            std::string::npos);
  EXPECT_NE(error_of([&] { PatchMesh(square, fan, "g", {{"diag", {{0, 4}}}}); })
                .find("g: boundary group 'diag' has the edge between vertices 0 and 4, which is not a boundary edge"),
            std::string::npos);
}

TEST(G1MeshFile, ConfigErrorsNameTheConfigPlace) {
  const std::string folded = write_temp("folded2.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0.8 0.2 0\nf 1 2 3 4\n");
  const std::string e1 = error_of([&] { test::space_from_yaml(yaml_for("{type: mesh_file, file: " + folded + "}")); });
  EXPECT_NE(e1.find("test.yaml:1:"), std::string::npos) << e1;
  EXPECT_NE(e1.find("domain.file"), std::string::npos) << e1;
  EXPECT_NE(e1.find("cell 0"), std::string::npos) << e1;
  const std::string e2 = error_of([&] {
    test::space_from_yaml(yaml_for("{type: mesh_file, file: " + kDomains + "g1_valence5_plate.obj, recombine: true}"));
  });
  EXPECT_NE(e2.find("recombine applies to .geo files only"), std::string::npos) << e2;
  const std::string e3 = error_of([&] { test::space_from_yaml(yaml_for("{type: mesh_file, file: /no/such/mesh.obj}")); });
  EXPECT_NE(e3.find("/no/such/mesh.obj"), std::string::npos) << e3;
  // Below the separability degree on the file's mesh: the space names the degree that works.
  const std::string e4 =
      error_of([&] { test::space_from_yaml(yaml_for("{type: mesh_file, file: " + kDomains + "g1_valence5_plate.obj}", 4)); });
  EXPECT_NE(e4.find("use degree >= 5"), std::string::npos) << e4;
}

TEST(G1MeshFile, GmshPhysicalCurvesAreTheBoundaryParts) {
  // tests/support/data/square_groups.msh: the unit square in triangles, physical curves "bottom" (y = 0),
  // "sides" (x = 0 and x = 1) and an unnamed one (tag 7, y = 1). Lengths stay under refinement.
  const std::string file = std::string(IGA_SOURCE_DIR) + "/tests/support/data/square_groups.msh";
  for (int level = 0; level <= 1; ++level) {
    const SpacePtr s = test::space_from_yaml(yaml_for("{type: mesh_file, file: " + file + "}"), level);
    EXPECT_EQ(s->boundary_names(), (std::vector<std::string>{"7", "bottom", "sides"}));
    auto length = [&](const std::string& part) {
      double sum = 0.0;
      const auto& mesh = dynamic_cast<const G1Space&>(*s).mesh();
      for (const BoundaryEdge& e : s->boundary_edges(part)) {
        const Point2 a = mesh.map(e.element, reference_edge_point(s->cell_shape(e.element), e.local_edge, 0.0)).x;
        const Point2 b = mesh.map(e.element, reference_edge_point(s->cell_shape(e.element), e.local_edge, 1.0)).x;
        sum += (b - a).norm();
      }
      return sum;
    };
    EXPECT_NEAR(length("bottom"), 1.0, 1e-14);
    EXPECT_NEAR(length("sides"), 2.0, 1e-14);
    EXPECT_NEAR(length("7"), 1.0, 1e-14);
    EXPECT_NEAR(length("all"), 4.0, 1e-14);
  }
  // Mixed conditions on the named parts: a quintic is still reproduced.
  const std::string text = yaml_for("{type: mesh_file, file: " + file + "}") +
                           "problem: {pde: poisson, exact: \"x^5 - 2*x^2*y^3 + y^4 - x*y + 1\", "
                           "boundary: {all: dirichlet, sides: neumann}}\n";
  const LevelResult r =
      solve_problem(*test::space_from_yaml(text, 0), test::problem_from_yaml(text), SolverKind::cholmod).result;
  EXPECT_LT(*r.l2, 1e-11);
  EXPECT_LT(*r.h1, 1e-10);
  EXPECT_NE(error_of([&] { test::space_from_yaml(text)->boundary_edges("left"); }).find("valid: all, 7, bottom, sides"),
            std::string::npos);
}
