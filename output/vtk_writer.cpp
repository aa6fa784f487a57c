#include "output/vtk_writer.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkIdTypeArray.h>
#include <vtkIndent.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <stdexcept>

#include "spaces/space.hpp"

namespace iga {

namespace {

/// The sampled elements laid out as one point/cell list: element e owns points
/// [point_offset[e], point_offset[e+1]) and is evaluated at the reference points of *rule[e].
struct SampleLayout {
  std::vector<vtkIdType> point_offset;
  std::vector<const QuadratureRule*> rule;
  /// Rules by point coordinates. Evaluators may cache tables keyed by a rule's address, so every
  /// distinct set of sample points gets its own rule, alive (and at a fixed address) for the whole write.
  std::map<std::vector<double>, std::shared_ptr<QuadratureRule>> rules;
};

/// The rule whose points are `points` (zero weights: only values are needed).
const QuadratureRule* sample_rule(SampleLayout& layout, const std::vector<Point2>& points) {
  std::vector<double> key;
  key.reserve(2 * points.size());
  for (const Point2& p : points) key.insert(key.end(), {p.x(), p.y()});
  auto [it, inserted] = layout.rules.try_emplace(std::move(key));
  if (inserted) {
    auto rule = std::make_shared<QuadratureRule>();
    rule->points = points;
    rule->weights.assign(points.size(), 0.0);
    it->second = std::move(rule);
  }
  return it->second.get();
}

vtkNew<vtkDoubleArray> make_point_field(const char* name, int components, vtkIdType num_points) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(num_points);
  return a;
}

/// Write an unstructured grid with VTK's XML writer (LZ4-compressed, appended binary); throws
/// std::runtime_error and removes the file if writing fails.
void write_grid(vtkUnstructuredGrid* grid, const std::string& filename);

}  // namespace

