#include "output/vtk_writer.hpp"
#include "output/first_failure.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
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

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <stdexcept>

#include "config/progress.hpp"
#include "config/worth_threads.hpp"
#include "output/element_drawing.hpp"
#include "output/point_merger.hpp"
#include "spaces/space.hpp"

namespace iga {

namespace {

vtkSmartPointer<vtkFloatArray> make_field(const std::string& name, int components, vtkIdType tuples) {
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetName(name.c_str());
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}

/// Write an unstructured grid with VTK's XML writer (compressed, appended binary); throws
/// std::runtime_error and removes the file if writing fails.
void write_grid(vtkUnstructuredGrid* grid, const std::string& filename, VtkCompression compression);

}  // namespace

bool write_solution_vtu(const Space& space, const Eigen::VectorXd& coefficients, const VtkFieldOptions& options,
                        const std::string& filename) {
  if (coefficients.size() != space.dimension())
    throw std::invalid_argument("write_solution_vtu: " + std::to_string(coefficients.size()) +
                                " coefficients for a space of dimension " + std::to_string(space.dimension()));
  for (const auto& [name, values] : options.element_fields)
    if (static_cast<int>(values.size()) != space.num_elements())
      throw std::invalid_argument("write_solution_vtu: cell field '" + name + "' has " + std::to_string(values.size()) +
                                  " values for " + std::to_string(space.num_elements()) + " elements");
  const int num_elements = space.num_elements();
  // Ticks: one per element in each of the two evaluation passes (the drawing's points, the fields).
  const ProgressPhase phase("writing VTK", 2 * static_cast<std::int64_t>(num_elements));
  ElementDrawing drawing = draw_elements(space, options.lagrange, options.divisions, options.samples);
  const std::int64_t unmerged = drawing.num_unmerged();
  const std::vector<std::int64_t>& merged_id = drawing.merged_id;
  const std::vector<char>& owner = drawing.owner;
  std::vector<double>& xyz = drawing.xyz;
  const auto num_points = static_cast<vtkIdType>(drawing.num_points);
  FirstFailure failure;

  auto coordinates = make_field("Points", 3, num_points);
  for (std::int64_t p = 0; p < unmerged; ++p)
    if (owner[p]) coordinates->SetTypedTuple(merged_id[p], std::array<float, 3>{float(xyz[3 * p]), float(xyz[3 * p + 1]),
                                                                                 float(xyz[3 * p + 2])}.data());

  // In parallel: the exact solution (and its derivatives, for the element errors) once per
  // distinct point, not once per element sharing it: these expressions are the costly part.
  const bool surface = space.ambient_dimension() == 3;
  const bool has_exact = surface ? static_cast<bool>(options.exact3) : static_cast<bool>(options.exact.u);
  const bool has_gradient = !surface && has_exact && options.exact.has_gradient();
  const bool has_hessian = has_gradient && options.exact.has_hessian();
  const int stride = (has_exact ? 1 : 0) + (has_gradient ? 2 : 0) + (has_hessian ? 3 : 0);
  std::vector<double> exact_at(static_cast<std::size_t>(stride) * num_points);
  if (has_exact && !surface && options.exact.jet) {
    // The batch program over blocks of points (shared subexpressions once per point).
    constexpr std::int64_t block = 1024;
    const auto blocks = static_cast<std::int64_t>((unmerged + block - 1) / block);
#pragma omp parallel if (worth_threads(unmerged))
    {
      Eigen::Matrix2Xd points(2, block);
      std::vector<std::int64_t> ids;
      Eigen::MatrixXd values;
#pragma omp for schedule(dynamic, 4)
      for (std::int64_t b = 0; b < blocks; ++b) {
        try {
          ids.clear();
          for (std::int64_t p = b * block; p < std::min(unmerged, (b + 1) * block); ++p) {
            if (!owner[p]) continue;
            points.col(static_cast<Eigen::Index>(ids.size())) = Eigen::Vector2d(xyz[3 * p], xyz[3 * p + 1]);
            ids.push_back(merged_id[p]);
          }
          const auto n = static_cast<Eigen::Index>(ids.size());
          options.exact.jet(points.leftCols(n), values);
          for (Eigen::Index k = 0; k < n; ++k)
            for (int r = 0; r < stride; ++r) exact_at[static_cast<std::size_t>(stride) * ids[k] + r] = values(r, k);
        } catch (...) {
          failure.keep();
        }
      }
    }
    failure.rethrow();
  } else if (has_exact) {
#pragma omp parallel for schedule(static) if (worth_threads(unmerged))
    for (std::int64_t p = 0; p < unmerged; ++p) {
      if (!owner[p]) continue;
      try {
        double* v = &exact_at[static_cast<std::size_t>(stride) * merged_id[p]];
        const Point2 x(xyz[3 * p], xyz[3 * p + 1]);
        v[0] = surface ? options.exact3(Eigen::Vector3d(xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2])) : options.exact.u(x);
        if (has_gradient) v[1] = options.exact.ux(x), v[2] = options.exact.uy(x);
        if (has_hessian) v[3] = options.exact.uxx(x), v[4] = options.exact.uxy(x), v[5] = options.exact.uyy(x);
      } catch (...) {
        failure.keep();
      }
    }
    failure.rethrow();
  }
  std::vector<double>().swap(xyz);

