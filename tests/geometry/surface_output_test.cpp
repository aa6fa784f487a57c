// Output of RSD surfaces: the fine sampling with shared points and smooth normals, and its VTK
// file (the Bernstein text format: tests/output/bernstein_patches_test.cpp).
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

}  // namespace
}  // namespace iga::rsd
