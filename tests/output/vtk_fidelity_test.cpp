/// @file
/// The VTK files of real spaces, read back with VTK's own reader: polynomial elements become one
/// Lagrange cell each whose interpolation reproduces the discrete function (to single precision)
/// anywhere in the element, points are shared (no two points coincide), macro-elements are drawn
/// by one Lagrange cell of the space's degree each (or, asked for, by shared-point linear
/// sub-cells), and surfaces in 3D carry normals.

#include <gtest/gtest.h>
#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <set>
#include <tuple>

#include "output/lagrange_cells.hpp"
#include "output/vtk_writer.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const std::string& file) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  return reader->GetOutput();
}

/// Number of distinct point positions (rounded far below any mesh size of these tests).
std::size_t distinct_points(vtkUnstructuredGrid* grid) {
  std::set<std::tuple<long long, long long, long long>> seen;
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p) {
    double x[3];
    grid->GetPoint(p, x);
    seen.emplace(std::llround(x[0] * 1e5), std::llround(x[1] * 1e5), std::llround(x[2] * 1e5));
  }
  return seen.size();
}

Eigen::VectorXd random_coefficients(int n) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> dist(-1.0, 1.0);
  Eigen::VectorXd c(n);
  for (int i = 0; i < n; ++i) c(i) = dist(rng);
  return c;
}

TEST(VtkFidelity, BsplineElementsAreLagrangeCellsThatReproduceTheFunction) {
  const SpacePtr space = test::space_from_yaml(
      "domain: {type: rectangle, min: [0, 0], max: [2, 1]}\n"
      "space: {type: bspline, degree: 3, regularity: 2, elements: [5, 3]}\n");
  ASSERT_TRUE(elements_are_polynomial(*space, 3));
  const Eigen::VectorXd c = random_coefficients(space->dimension());
  const std::string file = (test::scratch_folder() / "bspline.vtu").string();
  ASSERT_TRUE(write_solution_vtu(*space, c, {}, file));
  const auto grid = read_vtu(file);
  ASSERT_EQ(grid->GetNumberOfCells(), 15);
  // Shared nodes: a (3*5+1) x (3*3+1) lattice, each point once.
  ASSERT_EQ(grid->GetNumberOfPoints(), 16 * 10);
  EXPECT_EQ(distinct_points(grid), 160u);
  vtkDataArray* u = grid->GetPointData()->GetArray("u");
  ASSERT_NE(u, nullptr);
  ASSERT_NE(grid->GetPointData()->GetArray("warp_normal"), nullptr);
  const double scale = c.cwiseAbs().maxCoeff();

  // At points off the nodes, VTK's interpolation of the cell equals u_h evaluated by the space.
  const std::unique_ptr<Space::Evaluator> evaluator = space->make_evaluator();
  QuadratureRule probe;
  probe.points = {{0.137, 0.861}, {0.5, 0.5}, {0.913, 0.271}};
  probe.weights.assign(3, 0.0);
  PointValues geometry;
  FunctionValues uh;
  std::vector<double> weights(16);
  for (vtkIdType cell = 0; cell < grid->GetNumberOfCells(); ++cell) {
    ASSERT_EQ(grid->GetCellType(cell), VTK_LAGRANGE_QUADRILATERAL);
    vtkCell* vc = grid->GetCell(cell);
    ASSERT_EQ(vc->GetNumberOfPoints(), 16);
    evaluator->evaluate_function(static_cast<int>(cell), probe, c, update_values, geometry, uh);
    for (int k = 0; k < probe.size(); ++k) {
      double pcoords[3] = {probe.points[k].x(), probe.points[k].y(), 0.0}, x[3];
      int sub_id = 0;
      vc->EvaluateLocation(sub_id, pcoords, x, weights.data());
      double value = 0;
      for (int i = 0; i < 16; ++i) value += weights[i] * u->GetComponent(vc->GetPointId(i), 0);
      EXPECT_NEAR(x[0], geometry.x(0, k), 1e-6);
      EXPECT_NEAR(x[1], geometry.x(1, k), 1e-6);
      // Single-precision nodal values, amplified by the Lebesgue constant of cubic interpolation (< 3).
      EXPECT_NEAR(value, uh.value(k), 1e-5 * scale) << "cell " << cell << " probe " << k;
    }
  }
}

