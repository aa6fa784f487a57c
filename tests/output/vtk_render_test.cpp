/// @file
/// The quickstart's ParaView output rendered off-screen with VTK (as a user would look at it):
/// level 2's solution.vtu (cubic Lagrange cells) through VTK's nonlinear subdivision, warped by u
/// and coloured by u, written to a PNG whose pixels are then checked: the surface fills a good part
/// of the image, and its colours span the field's range (both ends of the colour map appear).
/// Debian's VTK renders through X only: ctest runs this under xvfb-run (registered when found).

#include <gtest/gtest.h>
#include <vtkCamera.h>
#include <vtkDataSetMapper.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWarpScalar.h>
#include <vtkWindowToImageFilter.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cstdlib>
#include <filesystem>

#include "tests/support/test_support.hpp"

namespace iga {
namespace {

TEST(VtkRender, QuickstartLevelWarpedByULooksLikeTheSolution) {
  const std::string config = std::string(IGA_SOURCE_DIR) + "/configs/quickstart.yaml";
  const std::string dir = (test::scratch_folder() / "render").string();
  const StudySettings settings = parse_study(ConfigNode::load_file(config), config, 3, dir);
  std::filesystem::create_directories(dir);
  run_study_with_vtk(settings, dir, [](const std::string&) {});
  const std::string vtu = dir + "/solution_2.vtu";
  ASSERT_TRUE(std::filesystem::exists(vtu));

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(vtu.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  ASSERT_EQ(grid->GetNumberOfCells(), 256);
  grid->GetPointData()->SetActiveScalars("u");
  double range[2];
  grid->GetPointData()->GetArray("u")->GetRange(range);
  ASSERT_LT(range[0], -0.9);  // sin(πx) sin(2πy)
  ASSERT_GT(range[1], 0.9);

  // Lagrange cells drawn as ParaView does: subdivided into linear triangles, then warped.
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(grid);
  surface->SetNonlinearSubdivisionLevel(3);
  vtkNew<vtkWarpScalar> warp;
  warp->SetInputConnection(surface->GetOutputPort());
  warp->SetScaleFactor(0.3);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(warp->GetOutputPort());
  vtkNew<vtkDataSetMapper> mapper;
  mapper->SetInputConnection(normals->GetOutputPort());
  mapper->SetScalarRange(range);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(0.4);
  actor->GetProperty()->SetDiffuse(0.6);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(1.0, 1.0, 1.0);
  // Looking down at the unit square from the front left, z up.
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.5, 0.5, 0.0);
  camera->SetPosition(-0.3, -1.0, 1.6);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();
  camera->Zoom(1.4);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(400, 300);
  window->Render();
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->Update();
  const std::string png = dir + "/quickstart-level2.png";
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(png.c_str());
  writer->SetInputConnection(capture->GetOutputPort());
  writer->Write();
  // IGA_RENDER_PNG=path keeps a copy of the image to look at (the scratch folder is removed).
  if (const char* keep = std::getenv("IGA_RENDER_PNG"))
    std::filesystem::copy_file(png, keep, std::filesystem::copy_options::overwrite_existing);

  // The pixels as written to the file.
  vtkNew<vtkPNGReader> image_reader;
  image_reader->SetFileName(png.c_str());
  image_reader->Update();
  vtkImageData* image = image_reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  ASSERT_EQ(dims[0], 400);
  ASSERT_EQ(dims[1], 300);
  auto* pixels = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  ASSERT_NE(pixels, nullptr);
  const int channels = pixels->GetNumberOfComponents();
  ASSERT_GE(channels, 3);
  long surface_pixels = 0, reddish = 0, bluish = 0, greenish = 0;
  const long total = static_cast<long>(dims[0]) * dims[1];
  for (long i = 0; i < total; ++i) {
    const int r = pixels->GetValue(i * channels), g = pixels->GetValue(i * channels + 1),
              b = pixels->GetValue(i * channels + 2);
    if (r == 255 && g == 255 && b == 255) continue;  // background
    ++surface_pixels;
    // VTK's default colour map runs from red (u = min) to blue (u = max).
    if (r > 2 * b + 40 && r > 2 * g) ++reddish;
    if (b > 2 * r + 40 && b > g) ++bluish;
    if (g > 2 * r + 40 && g > 2 * b + 40) ++greenish;  // u near 0: the band along the boundary
  }
  std::printf("surface %.3f of the image; of the surface: red %.3f, blue %.3f, green %.3f\n",
              static_cast<double>(surface_pixels) / total, static_cast<double>(reddish) / surface_pixels,
              static_cast<double>(bluish) / surface_pixels, static_cast<double>(greenish) / surface_pixels);
  EXPECT_GT(surface_pixels, total / 4) << "the surface should fill a good part of the image";
  EXPECT_LT(surface_pixels, total * 9 / 10) << "little background left: not a view of the whole surface";
  // Both ends of the colour map and its middle appear: the colours span the field (the trough,
  // partly behind the crest in this view, shows less).
  EXPECT_GT(reddish, surface_pixels / 100);
  EXPECT_GT(bluish, surface_pixels / 20);
  EXPECT_GT(greenish, surface_pixels / 10);
}

}  // namespace
}  // namespace iga
