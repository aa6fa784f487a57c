// Mesh files (Gmsh .geo/.msh, OBJ, OFF) read into a PlanarMesh, and every rejection of
// validate_planar_mesh with the content of its message.

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "tests/support/input_error.hpp"
#include "tests/support/scratch_files.hpp"
#include "config/errors.hpp"
#include "mesh/mesh_polygon.hpp"
#include "mesh/read_mesh_file.hpp"
#include "mesh/validate_planar_mesh.hpp"

namespace iga {
namespace {

const std::string source_dir = IGA_SOURCE_DIR;
const std::string l_shape_geo = source_dir + "/configs/domains/l_shape.geo";

double total_area(const PlanarMesh& m) {
  double a = 0.0;
  for (int c = 0; c < static_cast<int>(m.cells.size()); ++c) a += 0.5 * twice_signed_area(m, c);
  return a;
}

int num_edges(const PlanarMesh& m) {
  std::set<std::pair<int, int>> edges;
  for (const auto& cell : m.cells)
    for (std::size_t k = 0; k < cell.size(); ++k) {
      const int a = cell[k], b = cell[(k + 1) % cell.size()];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  return static_cast<int>(edges.size());
}

double length(const PlanarMesh& m, const std::vector<std::array<int, 2>>& edges) {
  double l = 0.0;
  for (const auto& e : edges) l += (m.vertices[e[1]] - m.vertices[e[0]]).norm();
  return l;
}

int euler_characteristic(const PlanarMesh& m) {
  return static_cast<int>(m.vertices.size()) - num_edges(m) + static_cast<int>(m.cells.size());
}

double longest_edge(const PlanarMesh& m) {
  double h = 0.0;
  for (const auto& cell : m.cells)
    for (std::size_t k = 0; k < cell.size(); ++k)
      h = std::max(h, (m.vertices[cell[(k + 1) % cell.size()]] - m.vertices[cell[k]]).norm());
  return h;
}

using test::input_error;

TEST(MeshIo, GeoLShapeMeshedWithSize) {
  const PlanarMesh coarse = read_mesh_file(l_shape_geo, {0.25, false});
  const PlanarMesh fine = read_mesh_file(l_shape_geo, {0.125, false});
  for (const PlanarMesh* m : {&coarse, &fine}) {
    EXPECT_NO_THROW(validate_planar_mesh(*m, {true, false, "ws4"}));
    EXPECT_NEAR(total_area(*m), 3.0, 1e-12);  // [-1,1]² minus a unit square
    EXPECT_EQ(euler_characteristic(*m), 1);   // a disc
    for (const auto& cell : m->cells) EXPECT_EQ(cell.size(), 3u);
    EXPECT_NEAR(length(*m, boundary_edges(*m)), 8.0, 1e-12);
    ASSERT_EQ(m->boundary_groups.size(), 2u);
    EXPECT_NEAR(length(*m, m->boundary_groups.at("reentrant")), 2.0, 1e-12);
    EXPECT_NEAR(length(*m, m->boundary_groups.at("outer")), 6.0, 1e-12);
    EXPECT_EQ(m->boundary_groups.at("reentrant").size() + m->boundary_groups.at("outer").size(),
              boundary_edges(*m).size());
    EXPECT_EQ(m->cell_origins.size(), m->cells.size());
  }
  EXPECT_LE(longest_edge(coarse), 1.5 * 0.25);
  EXPECT_LE(longest_edge(fine), 1.5 * 0.125);
  EXPECT_GT(fine.cells.size(), 3 * coarse.cells.size());
  // Without a size the file's own (h = 0.5) applies; the same call gives the same mesh.
  const PlanarMesh own = read_mesh_file(l_shape_geo);
  EXPECT_LT(own.cells.size(), coarse.cells.size());
  EXPECT_EQ(read_mesh_file(l_shape_geo, {0.25, false}).vertices, coarse.vertices);
}

TEST(MeshIo, GeoRecombinedGivesQuadrilaterals) {
  const PlanarMesh m = read_mesh_file(l_shape_geo, {0.25, true});
  int quads = 0;
  for (const auto& cell : m.cells) quads += cell.size() == 4;
  EXPECT_EQ(quads, static_cast<int>(m.cells.size()));  // Blossom recombination leaves no triangle here
  EXPECT_NO_THROW(validate_planar_mesh(m));
  EXPECT_NEAR(total_area(m), 3.0, 1e-12);
  EXPECT_EQ(euler_characteristic(m), 1);
  const std::string message = input_error([&] { validate_planar_mesh(m, {true, false, "ws4"}); });
  EXPECT_NE(message.find("is a quadrilateral; the ws4 space needs triangles"), std::string::npos) << message;
  // Options set for one file do not leak into the next read.
  for (const auto& cell : read_mesh_file(l_shape_geo, {0.25, false}).cells) EXPECT_EQ(cell.size(), 3u);
}

TEST(MeshIo, MshPhysicalCurvesBecomeBoundaryGroups) {
  const PlanarMesh m = read_mesh_file(source_dir + "/tests/support/data/square_groups.msh");
  validate_planar_mesh(m);
  EXPECT_NEAR(total_area(m), 1.0, 1e-14);
  EXPECT_EQ(euler_characteristic(m), 1);
  ASSERT_EQ(m.boundary_groups.size(), 3u);
  EXPECT_NEAR(length(m, m.boundary_groups.at("bottom")), 1.0, 1e-14);
  EXPECT_NEAR(length(m, m.boundary_groups.at("sides")), 2.0, 1e-14);
  EXPECT_NEAR(length(m, m.boundary_groups.at("7")), 1.0, 1e-14);  // unnamed: its tag
  for (const auto& e : m.boundary_groups.at("bottom")) {
    EXPECT_EQ(m.vertices[e[0]].y(), 0.0);
    EXPECT_EQ(m.vertices[e[1]].y(), 0.0);
  }
  for (const auto& e : m.boundary_groups.at("sides"))
    EXPECT_TRUE(m.vertices[e[0]].x() == m.vertices[e[1]].x() &&
                (m.vertices[e[0]].x() == 0.0 || m.vertices[e[0]].x() == 1.0));
}

TEST(MeshIo, ObjTrianglesAndQuadsOnAPlane) {
  // Two unit squares side by side at z = 2: a quad (with texture/normal indices) and two triangles
  // (negative indices), all clockwise in the file, plus statements that carry no geometry.
  const std::string path = test::scratch_file("mixed.obj",
                                              "# mixed mesh\n"
                                              "o part\n"
                                              "v 0 0 2\nv 1 0 2\nv 1 1 2\nv 0 1 2\n"
                                              "vt 0 0\nvn 0 0 1\n"
                                              "f 1/1/1 4/1/1 3//1 2\n"
                                              "v 2 0 2\nv 2 1 2\n"
                                              "s off\n"
                                              "f 2 -1 -2\n"
                                              "f 2 3 6\n");
  const PlanarMesh m = read_mesh_file(path);
  ASSERT_EQ(m.vertices.size(), 6u);
  ASSERT_EQ(m.cells.size(), 3u);
  EXPECT_EQ(m.cells[0].size(), 4u);
  EXPECT_EQ(m.cells[0], (std::vector<int>{0, 1, 2, 3}));  // reversed to counterclockwise
  EXPECT_EQ(m.cells[1], (std::vector<int>{1, 4, 5}));
  EXPECT_EQ(m.cell_origins[2], "line 14");
  validate_planar_mesh(m);
  EXPECT_NEAR(total_area(m), 2.0, 1e-15);
  EXPECT_EQ(euler_characteristic(m), 1);
  EXPECT_TRUE(m.boundary_groups.empty());
}

TEST(MeshIo, InconsistentOrientationIsRejectedNamingTheCell) {
  // The same two squares with the quad clockwise and the triangles counterclockwise: one of the
  // two senses is a broken export, so the reader refuses to guess.
  const std::string path = test::scratch_file("inconsistent.obj",
                                              "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
                                              "f 1 4 3 2\n"
                                              "f 2 5 6\n"
                                              "f 2 6 3\n");
  EXPECT_EQ(input_error([&] { read_mesh_file(path); }),
            path + ": cell 1 (line 8: triangle (1, 0), (2, 0), (2, 1)) is listed counterclockwise, but cell 0 "
                   "(line 7: quadrilateral (0, 0), (0, 1), (1, 1), (1, 0)) is listed clockwise: inconsistent "
                   "orientation (list the vertices of every cell in the same sense)");
  // OFF files are checked the same way.
  const std::string off = test::scratch_file("inconsistent.off",
                                             "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 3 2\n");
  EXPECT_NE(input_error([&] { read_mesh_file(off); }).find("inconsistent orientation"), std::string::npos);
}

TEST(MeshIo, OffTrianglesAndQuads) {
  const std::string path = test::scratch_file("mixed.off",
                                              "OFF\n# a quad and two triangles\n6 3 0\n"
                                              "0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n2 1 0\n"
                                              "4 0 1 2 3\n3 1 4 5 255 0 0\n3 1 5 2\n");
  const PlanarMesh m = read_mesh_file(path);
  ASSERT_EQ(m.cells.size(), 3u);
  EXPECT_EQ(m.cells[0], (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(m.cells[1], (std::vector<int>{1, 4, 5}));
  validate_planar_mesh(m);
  EXPECT_NEAR(total_area(m), 2.0, 1e-15);
  EXPECT_EQ(euler_characteristic(m), 1);
  // Counts on the header line are accepted too.
  EXPECT_EQ(read_mesh_file(test::scratch_file("inline.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")).cells.size(),
            1u);
}

TEST(MeshIo, PolygonWithHoleMeshedByGmsh) {
  using V = Eigen::Vector2d;
  // Square [0,3]² with a square hole [1,2]²: area 8, an annulus (V - E + F = 0).
  const PolygonDomain domain{{V(0, 0), V(3, 0), V(3, 3), V(0, 3)}, {{V(1, 1), V(1, 2), V(2, 2), V(2, 1)}}};
  const PlanarMesh m = mesh_polygon(domain, 0.4, false, "polygon");
  validate_planar_mesh(m, {true, false, "ws4"});
  EXPECT_NEAR(total_area(m), 8.0, 1e-12);
  EXPECT_EQ(euler_characteristic(m), 0);
  EXPECT_LE(longest_edge(m), 1.5 * 0.4);
  ASSERT_EQ(m.boundary_groups.size(), 5u);
  for (const char* side : {"side1", "side2", "side3", "side4"})
    EXPECT_NEAR(length(m, m.boundary_groups.at(side)), 3.0, 1e-12);
  EXPECT_NEAR(length(m, m.boundary_groups.at("hole1")), 4.0, 1e-12);
  for (const auto& e : m.boundary_groups.at("side2"))
    EXPECT_TRUE(m.vertices[e[0]].x() == 3.0 && m.vertices[e[1]].x() == 3.0);
  EXPECT_NEAR(length(m, boundary_edges(m)), 16.0, 1e-12);
  // Recombined: quadrilaterals, same domain.
  const PlanarMesh q = mesh_polygon(domain, 0.4, true, "polygon");
  EXPECT_NEAR(total_area(q), 8.0, 1e-12);
  EXPECT_GT(std::count_if(q.cells.begin(), q.cells.end(), [](const auto& c) { return c.size() == 4; }), 0);
}

TEST(MeshIo, PolygonRejectionsNameTheSides) {
  using V = Eigen::Vector2d;
  auto message = [](const PolygonDomain& d) {
    return input_error([&] { mesh_polygon(d, 0.5, false, "cfg.yaml:3:5: domain"); });
  };
  EXPECT_EQ(
      message({{V(0, 0), V(1, 1), V(1, 0), V(0, 1)}, {}}),
      "cfg.yaml:3:5: domain: outer side 1 ((0, 0)-(1, 1)) crosses outer side 3 ((1, 0)-(0, 1)); the polygon must be "
      "simple");
  EXPECT_EQ(message({{V(0, 0), V(1, 0)}, {}}),
            "cfg.yaml:3:5: domain: the outer polygon needs at least 3 vertices (got 2)");
  EXPECT_EQ(
      message({{V(0, 0), V(2, 0), V(1, 0), V(1, 1)}, {}}),
      "cfg.yaml:3:5: domain: outer side 1 ((0, 0)-(2, 0)) folds back onto outer side 2 ((2, 0)-(1, 0)); the polygon "
      "must be simple");
  EXPECT_EQ(message({{V(0, 0), V(1, 0), V(1, 1)}, {{V(5, 5), V(6, 5), V(6, 6)}}}),
            "cfg.yaml:3:5: domain: hole 1 is not inside the outer polygon");
  EXPECT_NE(message({{V(0, 0), V(4, 0), V(4, 4), V(0, 4)}, {{V(1, 1), V(5, 2), V(1, 3)}}})
                .find("outer side 2 ((4, 0)-(4, 4)) crosses hole 1 side 1"),
            std::string::npos);
}

struct Rejection {
  std::string file, text, expected;
};

TEST(MeshIo, FileErrorsNameTheFileAndLine) {
  const std::vector<Rejection> cases = {
      {"pentagon.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -1 0 0\nf 1 2 3 4 5\n",
       "pentagon.obj:6: a face with 5 vertices; only triangles (3) and quadrilaterals (4)"},
      {"index.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 4\n", "index.obj:4: face vertex 4 does not exist (3 vertices"},
      {"zero.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 0 1 2\n", "zero.obj:4: face vertex 0 does not exist"},
      {"bent.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0.5\nf 1 2 3\n",
       "bent.obj: vertex 2 (line 3) has z = 0.5, vertex 0 has z = 0: the mesh must lie in a plane"},
      {"typo.obj", "v 0 0 0\nvv 1 0 0\n", "typo.obj:2: unknown OBJ statement 'vv'"},
      {"number.obj", "v 0 0x 0\n", "number.obj:1: expected a number, got '0x'"},
      {"header.off", "COFF\n3 1 0\n", "header.off:1: expected the header 'OFF'"},
      {"short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n", "short.off:4: the file ends after 2 of 3 vertices"},
      {"hexagon.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n6 0 1 2 0 1 2\n", "hexagon.off:6: a face with 6 vertices"},
      {"range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
       "range.off:6: face vertex 3 does not exist (3 vertices; OFF indices are 0-based)"},
      {"mesh.stl", "solid\n", "mesh.stl: unknown mesh file extension '.stl' (supported: .msh, .geo, .obj, .off, .xml)"},
      {"syntax.geo", "Point(1) = {0, 0, 0, 1};\nLine(1) = {1, 7};\n", "syntax.geo: gmsh: Unknown control point 7"},
      {"curve.geo", "Point(1) = {0, 0, 0, 1};\nPoint(2) = {1, 0, 0, 1};\nLine(1) = {1, 2};\n",
       "curve.geo: the mesh has no triangles or quadrilaterals"},
      {"second_order.geo",
       "Point(1) = {0,0,0,1}; Point(2) = {1,0,0,1}; Point(3) = {0,1,0,1};\n"
       "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,1};\nCurve Loop(1) = {1,2,3}; Plane Surface(1) = {1};\n"
       "Mesh.ElementOrder = 2;\n",
       "2D elements of type 'Triangle 6' (Gmsh type 9) are not supported"},
      {"tilted.geo",
       "Point(1) = {0,0,0,1}; Point(2) = {1,0,0,1}; Point(3) = {0,1,1,1};\n"
       "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,1};\nCurve Loop(1) = {1,2,3}; Plane Surface(1) = {1};\n",
       "the mesh must lie in a plane z = const"},
  };
  for (const Rejection& c : cases) {
    const std::string path = test::scratch_file(c.file, c.text);
    const std::string message = input_error([&] { read_mesh_file(path); });
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.file << ": " << message;
    EXPECT_EQ(message.rfind(path, 0), 0u) << "message starts with the file: " << message;
  }
  // A Gmsh error does not spoil the next file (the SDK is restarted after errors).
  EXPECT_THROW(read_mesh_file(test::scratch_file("again.geo", "Line(1) = {1, 2};\n")), InputError);
  EXPECT_NEAR(total_area(read_mesh_file(l_shape_geo, {0.5, false})), 3.0, 1e-12);
  const std::string obj = test::scratch_file("options.obj", "v 0 0\nv 1 0\nv 0 1\nf 1 2 3\n");
  EXPECT_EQ(input_error([&] { read_mesh_file(obj, {0.1, false}); }),
            obj + ": a mesh size or recombination applies to .geo files only (a mesh is used as it is)");
  const std::string missing = input_error([] { read_mesh_file("/nonexistent/domain.msh"); });
  EXPECT_EQ(missing, "/nonexistent/domain.msh: cannot read the mesh file");
}

PlanarMesh mesh_of(std::vector<Eigen::Vector2d> vertices, std::vector<std::vector<int>> cells) {
  PlanarMesh m;
  m.vertices = std::move(vertices);
  m.cells = std::move(cells);
  m.source = "test.obj";
  return m;
}

std::string validation_error(const PlanarMesh& m, const AllowedCells& allowed = {}) {
  return input_error([&] { validate_planar_mesh(m, allowed); });
}

TEST(MeshIo, ValidationRejectsBadMeshesNamingTheCell) {
  using V = Eigen::Vector2d;
  const std::vector<V> square = {V(0, 0), V(1, 0), V(1, 1), V(0, 1)};
  // Degenerate: cell 1 has three collinear corners.
  std::string m = validation_error(mesh_of({V(0, 0), V(1, 0), V(0, 1), V(2, 0)}, {{0, 1, 2}, {0, 1, 3}}));
  EXPECT_EQ(m, "test.obj: cell 1 (triangle (0, 0), (1, 0), (2, 0)) is degenerate (area 0, longest edge 2)");
  // Clockwise cell (built in code; the readers would have reversed it).
  m = validation_error(mesh_of(square, {{0, 1, 2}, {0, 3, 2}}));
  EXPECT_EQ(m,
            "test.obj: cell 1 (triangle (0, 0), (0, 1), (1, 1)) is clockwise (inverted); list its vertices "
            "counterclockwise");
  // Non-convex quad (arrowhead): the corner (0.5, 0.3) has a negative Jacobian.
  m = validation_error(mesh_of({V(0, 0), V(1, 0), V(0.5, 0.3), V(0.5, 1)}, {{0, 1, 2, 3}}));
  EXPECT_NE(m.find("cell 0 (quadrilateral (0, 0), (1, 0), (0.5, 0.3), (0.5, 1)) is folded or not convex at corner "
                   "(0.5, 0.3)"),
            std::string::npos)
      << m;
  // Bow-tie quad with positive signed area: folded at the corners of the smaller loop.
  m = validation_error(mesh_of({V(0, 0), V(2, 0), V(0, 1), V(1, 1)}, {{0, 1, 3, 2}, {0, 1, 2, 3}}));
  EXPECT_NE(m.find("cell 1 (quadrilateral"), std::string::npos) << m;
  EXPECT_NE(m.find("is folded or not convex"), std::string::npos) << m;
  // Three cells on one edge.
  m = validation_error(mesh_of({V(0, 0), V(1, 0), V(0.5, 1), V(0.5, 2), V(0.5, 3)}, {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}}));
  EXPECT_EQ(m, "test.obj: edge (0, 0)-(1, 0) is shared by 3 cells (0, 1, 2): the mesh is not a manifold");
  // Two cells on the same side of their edge: the mesh folds over itself.
  m = validation_error(mesh_of({V(0, 0), V(1, 0), V(0.5, 1), V(0.5, 0.5)}, {{0, 1, 2}, {0, 1, 3}}));
  EXPECT_EQ(m,
            "test.obj: cell 0 (triangle (0, 0), (1, 0), (0.5, 1)) and cell 1 (triangle (0, 0), (1, 0), (0.5, 0.5)) "
            "lie on the same side of their common edge (0, 0)-(1, 0): the mesh folds over itself");
  // An unused vertex.
  m = validation_error(mesh_of({V(0, 0), V(1, 0), V(0, 1), V(5, 5)}, {{0, 1, 2}}));
  EXPECT_EQ(m, "test.obj: vertex 3 (5, 5) belongs to no cell");
  // Duplicate nodes: the two triangles are not connected.
  m = validation_error(mesh_of({V(0, 0), V(1, 0), V(1, 1), V(0, 0), V(1, 1), V(0, 1)}, {{0, 1, 2}, {3, 4, 5}}));
  EXPECT_EQ(m,
            "test.obj: vertex 0 (0, 0) and vertex 3 coincide; merge duplicate nodes (cells meeting there are not "
            "connected)");
  // Two triangles touching at one vertex only.
  m = validation_error(mesh_of({V(0, 0), V(1, 0), V(0, 1), V(-1, 0), V(0, -1)}, {{0, 1, 2}, {0, 3, 4}}));
  EXPECT_EQ(m,
            "test.obj: the boundary touches itself at vertex 0 (0, 0) (4 boundary edges meet there); cells must be "
            "connected through edges");
  // Repeated vertex in a cell, vertex out of range, polygon.
  m = validation_error(mesh_of(square, {{0, 1, 1}}));
  EXPECT_NE(m.find("uses vertex 1 twice"), std::string::npos) << m;
  m = validation_error(mesh_of(square, {{0, 1, 7}}));
  EXPECT_NE(m.find("refers to vertex 7, but the mesh has 4 vertices"), std::string::npos) << m;
  m = validation_error(mesh_of({V(0, 0), V(1, 0), V(1, 1), V(0.5, 1.5), V(0, 1)}, {{0, 1, 2, 3, 4}}));
  EXPECT_NE(m.find("5-gon"), std::string::npos) << m;
  // Cell kinds a space does not take, named with the origin of the cell.
  PlanarMesh quads = mesh_of(square, {{0, 1, 2, 3}});
  quads.cell_origins = {"line 9"};
  m = validation_error(quads, {true, false, "ws4"});
  EXPECT_EQ(m,
            "test.obj: cell 0 (line 9: quadrilateral (0, 0), (1, 0), (1, 1), (0, 1)) is a quadrilateral; the ws4 "
            "space needs triangles");
  m = validation_error(mesh_of(square, {{0, 1, 2}, {0, 2, 3}}), {false, true, "g1"});
  EXPECT_NE(m.find("cell 0 (triangle (0, 0), (1, 0), (1, 1)) is a triangle; the g1 space needs quadrilaterals"),
            std::string::npos)
      << m;
  // A boundary group on an interior edge.
  PlanarMesh grouped = mesh_of(square, {{0, 1, 2}, {0, 2, 3}});
  grouped.boundary_groups["diagonal"] = {{0, 2}};
  m = validation_error(grouped);
  EXPECT_EQ(m, "test.obj: boundary group 'diagonal' has edge (0, 0)-(1, 1), which is not a boundary edge of the mesh");
  // Empty mesh.
  EXPECT_EQ(validation_error(mesh_of({}, {})), "test.obj: the mesh has no cells");
  // And the valid two-triangle square passes.
  EXPECT_NO_THROW(validate_planar_mesh(mesh_of(square, {{0, 1, 2}, {0, 2, 3}})));
}

TEST(MeshIo, NearlyDegenerateCellsAreRejectedAtAnyScale) {
  using V = Eigen::Vector2d;
  // A 1 x 0.005 rectangle (aspect ratio 200) and a triangle whose apex is 0.004 above its base:
  // valid cells, but thinner than mesh_shape_tolerance; the same at 1e6 and 1e-6 times the size.
  for (const double scale : {1.0, 1e6, 1e-6}) {
    const auto at = [&](double x, double y) { return V(scale * x, scale * y); };
    std::string m = validation_error(mesh_of({at(0, 0), at(1, 0), at(1, 0.005), at(0, 0.005)}, {{0, 1, 2, 3}}));
    EXPECT_NE(m.find("cell 0 (quadrilateral"), std::string::npos) << m;
    EXPECT_NE(m.find("is nearly degenerate at corner"), std::string::npos) << m;
    EXPECT_NE(m.find("span 0.005 x (longest edge)², less than 0.01"), std::string::npos) << m;
    m = validation_error(mesh_of({at(0, 0), at(1, 0), at(0.5, 0.004)}, {{0, 1, 2}}));
    EXPECT_NE(m.find("cell 0 (triangle"), std::string::npos) << m;
    EXPECT_NE(m.find("span 0.004 x (longest edge)²"), std::string::npos) << m;
    // Aspect ratio 50 and a right triangle pass.
    EXPECT_NO_THROW(validate_planar_mesh(mesh_of({at(0, 0), at(1, 0), at(1, 0.02), at(0, 0.02)}, {{0, 1, 2, 3}})));
    EXPECT_NO_THROW(validate_planar_mesh(mesh_of({at(0, 0), at(1, 0), at(0, 1)}, {{0, 1, 2}})));
  }
  // Two vertices of a cell almost together (a hundredth of a percent of the cell apart).
  const std::string m = validation_error(
      mesh_of({V(0, 0), V(1, 0), V(1, 1), V(1e-4, 1), V(0, 1)}, {{0, 1, 2, 3}, {0, 3, 4}}));
  EXPECT_NE(m.find("cell 1 (triangle (0, 0), (0.0001, 1), (0, 1)) is nearly degenerate"), std::string::npos) << m;
  EXPECT_NE(m.find("shortest edge 0.0001"), std::string::npos) << m;
}

TEST(MeshIo, BoundaryGroupNamesMustBeUtf8) {
  using V = Eigen::Vector2d;
  PlanarMesh m = mesh_of({V(0, 0), V(1, 0), V(1, 1), V(0, 1)}, {{0, 1, 2}, {0, 2, 3}});
  m.boundary_groups["bottom"] = {{0, 1}};
  m.boundary_groups["l\xE9" "ft"] = {{3, 0}};
  EXPECT_EQ(validation_error(m), "test.obj: a boundary group name is not UTF-8 text (byte 0xE9 at byte 2 of the name)");
  m.boundary_groups.erase("l\xE9" "ft");
  m.boundary_groups["l\xC3\xA9" "ft"] = {{3, 0}};  // the same name in UTF-8
  EXPECT_NO_THROW(validate_planar_mesh(m));
}

}  // namespace
}  // namespace iga