  // In parallel: the fields. Every merged point is written by its owner alone.
  auto u = make_field("u", 1, num_points);
  auto grad_u = make_field("grad_u", 3, num_points);
  auto normals = make_field(surface ? "Normals" : "warp_normal", 3, num_points);
  vtkSmartPointer<vtkFloatArray> laplace_u, u_exact, error;
  if (options.laplacian) laplace_u = make_field("laplace_u", 1, num_points);
  if (has_exact) u_exact = make_field("u_exact", 1, num_points), error = make_field("error", 1, num_points);
  std::vector<vtkSmartPointer<vtkFloatArray>> further;
  for (const auto& [name, c] : options.point_functions) {
    if (c.size() != space.dimension())
      throw std::invalid_argument("write_solution_vtu: field " + name + " has the wrong length");
    further.push_back(make_field(name, 1, num_points));
  }
  std::vector<vtkSmartPointer<vtkFloatArray>> vectors;
  for (const auto& [name, c] : options.vector_functions) {
    if (c.size() != 3 * space.dimension())
      throw std::invalid_argument("write_solution_vtu: vector field " + name + " has the wrong length");
    vectors.push_back(make_field(name, 3, num_points));
  }
  std::vector<double> element_l2(has_exact ? num_elements : 0), element_h1(has_gradient ? num_elements : 0),
      element_h2(has_hessian ? num_elements : 0);
  const unsigned flags = update_values | update_gradients | (options.laplacian || has_hessian ? update_hessians : 0u);
#pragma omp parallel if (worth_threads(unmerged))
  {
    const std::unique_ptr<Space::Evaluator> evaluator = failure.make_evaluator(space);
    PointValues geometry;
    FunctionValues uh;
#pragma omp for schedule(dynamic, 16)
    for (int e = 0; e < num_elements; ++e) {
      if (!evaluator) continue;
      try {
        progress_tick();
        const std::int64_t first = drawing.offset[e];
        const int q = static_cast<int>(drawing.offset[e + 1] - first);
        for (std::size_t j = 0; j < further.size(); ++j) {
          const Eigen::VectorXd& c = options.point_functions[j].second;
          evaluator->evaluate_function(e, *drawing.rule[e], c, update_values, geometry, uh);
          for (int k = 0; k < q; ++k)
            if (owner[first + k]) further[j]->SetValue(merged_id[first + k], static_cast<float>(uh.value(k)));
        }
        const int n = space.dimension();
        for (std::size_t j = 0; j < vectors.size(); ++j)
          for (int c = 0; c < 3; ++c) {
            const Eigen::VectorXd component = options.vector_functions[j].second.segment(c * n, n);
            evaluator->evaluate_function(e, *drawing.rule[e], component, update_values, geometry, uh);
            for (int k = 0; k < q; ++k)
              if (owner[first + k])
                vectors[j]->SetComponent(merged_id[first + k], c, static_cast<float>(uh.value(k)));
          }
        evaluator->evaluate_function(e, *drawing.rule[e], coefficients, flags, geometry, uh);
        const bool ambient = geometry.x3.cols() == q;
        // Sampled errors of the element: the mean over its drawn points times its area (a map of
        // where the error is; the norms of the convergence table integrate with the error rule).
        double area = 0, sum_l2 = 0, sum_h1 = 0, sum_h2 = 0;
        for (int k = 0; k < q; ++k) {
          const std::int64_t p = merged_id[first + k];
          const bool write = owner[first + k];
          Eigen::Vector3d n;
          if (ambient) {
            const Eigen::Matrix<double, 3, 2>& J = geometry.jacobian3[k];
            const Eigen::Vector3d c = J.col(0).cross(J.col(1));
            area += c.norm();
            n = c.normalized();
          } else {
            area += std::abs(geometry.jacobian[k].determinant());
            n = Eigen::Vector3d(-uh.dx(k), -uh.dy(k), 1.0).normalized();
          }
          const double gz = ambient ? uh.dz(k) : 0.0;
          if (write) {
            u->SetValue(p, static_cast<float>(uh.value(k)));
            grad_u->SetTypedTuple(p, std::array<float, 3>{float(uh.dx(k)), float(uh.dy(k)), float(gz)}.data());
            normals->SetTypedTuple(p, std::array<float, 3>{float(n(0)), float(n(1)), float(n(2))}.data());
            if (laplace_u) laplace_u->SetValue(p, static_cast<float>(uh.dxx(k) + uh.dyy(k)));
          }
          if (!has_exact) continue;
          const double* v = &exact_at[static_cast<std::size_t>(stride) * p];
          const double exact = v[0];
          const double difference = uh.value(k) - exact;
          if (write) {
            u_exact->SetValue(p, static_cast<float>(exact));
            error->SetValue(p, static_cast<float>(difference));
          }
          sum_l2 += difference * difference;
          if (has_gradient) sum_h1 += std::pow(uh.dx(k) - v[1], 2) + std::pow(uh.dy(k) - v[2], 2);
          if (has_hessian)
            sum_h2 += std::pow(uh.dxx(k) - v[3], 2) + 2 * std::pow(uh.dxy(k) - v[4], 2) + std::pow(uh.dyy(k) - v[5], 2);
        }
        if (q > 0) {
          // Mean |det J| times the reference area.
          const double measure = area / q * (space.cell_shape(e) == CellShape::triangle ? 0.5 : 1.0);
          if (has_exact) element_l2[e] = std::sqrt(measure * sum_l2 / q);
          if (has_gradient) element_h1[e] = std::sqrt(measure * sum_h1 / q);
          if (has_hessian) element_h2[e] = std::sqrt(measure * sum_h2 / q);
        }
      } catch (...) {
        failure.keep();
      }
    }
  }
  failure.rethrow();