void write_solution_vtu(const Space& space, const Eigen::VectorXd& coefficients, const VtkFieldOptions& options,
                        const std::string& filename) {
  if (coefficients.size() != space.dimension())
    throw std::invalid_argument("write_solution_vtu: " + std::to_string(coefficients.size()) +
                                " coefficients for a space of dimension " + std::to_string(space.dimension()));
  const int num_elements = space.num_elements();

  // Pass 1 (serial, cheap): sample cells, point offsets and the linear sub-cells.
  SampleLayout layout;
  layout.point_offset.assign(num_elements + 1, 0);
  layout.rule.resize(num_elements);
  vtkNew<vtkIdTypeArray> cell_offsets, connectivity;
  vtkNew<vtkUnsignedCharArray> cell_types;
  vtkNew<vtkIntArray> cell_element;
  cell_element->SetName("element");
  cell_offsets->InsertNextValue(0);
  for (int e = 0; e < num_elements; ++e) {
    const SampleCell sample = space.sample_cell(e, options.samples);
    const vtkIdType base = layout.point_offset[e];
    const auto num_points = static_cast<vtkIdType>(sample.points.size());
    for (const std::vector<int>& cell : sample.cells) {
      if (cell.size() != 3 && cell.size() != 4)
        throw std::logic_error("write_solution_vtu: sample cell of element " + std::to_string(e) + " has " +
                               std::to_string(cell.size()) + " vertices (3 or 4 expected)");
      for (int v : cell) {
        if (v < 0 || v >= num_points)
          throw std::logic_error("write_solution_vtu: sample cell of element " + std::to_string(e) +
                                 " refers to point " + std::to_string(v));
        connectivity->InsertNextValue(base + v);
      }
      cell_offsets->InsertNextValue(connectivity->GetNumberOfTuples());
      cell_types->InsertNextValue(cell.size() == 3 ? VTK_TRIANGLE : VTK_QUAD);
      cell_element->InsertNextValue(e);
    }
    layout.point_offset[e + 1] = base + num_points;
    layout.rule[e] = sample_rule(layout, sample.points);
  }
  const vtkIdType num_points = layout.point_offset[num_elements];

  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(num_points);
  auto u = make_point_field("u", 1, num_points);
  auto grad_u = make_point_field("grad_u", 3, num_points);
  vtkNew<vtkDoubleArray> laplace_u;
  if (options.laplacian) {
    laplace_u->SetName("laplace_u");
    laplace_u->SetNumberOfTuples(num_points);
  }
  double* const xyz = coordinates->GetPointer(0);
  double* const u_ptr = u->GetPointer(0);
  double* const grad_ptr = grad_u->GetPointer(0);
  double* const laplace_ptr = options.laplacian ? laplace_u->GetPointer(0) : nullptr;

  // Pass 2: evaluate element by element. Elements write disjoint point ranges, so threads need no
  // synchronisation beyond one Evaluator each; an exception is carried out of the parallel region.
  const unsigned flags = update_values | update_gradients | (options.laplacian ? update_hessians : 0u);
  std::exception_ptr failure;
#pragma omp parallel if (num_elements > 1)
  {
    std::unique_ptr<Space::Evaluator> evaluator;
    try {
      evaluator = space.make_evaluator();
    } catch (...) {
#pragma omp critical(iga_vtk_failure)
      if (!failure) failure = std::current_exception();
    }
    PointValues geometry;
    FunctionValues uh;
#pragma omp for schedule(dynamic, 8)
    for (int e = 0; e < num_elements; ++e) {
      if (!evaluator) continue;
      try {
        evaluator->evaluate_function(e, *layout.rule[e], coefficients, flags, geometry, uh);
        const vtkIdType first = layout.point_offset[e];
        const int q = static_cast<int>(layout.point_offset[e + 1] - first);
        if (geometry.num_points() != q)
          throw std::logic_error("write_solution_vtu: element " + std::to_string(e) + " evaluated at " +
                                 std::to_string(geometry.num_points()) + " points instead of " + std::to_string(q));
        for (int k = 0; k < q; ++k) {
          const vtkIdType p = first + k;
          xyz[3 * p] = geometry.x(0, k);
          xyz[3 * p + 1] = geometry.x(1, k);
          xyz[3 * p + 2] = 0.0;
          u_ptr[p] = uh.value(k);
          grad_ptr[3 * p] = uh.dx(k);
          grad_ptr[3 * p + 1] = uh.dy(k);
          grad_ptr[3 * p + 2] = 0.0;
        }
        if (geometry.x3.cols() == q)  // a surface in 3D: ambient points, surface gradient
          for (int k = 0; k < q; ++k) {
            const vtkIdType p = first + k;
            xyz[3 * p + 2] = geometry.x3(2, k);
            grad_ptr[3 * p + 2] = uh.dz(k);
          }
        if (laplace_ptr)
          for (int k = 0; k < q; ++k) laplace_ptr[first + k] = uh.dxx(k) + uh.dyy(k);
      } catch (...) {
#pragma omp critical(iga_vtk_failure)
        if (!failure) failure = std::current_exception();
      }
    }
  }
  if (failure) std::rethrow_exception(failure);

  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  grid->SetPoints(points);
  vtkNew<vtkCellArray> cells;
  cells->SetData(cell_offsets, connectivity);
  grid->SetCells(cell_types, cells);
  grid->GetPointData()->SetScalars(u);
  grid->GetPointData()->SetVectors(grad_u);
  if (options.exact || options.exact3) {
    // The exact solution is thread-safe (VtkFieldOptions::exact), so points are split over threads.
    auto u_exact = make_point_field("u_exact", 1, num_points);
    auto error = make_point_field("error", 1, num_points);
#pragma omp parallel for schedule(static)
    for (vtkIdType p = 0; p < num_points; ++p) {
      const double exact = options.exact3 ? options.exact3(Eigen::Vector3d(xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2]))
                                          : options.exact(Point2(xyz[3 * p], xyz[3 * p + 1]));
      u_exact->SetValue(p, exact);
      error->SetValue(p, u_ptr[p] - exact);
    }
    grid->GetPointData()->AddArray(u_exact);
    grid->GetPointData()->AddArray(error);
  }
  if (options.laplacian) grid->GetPointData()->AddArray(laplace_u);
  grid->GetCellData()->AddArray(cell_element);
  write_grid(grid, filename);
}

