// Output of RSD surfaces: the fine sampling with shared points and smooth normals, its VTK file,
// and the text format of the Bézier control points (exact round trip).
#include <gtest/gtest.h>

#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <Eigen/Geometry>
#include <fstream>
#include <sstream>

#include "config/errors.hpp"
#include "geometry/builtin_surface_meshes.hpp"
#include "geometry/rsd/bezier_text_format.hpp"
#include "geometry/rsd/surface_sampling.hpp"
#include "output/surface_vtk.hpp"
#include "tests/support/scratch_files.hpp"

namespace iga::rsd {
namespace {

TEST(SurfaceSampling, SharesPointsAlongEdgesAndKeepsOrientation) {
  const RsdSurface s = build_rsd_surface(icosphere(1), {});
  const int T = 80, V = 42, E = 120;
  for (int sub : {1, 2, 5}) {
    const SampledSurface sampled = sample_surface(s, sub);
    EXPECT_EQ(static_cast<int>(sampled.triangles.size()), T * sub * sub);
    EXPECT_EQ(static_cast<int>(sampled.points.size()), V + E * (sub - 1) + T * (sub - 1) * (sub - 2) / 2);
    for (std::size_t n = 0; n < sampled.triangles.size(); ++n) {
      const auto& t = sampled.triangles[n];
      const Eigen::Vector3d facet =
          (sampled.points[t[1]] - sampled.points[t[0]]).cross(sampled.points[t[2]] - sampled.points[t[0]]);
      EXPECT_GT(facet.dot(sampled.points[t[0]]), 0) << "sub-triangle " << n << " faces inward";
    }
    for (std::size_t v = 0; v < sampled.points.size(); ++v)
      EXPECT_GT(sampled.normals[v].dot(sampled.points[v].normalized()), std::cos(4.0 * M_PI / 180));
  }
}

TEST(SurfaceVtk, WritesPointsCellsAndNormals) {
  const SampledSurface sampled = sample_surface(build_rsd_surface(perturbed_octahedron(), {}), 4);
  const std::string path = (test::scratch_folder() / "surface.vtu").string();
  write_surface_vtu(sampled.points, sampled.normals, sampled.triangles, sampled.patch, path);
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  EXPECT_EQ(grid->GetNumberOfPoints(), static_cast<vtkIdType>(sampled.points.size()));
  EXPECT_EQ(grid->GetNumberOfCells(), 8 * 16);
  ASSERT_NE(grid->GetPointData()->GetNormals(), nullptr);
  EXPECT_EQ(grid->GetPointData()->GetNormals()->GetNumberOfComponents(), 3);
  EXPECT_THROW(write_surface_vtu(sampled.points, sampled.normals, sampled.triangles, sampled.patch,
                                 "/nonexistent-folder/surface.vtu"),
               std::runtime_error);
}

TEST(BezierTextFormat, RoundTripIsExact) {
  const RsdSurface s = build_rsd_surface(height_field(), {RsdTuple::pi1, RsdMethod::hermite});
  std::stringstream file;
  write_bezier_patches(file, bezier_patches_of(s), "height field, pi1");
  const BezierPatchSet back = read_bezier_patches(file, "patches.txt");
  ASSERT_EQ(back.patches.size(), s.patches.size());
  for (std::size_t n = 0; n < s.patches.size(); ++n) {
    EXPECT_EQ(back.patches[n].degree, 9);
    EXPECT_EQ(back.vertices[n], s.mesh.triangles[n]);
    for (std::size_t c = 0; c < s.patches[n].control.size(); ++c)
      EXPECT_EQ(back.patches[n].control[c], s.patches[n].control[c]);
  }
}

TEST(BezierTextFormat, MalformedFilesNameTheLine) {
  std::istringstream short_file("iga-run-bezier-triangles 1\ndegree 1\npatches 1\npatch 0 0 1 2\n0 0 0\n1 0 x\n");
  try {
    read_bezier_patches(short_file, "p.txt");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("p.txt:6: expected a control point"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace iga::rsd
