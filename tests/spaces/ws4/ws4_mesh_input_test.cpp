/// @file
/// WS4 spaces on meshes from files (Gmsh .geo/.msh, OBJ), on the built-in L-shape and on Gmsh-meshed
/// polygons: dimension 10 V + 6 E + 3 T of the mesh that was read, named boundary parts from
/// physical curves, rates on the Gmsh L-shape, quartic reproduction on a polygon with a hole, and
/// config errors naming the config key and the offending triangle.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <sys/wait.h>

#include "tests/support/scratch_files.hpp"
#include "config/errors.hpp"
#include "mesh/read_mesh_file.hpp"
#include "spaces/ws4/ws4_space.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

const std::string l_shape_geo = std::string(IGA_SOURCE_DIR) + "/configs/domains/l_shape.geo";

const ws4::Ws4Space& as_ws4(const SpacePtr& space) { return dynamic_cast<const ws4::Ws4Space&>(*space); }

int count_edges(const PlanarMesh& m) {
  std::set<std::pair<int, int>> edges;
  for (const auto& c : m.cells)
    for (int k = 0; k < 3; ++k) edges.insert({std::min(c[k], c[(k + 1) % 3]), std::max(c[k], c[(k + 1) % 3])});
  return static_cast<int>(edges.size());
}

/// Total length of a named boundary part of a WS4 space.
double part_length(const ws4::Ws4Space& space, const std::string& name) {
  double length = 0.0;
  for (const BoundaryEdge& b : space.boundary_edges(name)) {
    const auto& e = space.mesh().edge(space.mesh().triangle_edge(b.element, b.local_edge));
    length += (space.mesh().vertices()[e[1]] - space.mesh().vertices()[e[0]]).norm();
  }
  return length;
}

std::string geo_domain(double mesh_size, const std::string& space = "{type: ws4}") {
  return "domain: {type: mesh_file, file: " + l_shape_geo + ", mesh_size: " + std::to_string(mesh_size) + "}\n" +
         "space: " + space + "\n";
}

TEST(Ws4MeshInput, GmshLShapeDimensionAndBoundaryParts) {
  // V, E, T counted on the mesh as read (independently of the space), then after one refinement.
  const PlanarMesh read = read_mesh_file(l_shape_geo, {0.5, false});
  const int v = static_cast<int>(read.vertices.size()), e = count_edges(read), t = static_cast<int>(read.cells.size());
  EXPECT_EQ(v - e + t, 1);
  const SpacePtr level0 = test::space_from_yaml(geo_domain(0.5), 0);
  EXPECT_EQ(level0->num_elements(), t);
  EXPECT_EQ(level0->dimension(), 10 * v + 6 * e + 3 * t);
  const SpacePtr level1 = test::space_from_yaml(geo_domain(0.5), 1);
  EXPECT_EQ(level1->num_elements(), 4 * t);
  EXPECT_EQ(level1->dimension(), 10 * (v + e) + 6 * (2 * e + 3 * t) + 3 * (4 * t));

  EXPECT_EQ(level1->boundary_names(), (std::vector<std::string>{"outer", "reentrant"}));
  EXPECT_NEAR(part_length(as_ws4(level1), "reentrant"), 2.0, 1e-12);
  EXPECT_NEAR(part_length(as_ws4(level1), "outer"), 6.0, 1e-12);
  EXPECT_NEAR(part_length(as_ws4(level1), "all"), 8.0, 1e-12);
}

TEST(Ws4MeshInput, MshPhysicalCurvesNameTheParts) {
  const std::string msh = std::string(IGA_SOURCE_DIR) + "/tests/support/data/square_groups.msh";
  const PlanarMesh read = read_mesh_file(msh);
  const int v = static_cast<int>(read.vertices.size()), e = count_edges(read), t = static_cast<int>(read.cells.size());
  const SpacePtr space = test::space_from_yaml("domain: {type: mesh_file, file: " + msh + "}\nspace: {type: ws4}\n");
  EXPECT_EQ(space->dimension(), 10 * v + 6 * e + 3 * t);
  EXPECT_EQ(space->boundary_names(), (std::vector<std::string>{"7", "bottom", "sides"}));
  EXPECT_NEAR(part_length(as_ws4(space), "bottom"), 1.0, 1e-15);
  EXPECT_NEAR(part_length(as_ws4(space), "sides"), 2.0, 1e-15);
  EXPECT_NEAR(part_length(as_ws4(space), "7"), 1.0, 1e-15);
}