void write_mesh_vtu(const Space& space, int samples, const std::string& filename) {
  const int m = std::max(1, samples);
  const int ne = space.num_elements();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  auto cell_element = vtkSmartPointer<vtkIntArray>::New();
  cell_element->SetName("element");
  const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
  PointValues geometry;
  std::vector<vtkIdType> ids;
  for (int e = 0; e < ne; ++e) {
    // The closed boundary of the reference cell, m samples per edge, mapped like the solution.
    const CellShape shape = space.cell_shape(e);
    QuadratureRule outline;
    for (int edge = 0; edge < num_edges(shape); ++edge)
      for (int j = 0; j < m; ++j) {
        outline.points.push_back(reference_edge_point(shape, edge, double(j) / m));
        outline.weights.push_back(0.0);
      }
    evaluator->evaluate_geometry(e, outline, geometry);
    ids.clear();
    for (int k = 0; k < outline.size(); ++k)
      ids.push_back(points->InsertNextPoint(geometry.x(0, k), geometry.x(1, k),
                                            geometry.x3.cols() == outline.size() ? geometry.x3(2, k) : 0.0));
    ids.push_back(ids.front());
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    cell_element->InsertNextValue(e);
  }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->SetCells(VTK_POLY_LINE, lines);
  grid->GetCellData()->AddArray(cell_element);
  write_grid(grid, filename);
}

namespace {

void write_grid(vtkUnstructuredGrid* grid, const std::string& filename) {
  // Open the file first: VTK would log a multi-line error of its own for an unwritable path.
  if (!std::ofstream(filename)) throw std::runtime_error("cannot write VTK file '" + filename + "'");
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(filename.c_str());
  writer->SetInputData(grid);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToLZ4();  // several times faster than zlib; ParaView reads it
  // VTK 9.1's Write() returns 1 even when the pipeline failed; the error code tells the truth.
  if (writer->Write() != 1 || writer->GetErrorCode() != vtkErrorCode::NoError) {
    if (std::filesystem::is_regular_file(filename)) std::filesystem::remove(filename);  // no half-written output
    throw std::runtime_error("cannot write VTK file '" + filename + "'");
  }
}

}  // namespace

void write_pvd(const std::vector<std::string>& datasets, const std::string& filename) {
  vtkNew<vtkXMLDataElement> root;
  root->SetName("VTKFile");
  root->SetAttribute("type", "Collection");
  root->SetAttribute("version", "0.1");
  root->SetAttribute("byte_order", "LittleEndian");
  vtkNew<vtkXMLDataElement> collection;
  collection->SetName("Collection");
  for (std::size_t i = 0; i < datasets.size(); ++i) {
    vtkNew<vtkXMLDataElement> dataset;
    dataset->SetName("DataSet");
    dataset->SetIntAttribute("timestep", static_cast<int>(i));
    dataset->SetIntAttribute("part", 0);
    dataset->SetAttribute("file", datasets[i].c_str());
    collection->AddNestedElement(dataset);
  }
  root->AddNestedElement(collection);

  // PrintXML(filename) reports no errors, so write through a stream we can check.
  std::ofstream os(filename);
  if (!os) throw std::runtime_error("cannot write ParaView collection '" + filename + "'");
  os << "<?xml version=\"1.0\"?>\n";
  root->PrintXML(os, vtkIndent());
  os.close();
  if (!os) throw std::runtime_error("cannot write ParaView collection '" + filename + "'");
}

}  // namespace iga