  const std::vector<int>& cell_element = drawing.cell_element;
  const auto num_cells = static_cast<vtkIdType>(cell_element.size());
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  grid->SetPoints(points);
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkIdTypeArray> cell_offsets, connectivity;
  vtkNew<vtkUnsignedCharArray> cell_types;
  cell_offsets->SetNumberOfValues(static_cast<vtkIdType>(drawing.cell_offsets.size()));
  std::copy(drawing.cell_offsets.begin(), drawing.cell_offsets.end(), cell_offsets->GetPointer(0));
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(drawing.connectivity.size()));
  std::copy(drawing.connectivity.begin(), drawing.connectivity.end(), connectivity->GetPointer(0));
  cell_types->SetNumberOfValues(static_cast<vtkIdType>(drawing.cell_types.size()));
  std::copy(drawing.cell_types.begin(), drawing.cell_types.end(), cell_types->GetPointer(0));
  cells->SetData(cell_offsets, connectivity);
  grid->SetCells(cell_types, cells);
  grid->GetPointData()->SetScalars(u);
  grid->GetPointData()->SetVectors(grad_u);
  if (surface)
    grid->GetPointData()->SetNormals(normals);
  else
    grid->GetPointData()->AddArray(normals);  // not the active normals: Warp By Scalar would warp along them
  if (laplace_u) grid->GetPointData()->AddArray(laplace_u);
  if (u_exact) grid->GetPointData()->AddArray(u_exact), grid->GetPointData()->AddArray(error);
  for (const auto& f : further) grid->GetPointData()->AddArray(f);
  for (const auto& f : vectors) grid->GetPointData()->AddArray(f);

  auto cell_field = [&](const std::string& name, const std::vector<double>& per_element) {
    auto a = make_field(name, 1, num_cells);
    for (vtkIdType c = 0; c < num_cells; ++c) a->SetValue(c, static_cast<float>(per_element[cell_element[c]]));
    grid->GetCellData()->AddArray(a);
  };
  vtkNew<vtkIntArray> element;
  element->SetName("element");
  element->SetNumberOfTuples(num_cells);
  for (vtkIdType c = 0; c < num_cells; ++c) element->SetValue(c, cell_element[c]);
  grid->GetCellData()->AddArray(element);
  if (has_exact) cell_field("error_l2", element_l2);
  if (has_gradient) cell_field("error_h1", element_h1);
  if (has_hessian) cell_field("error_h2", element_h2);
  for (const auto& [name, values] : options.element_fields) cell_field(name, values);
  write_grid(grid, filename, options.compression);
  return drawing.lagrange;
}