TEST(Ws4MeshInput, GmshLShapePoissonConvergesAtOptimalRates) {
  // Smooth solution, Dirichlet on `outer` and the exact normal derivative on `reentrant`.
  const test::Rates r = test::last_rates(geo_domain(0.5) + R"yaml(
problem: {pde: poisson, exact: "exp(0.5*x)*sin(2*y+0.3)", boundary: {all: dirichlet, reentrant: neumann}}
)yaml",
                                         2);
  EXPECT_GE(r.l2, 4.7);
  EXPECT_GE(r.h1, 3.8);
  EXPECT_GE(r.h2, 2.8);
}

TEST(Ws4MeshInput, BuiltInLShape) {
  for (int n : {1, 2}) {
    const SpacePtr space =
        test::space_from_yaml("domain: {type: l_shape}\nspace: {type: ws4, elements: " + std::to_string(n) + "}\n");
    // (2n+1)² grid points minus the n² strictly inside the removed quarter; 2 triangles per square.
    const int v = (2 * n + 1) * (2 * n + 1) - n * n, t = 6 * n * n, e = v + t - 1;
    EXPECT_EQ(space->num_elements(), t);
    EXPECT_EQ(space->dimension(), 10 * v + 6 * e + 3 * t);
    const auto& ws4 = as_ws4(space);
    EXPECT_EQ(space->boundary_names(), (std::vector<std::string>{"bottom", "left", "reentrant", "right", "top"}));
    EXPECT_NEAR(part_length(ws4, "left"), 2.0, 1e-14);
    EXPECT_NEAR(part_length(ws4, "top"), 2.0, 1e-14);
    EXPECT_NEAR(part_length(ws4, "right"), 1.0, 1e-14);
    EXPECT_NEAR(part_length(ws4, "bottom"), 1.0, 1e-14);
    EXPECT_NEAR(part_length(ws4, "reentrant"), 2.0, 1e-14);
  }
}

TEST(Ws4MeshInput, PolygonWithHoleReproducesQuartics) {
  // A quartic lies in the space: the Gmsh-meshed (unstructured) domain with a hole solves it to
  // round-off, with clamped data on the outer sides and on the hole.
  const std::string yaml = R"yaml(
domain:
  type: polygon
  vertices: [[0, 0], [2, 0], [2.5, 1.2], [1, 2], [-0.3, 1]]
  holes: [[[0.8, 0.6], [1.3, 0.7], [1.0, 1.1]]]
  mesh_size: 0.6
space: {type: ws4}
problem: {pde: biharmonic, exact: "x^4 - 2*x^2*y^2 + x*y^3 + 3*y - 1", boundary: {all: clamped}}
)yaml";
  const SpacePtr space = test::space_from_yaml(yaml);
  const std::vector<std::string> names = space->boundary_names();
  EXPECT_EQ(names, (std::vector<std::string>{"hole1", "side1", "side2", "side3", "side4", "side5"}));
  EXPECT_NEAR(part_length(as_ws4(space), "side1"), 2.0, 1e-12);
  const LevelResult r = solve_problem(*space, test::problem_from_yaml(yaml), SolverKind::cholmod).result;
  std::printf("polygon with hole: %d triangles, L2 %.3e H2 %.3e\n", space->num_elements(), *r.l2, *r.h2);
  EXPECT_GT(space->num_elements(), 10);
  EXPECT_LT(*r.l2, 1e-9);
  EXPECT_LT(*r.h2, 1e-7);
}