TEST(VtkFidelity, MacroElementsAreOneLagrangeTriangleEachByDefault) {
  const SpacePtr space = test::space_from_yaml("domain: {type: unit_square}\nspace: {type: ws4, elements: 2}\n", 1);
  const Eigen::VectorXd c = random_coefficients(space->dimension());
  const std::string file = (test::scratch_folder() / "ws4_lagrange.vtu").string();
  ASSERT_FALSE(write_solution_vtu(*space, c, VtkFieldOptions{}, file));  // not single polynomials
  const auto grid = read_vtu(file);
  ASSERT_EQ(grid->GetNumberOfCells(), space->num_elements());
  for (vtkIdType cell = 0; cell < grid->GetNumberOfCells(); ++cell) {
    EXPECT_EQ(grid->GetCellType(cell), VTK_LAGRANGE_TRIANGLE);
    EXPECT_EQ(grid->GetCell(cell)->GetNumberOfPoints(), 15);  // quartic
  }
  // Quartic nodes shared: one per vertex, 3 per edge, 3 inside each triangle.
  int vertices = 0, edges = 0;
  for (const auto& [key, value] : space->parameters()) {
    if (key == "vertices") vertices = std::stoi(value);
    if (key == "edges") edges = std::stoi(value);
  }
  EXPECT_EQ(grid->GetNumberOfPoints(), vertices + 3 * edges + 3 * space->num_elements());
  EXPECT_EQ(distinct_points(grid), static_cast<std::size_t>(grid->GetNumberOfPoints()));
}

TEST(VtkFidelity, MacroElementsAsLinearSubCellsShareTheirPoints) {
  const SpacePtr space = test::space_from_yaml("domain: {type: unit_square}\nspace: {type: ws4, elements: 2}\n");
  // WS4 is polynomial only on the pieces of its split.
  EXPECT_FALSE(elements_are_polynomial(*space, space->degree()));
  const Eigen::VectorXd c = random_coefficients(space->dimension());
  const std::string file = (test::scratch_folder() / "ws4.vtu").string();
  VtkFieldOptions options;
  options.samples = 2;
  options.lagrange = false;  // output.vtk.cells: linear
  ASSERT_FALSE(write_solution_vtu(*space, c, options, file));
  const auto grid = read_vtu(file);
  // Every sub-cell of every element's sample_cell.
  std::size_t unmerged = 0, sub_cells = 0;
  for (int e = 0; e < space->num_elements(); ++e) {
    const SampleCell sample = space->sample_cell(e, 2);
    unmerged += sample.points.size();
    sub_cells += sample.cells.size();
  }
  ASSERT_EQ(static_cast<std::size_t>(grid->GetNumberOfCells()), sub_cells);
  for (vtkIdType cell = 0; cell < grid->GetNumberOfCells(); ++cell) EXPECT_EQ(grid->GetCellType(cell), VTK_TRIANGLE);
  // Every position once: the points of element edges shared by two elements are written once.
  EXPECT_EQ(distinct_points(grid), static_cast<std::size_t>(grid->GetNumberOfPoints()));
  EXPECT_LT(static_cast<std::size_t>(grid->GetNumberOfPoints()), unmerged);
}

TEST(VtkFidelity, SurfaceInThreeDimensionsHasUnitNormalsOfTheSphere) {
  const SpacePtr space =
      test::space_from_yaml("domain: {type: surface, mesh: icosphere, level: 1}\nspace: {type: surface, degree: 2}\n");
  ASSERT_EQ(space->ambient_dimension(), 3);
  const Eigen::VectorXd c = random_coefficients(space->dimension());
  const std::string file = (test::scratch_folder() / "sphere.vtu").string();
  ASSERT_TRUE(write_solution_vtu(*space, c, {}, file));  // Bernstein triangles: single polynomials
  const auto grid = read_vtu(file);
  // One quadratic Lagrange triangle per face of the level-1 icosphere (80 faces, 120 edges, 42
  // vertices), nodes shared: 42 + 120 points, each once.
  ASSERT_EQ(grid->GetNumberOfCells(), 80);
  ASSERT_EQ(grid->GetNumberOfPoints(), 42 + 120);
  EXPECT_EQ(distinct_points(grid), static_cast<std::size_t>(grid->GetNumberOfPoints()));
  vtkDataArray* normals = grid->GetPointData()->GetNormals();
  ASSERT_NE(normals, nullptr);
  // A G1 surface close to the unit sphere: the normal is nearly radial, the points nearly unit.
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p) {
    double x[3], n[3];
    grid->GetPoint(p, x);
    normals->GetTuple(p, n);
    const Eigen::Vector3d X(x[0], x[1], x[2]), N(n[0], n[1], n[2]);
    EXPECT_NEAR(N.norm(), 1.0, 1e-6);
    EXPECT_GT(std::abs(N.dot(X.normalized())), 0.9) << "point " << p;
  }
}

}  // namespace
}  // namespace iga
