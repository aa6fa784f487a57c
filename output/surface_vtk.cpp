#include "output/surface_vtk.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace iga {

void write_surface_vtu(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& normals,
                       const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& patch,
                       const std::string& filename) {
  if (normals.size() != points.size() || patch.size() != triangles.size())
    throw std::logic_error("write_surface_vtu: one normal per point and one patch per triangle are required");
  vtkNew<vtkPoints> coordinates;
  coordinates->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> normal_field;
  normal_field->SetName("Normals");
  normal_field->SetNumberOfComponents(3);
  for (std::size_t v = 0; v < points.size(); ++v) {
    coordinates->InsertNextPoint(points[v].data());
    normal_field->InsertNextTuple(normals[v].data());
  }
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  vtkNew<vtkUnsignedCharArray> types;
  vtkNew<vtkIntArray> patch_field;
  patch_field->SetName("patch");
  offsets->InsertNextValue(0);
  for (std::size_t n = 0; n < triangles.size(); ++n) {
    for (int v : triangles[n]) {
      if (v < 0 || v >= static_cast<int>(points.size()))
        throw std::logic_error("write_surface_vtu: triangle " + std::to_string(n) + " names point " + std::to_string(v));
      connectivity->InsertNextValue(v);
    }
    offsets->InsertNextValue(connectivity->GetNumberOfTuples());
    types->InsertNextValue(VTK_TRIANGLE);
    patch_field->InsertNextValue(patch[n]);
  }
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(coordinates);
  grid->SetCells(types, cells);
  grid->GetPointData()->SetNormals(normal_field);
  grid->GetCellData()->AddArray(patch_field);

  if (!std::ofstream(filename)) throw std::runtime_error("cannot write VTK file '" + filename + "'");
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(filename.c_str());
  writer->SetInputData(grid);
  writer->SetDataModeToAppended();
  // VTK 9.1's Write() returns 1 even when the pipeline failed; the error code tells the truth.
  if (writer->Write() != 1 || writer->GetErrorCode() != vtkErrorCode::NoError) {
    std::error_code ignored;
    std::filesystem::remove(filename, ignored);
    throw std::runtime_error("cannot write VTK file '" + filename + "'");
  }
}

}  // namespace iga
