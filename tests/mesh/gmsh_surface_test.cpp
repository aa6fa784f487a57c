// Triangle meshes in 3D made or read by Gmsh (.geo, .msh, .stl) through the worker: a meshed
// OpenCASCADE torus is closed with Euler characteristic 0, the same triangles come back from a
// .msh and from ASCII and binary STL, Gmsh's independently oriented surface entities are made to
// agree, and broken files are refused with the file (and line or Gmsh tag) named.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "geometry/rsd/rsd_surface.hpp"
#include "geometry/triangle_surface_mesh.hpp"
#include "mesh/read_surface_mesh.hpp"
#include "mesh/stl_structure_check.hpp"
#include "tests/support/input_error.hpp"
#include "tests/support/scratch_files.hpp"

namespace iga {
namespace {

const std::string source_dir = IGA_SOURCE_DIR;
using test::input_error;

SurfaceMeshFile torus() { return read_surface_mesh(source_dir + "/configs/domains/torus.geo"); }

/// V − E + F of a mesh (0 for a torus, 2 for a sphere).
long euler_characteristic(const SurfaceMeshFile& m) {
  std::set<std::pair<int, int>> edges;
  for (const auto& t : m.triangles)
    for (int c = 0; c < 3; ++c) edges.insert(std::minmax(t[c], t[(c + 1) % 3]));
  return static_cast<long>(m.points.size()) - static_cast<long>(edges.size()) + static_cast<long>(m.triangles.size());
}

std::string as_msh22(const SurfaceMeshFile& m, const std::vector<int>& entity) {
  std::ostringstream s;
  s.precision(17);
  s << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << m.points.size() << "\n";
  for (std::size_t v = 0; v < m.points.size(); ++v)
    s << v + 1 << " " << m.points[v].x() << " " << m.points[v].y() << " " << m.points[v].z() << "\n";
  s << "$EndNodes\n$Elements\n" << m.triangles.size() << "\n";
  for (std::size_t n = 0; n < m.triangles.size(); ++n)
    s << n + 1 << " 2 2 " << entity[n] << " " << entity[n] << " " << m.triangles[n][0] + 1 << " "
      << m.triangles[n][1] + 1 << " " << m.triangles[n][2] + 1 << "\n";
  s << "$EndElements\n";
  return s.str();
}

std::string as_ascii_stl(const SurfaceMeshFile& m) {
  std::ostringstream s;
  s.precision(17);
  s << "solid torus\n";
  for (const auto& t : m.triangles) {
    s << " facet normal 0 0 0\n  outer loop\n";
    for (int v : t) s << "   vertex " << m.points[v].x() << " " << m.points[v].y() << " " << m.points[v].z() << "\n";
    s << "  endloop\n endfacet\n";
  }
  s << "endsolid torus\n";
  return s.str();
}

std::string as_binary_stl(const SurfaceMeshFile& m) {
  std::string s(80, ' ');
  const auto put = [&](auto value) { s.append(reinterpret_cast<const char*>(&value), sizeof value); };
  put(static_cast<std::uint32_t>(m.triangles.size()));
  for (const auto& t : m.triangles) {
    for (int k = 0; k < 3; ++k) put(0.0f);
    for (int v : t)
      for (int k = 0; k < 3; ++k) put(static_cast<float>(m.points[v](k)));
    put(std::uint16_t{0});
  }
  return s;
}

TEST(GmshSurface, TheOpenCascadeTorusIsAClosedOrientedSurfaceOfGenusOne) {
  const SurfaceMeshFile m = torus();
  EXPECT_GT(m.triangles.size(), 200u);
  EXPECT_EQ(euler_characteristic(m), 0);
  ASSERT_EQ(m.point_origins.size(), m.points.size());
  EXPECT_EQ(m.triangle_origins[0].rfind("Gmsh element ", 0), 0u);
  // Every vertex lies on the torus (R = 1, r = 0.4), and surface_edges finds every edge twice
  // and in opposite directions (it throws otherwise).
  for (const auto& x : m.points) EXPECT_NEAR(std::hypot(std::hypot(x.x(), x.y()) - 1.0, x.z()), 0.4, 1e-9);
  const TriangleSurfaceMesh mesh = surface_mesh_from_file(m);
  for (const SurfaceEdge& e : surface_edges(mesh)) EXPECT_TRUE(e.interior());
  // Angle-weighted normals point away from the core circle.
  for (int v = 0; v < mesh.num_points(); ++v) {
    const Eigen::Vector3d x = mesh.points[v];
    const Eigen::Vector3d core = Eigen::Vector3d(x.x(), x.y(), 0).normalized();
    EXPECT_GT(mesh.normals[v].dot((x - core).normalized()), 0.9);
  }
}

TEST(GmshSurface, EllipsoidAndFilletedBoxGiveG1SurfacesOfGenusZero) {
  // The filleted box has 26 surface entities (faces, fillets, corners) that Gmsh orients each
  // its own way; the ellipsoid is one stretched entity with a seam.
  for (const char* name : {"ellipsoid.geo", "filleted_box.geo"}) {
    SCOPED_TRACE(name);
    const SurfaceMeshFile m = read_surface_mesh(source_dir + "/configs/domains/" + name);
    EXPECT_EQ(euler_characteristic(m), 2);
    const rsd::RsdSurface s = rsd::build_rsd_surface(surface_mesh_from_file(m));
    EXPECT_EQ(s.report.boundary_edges, 0);
    EXPECT_LT(s.report.max_g1_residual, 1e-12);
    EXPECT_LT(s.report.max_fold_alpha, 0.0);
    EXPECT_GT(s.report.min_regularity, 0.1);
  }
}

TEST(GmshSurface, MshAndStlFilesGiveTheSameTriangles) {
  const SurfaceMeshFile m = torus();
  const std::vector<int> one_entity(m.triangles.size(), 1);
  for (const std::string& path : {test::scratch_file("torus.msh", as_msh22(m, one_entity)),
                                  test::scratch_file("torus.stl", as_ascii_stl(m)),
                                  test::scratch_file("torus_binary.stl", as_binary_stl(m))}) {
    SCOPED_TRACE(path);
    const SurfaceMeshFile back = read_surface_mesh(path);
    ASSERT_EQ(back.triangles.size(), m.triangles.size());
    EXPECT_EQ(back.points.size(), m.points.size());  // STL: Gmsh merges the repeated corners
    EXPECT_EQ(euler_characteristic(back), 0);
    EXPECT_NO_THROW(surface_mesh_from_file(back));
  }
}

TEST(GmshSurface, EntitiesOrientedAgainstEachOtherAreMadeToAgree) {
  // The torus's triangles in two entities, the second one listed clockwise: Gmsh files may orient
  // every surface entity its own way.
  SurfaceMeshFile m = torus();
  std::vector<int> entity(m.triangles.size(), 1);
  for (std::size_t n = 0; n < m.triangles.size(); ++n)
    if (m.points[m.triangles[n][0]].x() > 0.0) {
      entity[n] = 2;
      std::swap(m.triangles[n][1], m.triangles[n][2]);
    }
  const SurfaceMeshFile back = read_surface_mesh(test::scratch_file("two_entities.msh", as_msh22(m, entity)));
  EXPECT_NO_THROW(surface_mesh_from_file(back));
}

TEST(GmshSurface, InconsistentTrianglesOfOneEntityAreAnInputErrorNamingGmshTags) {
  SurfaceMeshFile m = torus();
  std::swap(m.triangles[5][1], m.triangles[5][2]);
  const SurfaceMeshFile back =
      read_surface_mesh(test::scratch_file("flipped.msh", as_msh22(m, std::vector<int>(m.triangles.size(), 1))));
  const std::string message = input_error([&] { surface_mesh_from_file(back); });
  EXPECT_NE(message.find("inconsistent orientation"), std::string::npos) << message;
  EXPECT_NE(message.find("Gmsh node"), std::string::npos) << message;
  EXPECT_NE(message.find("Gmsh element 6"), std::string::npos) << message;
}

TEST(GmshSurface, BrokenStlFilesAreRefusedBeforeGmshReadsThem) {
  const SurfaceMeshFile m = torus();
  std::string binary = as_binary_stl(m);
  const std::string truncated = test::scratch_file("truncated.stl", binary.substr(0, binary.size() - 7));
  EXPECT_NE(input_error([&] { read_surface_mesh(truncated); }).find("neither binary STL"), std::string::npos);
  std::string ascii = as_ascii_stl(m);
  ascii.erase(ascii.find("  endloop\n"), 10);  // the first facet loses its endloop
  const std::string broken = test::scratch_file("broken.stl", ascii);
  const std::string message = input_error([&] { read_surface_mesh(broken); });
  EXPECT_NE(message.find("broken.stl:7: expected 'endloop'"), std::string::npos) << message;
  const std::string nan = test::scratch_file("nan.stl", "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                                                        "vertex nan 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid a\n");
  EXPECT_NE(input_error([&] { read_surface_mesh(nan); }).find("nan.stl:5"), std::string::npos);
  MeshLimits limits;
  limits.max_elements = 10;
  EXPECT_NE(input_error([&] { check_stl_structure(test::scratch_file("big.stl", binary), limits); }).find("more than the limit"),
            std::string::npos);
}

TEST(GmshSurface, ARecombinedSurfaceIsRefusedNamingTheElementType) {
  const std::string geo = test::scratch_file("quads.geo",
                                             "SetFactory(\"OpenCASCADE\");\nSphere(1) = {0, 0, 0, 1};\n"
                                             "Mesh.MeshSizeMax = 0.5;\nMesh.RecombineAll = 1;\n");
  const std::string message = input_error([&] { read_surface_mesh(geo); });
  EXPECT_NE(message.find("only 3-node triangles"), std::string::npos) << message;
}

}  // namespace
}  // namespace iga