std::string config_error(const std::string& yaml) {
  try {
    test::space_from_yaml(yaml);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for\n" << yaml;
  return "";
}

TEST(Ws4MeshInput, RelativeFilesAreFoundNextToTheConfig) {
  const std::string obj = test::scratch_file("square.obj", "v 0 0\nv 1 0\nv 1 1\nv 0 1\nf 1 2 3\nf 1 3 4\n");
  const std::string config =
      test::scratch_file("run.yaml", "domain: {type: mesh_file, file: square.obj}\nspace: {type: ws4}\n");
  const ConfigNode root = ConfigNode::load_file(config);
  const SpacePtr space = make_space(root["domain"], root["space"], 1);
  EXPECT_EQ(space->num_elements(), 8);
  EXPECT_EQ(space->dimension(), 10 * 9 + 6 * 16 + 3 * 8);
  EXPECT_EQ(space->boundary_names(), std::vector<std::string>{});  // OBJ: only "all"
  EXPECT_NEAR(part_length(as_ws4(space), "all"), 4.0, 1e-15);
  (void)obj;
}

TEST(Ws4MeshInput, ConfigErrorsNameTheKeyAndTheTriangle) {
  std::string m = config_error("domain: {type: mesh_file, file: /nonexistent/l.msh}\nspace: {type: ws4}\n");
  EXPECT_EQ(m, "test.yaml:1:33: domain.file: /nonexistent/l.msh: cannot read the mesh file");

  const std::string flat =
      test::scratch_file("flat.obj", "v 0 0\nv 1 0\nv 0 1\nv 2 0\nf 1 2 3\nf 2 4 3\nf 1 2 4\n");  // cell 2 is a segment
  m = config_error("domain: {type: mesh_file, file: " + flat + "}\nspace: {type: ws4}\n");
  EXPECT_NE(m.find("test.yaml:1:33: domain.file: " + flat +
                   ": cell 2 (line 7: triangle (0, 0), (1, 0), (2, 0)) is degenerate"),
            std::string::npos)
      << m;

  const std::string quads = test::scratch_file("quads.obj", "v 0 0\nv 1 0\nv 1 1\nv 0 1\nf 1 2 3 4\n");
  m = config_error("domain: {type: mesh_file, file: " + quads + "}\nspace: {type: ws4}\n");
  EXPECT_NE(m.find("cell 0 (line 5: quadrilateral (0, 0), (1, 0), (1, 1), (0, 1)) is a quadrilateral; the ws4 space "
                   "needs triangles"),
            std::string::npos)
      << m;

  m = config_error("domain: {type: mesh_file, file: " + quads + ", mesh_size: 0.1}\nspace: {type: ws4}\n");
  EXPECT_NE(m.find("domain.mesh_size: mesh_size applies to .geo files only"), std::string::npos) << m;

  m = config_error(geo_domain(0.5, "{type: ws4, elements: 4}"));
  EXPECT_NE(m.find("space.elements: 'elements' sets the grid of unit_square, rectangle and l_shape domains"),
            std::string::npos)
      << m;

  const std::string all = test::scratch_file("all.geo",
                                             "Point(1) = {0,0,0,1}; Point(2) = {1,0,0,1}; Point(3) = {0,1,0,1};\n"
                                             "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,1};\n"
                                             "Curve Loop(1) = {1,2,3}; Plane Surface(1) = {1};\n"
                                             "Physical Curve(\"all\") = {1};\n");
  m = config_error("domain: {type: mesh_file, file: " + all + "}\nspace: {type: ws4}\n");
  EXPECT_NE(m.find("boundary group name 'all' is reserved"), std::string::npos) << m;

  m = config_error(
      "domain: {type: polygon, vertices: [[0, 0], [1, 1], [1, 0], [0, 1]], mesh_size: 0.5}\n"
      "space: {type: ws4}\n");
  EXPECT_EQ(m,
            "test.yaml:1:9: domain: polygon: outer side 1 ((0, 0)-(1, 1)) crosses outer side 3 ((1, 0)-(0, 1)); "
            "the polygon must be simple");

  // A thin triangle (height 0.03 under a vertex whose shortest edge is 0.5) turned over by the jitter.
  const std::string thin =
      test::scratch_file("thin.obj", "v 0 0\nv 1 0\nv 1 1\nv 0 1\nv 0.5 0.03\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n");
  m = config_error("domain: {type: mesh_file, file: " + thin + ", jitter: 0.2, seed: 10}\nspace: {type: ws4}\n");
  EXPECT_NE(m.find("domain.jitter: the jitter turns over triangle 0 of level 0 (seed 10); use a smaller jitter"),
            std::string::npos)
      << m;

  m = config_error("domain: {type: l_shape}\nspace: {type: ws4, elements: [2, 3]}\n");
  EXPECT_NE(m.find("space.elements: expected one number N"), std::string::npos) << m;
}

TEST(Ws4MeshInput, CommandLineExitsWithCode2NamingTheTriangle) {
  const std::string flat =
      test::scratch_file("cli_flat.obj", "v 0 0\nv 1 0\nv 0 1\nv 2 0\nf 1 2 3\nf 2 4 3\nf 1 2 4\n");
  const std::string config = test::scratch_file("cli.yaml",
                                                "problem: {pde: poisson, exact: \"x*y\", boundary: {all: dirichlet}}\n"
                                                "domain: {type: mesh_file, file: cli_flat.obj}\n"
                                                "space: {type: ws4}\n");
  const std::string out = test::scratch_file("cli_out", ""), err = test::scratch_file("cli.err", "");
  std::filesystem::remove(out);
  const int status =
      std::system((std::string(IGA_RUN_BINARY) + " " + config + " --quiet --output " + out + " 2>" + err).c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::stringstream message;
  message << std::ifstream(err).rdbuf();
  EXPECT_EQ(message.str(), "iga-run: error: " + config + ":2:33: domain.file: " + flat +
                               ": cell 2 (line 7: triangle (0, 0), (1, 0), (2, 0)) is degenerate (area 0, longest "
                               "edge 2)\n");
  EXPECT_FALSE(std::filesystem::exists(out));  // no result directory for bad input
}

}  // namespace
}  // namespace iga
