// Triangle surface meshes in 3D: built-ins, .obj/.off input, normals, and the validation errors.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <sstream>

#include "config/errors.hpp"
#include "geometry/builtin_surface_meshes.hpp"
#include "geometry/triangle_surface_mesh.hpp"
#include "mesh/read_surface_mesh.hpp"
#include "tests/support/input_error.hpp"
#include "tests/support/scratch_files.hpp"

namespace iga {
namespace {

int count_interior(const std::vector<SurfaceEdge>& edges) {
  int n = 0;
  for (const auto& e : edges) n += e.interior();
  return n;
}

TEST(BuiltinSurfaces, CountsFollowEulerAndAreValid) {
  for (int level = 0; level <= 3; ++level) {
    const auto mesh = icosphere(level);
    const int T = 20 << (2 * level);
    EXPECT_EQ(mesh.num_triangles(), T);
    EXPECT_EQ(mesh.num_points(), T / 2 + 2);  // V − E + F = 2 with E = 3F/2
    EXPECT_NO_THROW(validate_surface_mesh(mesh));
    const auto edges = surface_edges(mesh);
    EXPECT_EQ(count_interior(edges), 3 * T / 2);
    for (int v = 0; v < mesh.num_points(); ++v) EXPECT_NEAR(mesh.points[v].norm(), 1.0, 1e-15);
  }
  // Longest edge of the level-0 icosphere: the icosahedron edge 1/sin(2π/5) = 1.0515.
  const auto ico = icosphere(0);
  EXPECT_NEAR((ico.points[0] - ico.points[11]).norm(), 1.0 / std::sin(2 * M_PI / 5), 1e-14);
  for (const auto& mesh : {regular_octahedron(), regular_tetrahedron(), perturbed_octahedron(), height_field()})
    EXPECT_NO_THROW(validate_surface_mesh(mesh)) << mesh.source;
  EXPECT_EQ(regular_octahedron().num_triangles(), 8);
  EXPECT_EQ(regular_tetrahedron().num_triangles(), 4);
  const auto field = surface_edges(height_field());
  EXPECT_EQ(height_field().num_triangles(), 18);
  EXPECT_EQ(count_interior(field), 21);
  EXPECT_EQ(static_cast<int>(field.size()) - count_interior(field), 12);
}

TEST(BuiltinSurfaces, FanNormalsOfThePerturbedOctahedronMatchTheNote) {
  // Note §5.3: the fan normal of vertex 0 is (253/50, −19/50, 31/50) (up to length).
  const auto mesh = perturbed_octahedron();
  const Eigen::Vector3d expected = Eigen::Vector3d(253, -19, 31).normalized();
  EXPECT_NEAR((mesh.normals[0] - expected).norm(), 0, 1e-15);
  EXPECT_NEAR((mesh.normals[4] - Eigen::Vector3d(2, 11, 279).normalized()).norm(), 0, 1e-15);
}

TEST(BuiltinSurfaces, AngleWeightedNormalsOfTheIcosphereAreRadial) {
  // By symmetry every vertex of the icosahedron has the radial normal.
  const auto mesh = icosphere(0);
  const auto normals = angle_weighted_normals(mesh);
  for (int v = 0; v < mesh.num_points(); ++v) EXPECT_NEAR((normals[v] - mesh.points[v]).norm(), 0, 1e-14);
}

const char* const tetrahedron_obj =
    "# tetrahedron\n"
    "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\n"
    "f 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n";

TEST(SurfaceMeshFiles, ObjWithoutNormalsGetsAngleWeightedNormals) {
  const auto mesh = surface_mesh_from_file(read_surface_mesh(test::scratch_file("tet.obj", tetrahedron_obj)));
  ASSERT_EQ(mesh.num_triangles(), 4);
  for (int v = 0; v < 4; ++v) EXPECT_NEAR((mesh.normals[v] - mesh.points[v].normalized()).norm(), 0, 1e-15);
}

TEST(SurfaceMeshFiles, ObjNormalsAreTakenFromTheFile) {
  const std::string text =
      "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\n"
      "vn 0 0 2\nvn 0 1 0\nvn 1 0 0\nvn 0 0 -1\n"
      "f 1//1 2//2 3//3\nf 1//1 4//4 2//2\nf 1//1 3//3 4//4\nf 2/5/2 4//4 3//3\n";
  std::istringstream in(text);
  const auto file = read_obj_surface(in, "n.obj");
  ASSERT_EQ(file.normals.size(), 4u);
  EXPECT_NEAR((file.normals[0] - Eigen::Vector3d(0, 0, 1)).norm(), 0, 1e-15);
  EXPECT_NEAR((file.normals[3] - Eigen::Vector3d(0, 0, -1)).norm(), 0, 1e-15);
}

TEST(SurfaceMeshFiles, ObjVertexWithTwoNormalsIsAnErrorWithTheLine) {
  const std::string text =
      "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nvn 0 0 1\nvn 0 1 0\n"
      "f 1//1 2//1 3//1\nf 1//2 4//1 2//1\n";
  std::istringstream in(text);
  const std::string message = iga::test::input_error([&] { read_obj_surface(in, "two.obj"); });
  EXPECT_NE(message.find("two.obj:8:"), std::string::npos) << message;
  EXPECT_NE(message.find("vertex 1 "), std::string::npos) << message;
}

TEST(SurfaceMeshFiles, OffIsRead) {
  const std::string text = "OFF\n4 4 6\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n";
  const auto mesh = surface_mesh_from_file(read_surface_mesh(test::scratch_file("tet.off", text)));
  EXPECT_EQ(mesh.num_triangles(), 4);
  EXPECT_EQ(mesh.triangle_lines[3], 10);
}

TEST(SurfaceMeshFiles, QuadFacesAndUnknownExtensionsAreRejected) {
  std::istringstream quad("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  EXPECT_NE(iga::test::input_error([&] { read_obj_surface(quad, "q.obj"); }).find("q.obj:5: a face with 4 vertices"),
            std::string::npos);
  EXPECT_NE(iga::test::input_error([] { read_surface_mesh("surface.ply"); }).find("unsupported surface mesh format"),
            std::string::npos);
}

TEST(SurfaceMeshValidation, NonManifoldEdgeIsNamed) {
  // Three triangles on the edge (0, 1).
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n";
  const std::string message =
      iga::test::input_error([&] { surface_mesh_from_file(read_surface_mesh(test::scratch_file("nm.obj", text))); });
  EXPECT_NE(message.find("edge (0, 1)"), std::string::npos) << message;
  EXPECT_NE(message.find("shared by 3 triangles"), std::string::npos) << message;
  EXPECT_NE(message.find("vertex 0 (line 1)"), std::string::npos) << message;  // vertex 0 is on line 1
}

TEST(SurfaceMeshValidation, InconsistentOrientationIsNamed) {
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 3 4\n";
  const std::string message =
      iga::test::input_error([&] { surface_mesh_from_file(read_surface_mesh(test::scratch_file("or.obj", text))); });
  EXPECT_NE(message.find("or.obj: edge (1, 2)"), std::string::npos) << message;
  EXPECT_NE(message.find("inconsistent orientation"), std::string::npos) << message;
  EXPECT_NE(message.find("triangle 1 (line 6)"), std::string::npos) << message;  // the second triangle
}

TEST(SurfaceMeshValidation, ZeroAreaTriangleIsNamed) {
  const std::string text = "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 4\nf 2 3 4\nf 1 3 2\n";
  const std::string message =
      iga::test::input_error([&] { surface_mesh_from_file(read_surface_mesh(test::scratch_file("za.obj", text))); });
  EXPECT_NE(message.find("za.obj: triangle 2 (line 7)"), std::string::npos) << message;
  EXPECT_NE(message.find("zero area"), std::string::npos) << message;
}

}  // namespace
}  // namespace iga