void write_mesh_vtu(const Space& space, int samples, const std::string& filename, VtkCompression compression) {
  const int m = std::max(1, samples);
  const int ne = space.num_elements();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();  // an outline to look at: single precision is plenty
  vtkNew<vtkCellArray> lines;
  auto cell_element = vtkSmartPointer<vtkIntArray>::New();
  cell_element->SetName("element");
  const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
  // The closed boundary of the reference cell, m samples per edge (one rule per shape, alive for
  // the whole write: evaluators may cache tables by the rule's address).
  std::map<CellShape, QuadratureRule> outlines;
  for (int e = 0; e < ne; ++e) {
    const CellShape shape = space.cell_shape(e);
    if (outlines.count(shape)) continue;
    QuadratureRule& outline = outlines[shape];
    for (int edge = 0; edge < num_edges(shape); ++edge)
      for (int j = 0; j < m; ++j) {
        outline.points.push_back(reference_edge_point(shape, edge, double(j) / m));
        outline.weights.push_back(0.0);
      }
  }
  // Neighbours share their edge's points (merged to a fraction of the mesh size).
  PointMerger merger(1e-9 * std::max(space.mesh_size(), 1e-300));
  PointValues geometry;
  std::vector<vtkIdType> ids;
  for (int e = 0; e < ne; ++e) {
    const QuadratureRule& outline = outlines.at(space.cell_shape(e));
    evaluator->evaluate_geometry(e, outline, geometry);
    ids.clear();
    for (int k = 0; k < outline.size(); ++k) {
      const Eigen::Vector3d x(geometry.x(0, k), geometry.x(1, k),
                              geometry.x3.cols() == outline.size() ? geometry.x3(2, k) : 0.0);
      bool inserted = false;
      const auto id = static_cast<vtkIdType>(merger.insert(x, inserted));
      if (inserted) points->InsertNextPoint(x.data());
      ids.push_back(id);
    }
    ids.push_back(ids.front());
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    cell_element->InsertNextValue(e);
  }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->SetCells(VTK_POLY_LINE, lines);
  grid->GetCellData()->AddArray(cell_element);
  write_grid(grid, filename, compression);
}

namespace {

void write_grid(vtkUnstructuredGrid* grid, const std::string& filename, VtkCompression compression) {
  // Open the file first: VTK would log a multi-line error of its own for an unwritable path.
  if (!std::ofstream(filename)) throw std::runtime_error("cannot write VTK file '" + filename + "'");
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(filename.c_str());
  writer->SetInputData(grid);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  set_vtk_compression(*writer, compression);
  // 32-bit ids and block headers where they suffice (the defaults are 64-bit).
  if (grid->GetNumberOfPoints() < (vtkIdType(1) << 31) && grid->GetNumberOfCells() < (vtkIdType(1) << 30)) {
    writer->SetIdTypeToInt32();
    writer->SetHeaderTypeToUInt32();
  }
  // VTK 9.1's Write() returns 1 even when the pipeline failed; the error code tells the truth.
  if (writer->Write() != 1 || writer->GetErrorCode() != vtkErrorCode::NoError) {
    if (std::filesystem::is_regular_file(filename)) std::filesystem::remove(filename);  // no half-written output
    throw std::runtime_error("cannot write VTK file '" + filename + "'");
  }
}

}  // namespace

void set_vtk_compression(vtkXMLWriter& writer, VtkCompression compression) {
  // Measured on a 104k-DOF cubic plate (37 MB of fields): LZ4 at acceleration 1 writes in 0.09 s
  // and 38 MB, zlib level 1 in 0.43 s and 25 MB (zlib's higher levels cost more for little).
  switch (compression) {
    case VtkCompression::lz4:
      writer.SetCompressorTypeToLZ4();
      writer.SetCompressionLevel(9);
      break;
    case VtkCompression::zlib:
      writer.SetCompressorTypeToZLib();
      writer.SetCompressionLevel(1);
      break;
    case VtkCompression::none:
      writer.SetCompressorTypeToNone();
      break;
  }
}

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
