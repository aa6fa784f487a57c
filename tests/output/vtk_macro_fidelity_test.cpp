/// @file
/// Macro-elements (WS4, 4-split G1) and non-polynomial sections (trigonometric T-mesh) are drawn
/// by one Lagrange cell of the space's degree per element, interpolating u_h at its nodes (not
/// exact: u_h is polynomial only piece by piece): read back with VTK, the drawn surface must follow
/// the discrete solution at least as closely as the linear sub-cells drawn before
/// (Space::sample_cell with 8 samples per edge), with a third of the bytes or less. The drawn value at a
/// point inside each cell is VTK's own interpolation; u_h there is evaluated through the point
/// locator.

#include <gtest/gtest.h>
#include <vtkCell.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>

#include "output/vtk_writer.hpp"
#include "spaces/point_location.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

/// Four points inside every cell of a file, drawn value against u_h.
struct Deviation {
  double worst = 0;       ///< largest |drawn u − u_h|
  vtkIdType cells = 0;    ///< cells in the file
  vtkIdType compared = 0; ///< points where u_h was evaluated
};

Deviation drawing_deviation(const std::string& file, const PointLocator& locator, const Eigen::VectorXd& c) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  vtkDataArray* u = grid->GetPointData()->GetArray("u");
  const auto evaluator = locator.space().make_evaluator();
  PointValues geometry;
  FunctionValues uh;
  QuadratureRule one;
  one.weights = {0.0};
  Deviation out;
  out.cells = grid->GetNumberOfCells();
  const double pcoords[4][3] = {{0.2, 0.3, 0}, {0.6, 0.2, 0}, {0.25, 0.25, 0}, {0.1, 0.7, 0}};
  std::vector<double> weights;
  for (vtkIdType k = 0; k < grid->GetNumberOfCells(); ++k) {
    vtkCell* cell = grid->GetCell(k);
    weights.resize(cell->GetNumberOfPoints());
    for (const auto& pc : pcoords) {
      double x[3];
      int sub = 0;
      cell->EvaluateLocation(sub, const_cast<double*>(pc), x, weights.data());
      double drawn = 0;
      for (vtkIdType i = 0; i < cell->GetNumberOfPoints(); ++i) drawn += weights[i] * u->GetTuple1(cell->GetPointId(i));
      const auto at = locator.locate(Point2(x[0], x[1]), *evaluator);
      if (!at) continue;  // not expected here: the points are well inside cells of straight-edged domains
      one.points = {at->reference};
      evaluator->evaluate_function(at->element, one, c, update_values, geometry, uh);
      out.worst = std::max(out.worst, std::abs(drawn - uh.value(0)));
      ++out.compared;
    }
  }
  return out;
}

void compare_drawings(const std::string& yaml, int level, const std::string& name) {
  const SpacePtr space = test::space_from_yaml(yaml, level);
  const DiscreteSolution sol = solve_problem(*space, test::problem_from_yaml(yaml), SolverKind::cholmod);
  const std::filesystem::path dir = test::scratch_folder() / name;
  std::filesystem::create_directories(dir);
  VtkFieldOptions lagrange;
  VtkFieldOptions linear;
  linear.lagrange = false;
  linear.samples = 8;
  const std::string a = (dir / "lagrange.vtu").string(), b = (dir / "linear.vtu").string();
  EXPECT_FALSE(write_solution_vtu(*space, sol.coefficients, lagrange, a)) << "not single polynomials";
  write_solution_vtu(*space, sol.coefficients, linear, b);
  const PointLocator locator(space);
  const Deviation drawn = drawing_deviation(a, locator, sol.coefficients);
  const Deviation sampled = drawing_deviation(b, locator, sol.coefficients);
  const double new_deviation = drawn.worst, old_deviation = sampled.worst;
  // One Lagrange cell per element, Space::sample_cell's sub-cells for the linear drawing, and
  // every one of the four points of every cell compared.
  vtkIdType sub_cells = 0;
  for (int e = 0; e < space->num_elements(); ++e) sub_cells += std::ssize(space->sample_cell(e, linear.samples).cells);
  EXPECT_EQ(drawn.cells, space->num_elements());
  EXPECT_EQ(sampled.cells, sub_cells);
  EXPECT_EQ(drawn.compared, 4 * drawn.cells);
  EXPECT_EQ(sampled.compared, 4 * sampled.cells);
  const auto size_a = std::filesystem::file_size(a), size_b = std::filesystem::file_size(b);
  std::printf("%s level %d: %d elements; max |drawn - u_h|: Lagrange %.3e (%ju bytes, %lld points), linear "
              "sub-cells %.3e (%ju bytes, %lld points)\n",
              name.c_str(), level, space->num_elements(), new_deviation, static_cast<std::uintmax_t>(size_a),
              static_cast<long long>(drawn.compared), old_deviation, static_cast<std::uintmax_t>(size_b),
              static_cast<long long>(sampled.compared));
  // At least as faithful (single-precision storage, 1e-6 of |u| ~ 1, is the common floor) ...
  EXPECT_LE(new_deviation, std::max(old_deviation, 1e-6));
  // ... and at most a third of the bytes.
  EXPECT_LT(3 * size_a, size_b);
}

TEST(VtkMacroFidelity, Ws4) {
  compare_drawings(R"yaml(
problem: {pde: poisson, exact: "sin(pi*x)*sin(pi*y)", boundary: {all: dirichlet}}
domain: {type: unit_square}
space: {type: ws4, elements: 2}
)yaml",
                   2, "ws4");
}

TEST(VtkMacroFidelity, G1FourSplit) {
  compare_drawings(R"yaml(
problem: {pde: poisson, exact: "sin(2*x+0.3)*cos(3*y)", boundary: {all: dirichlet}}
domain: {type: multipatch, name: fan3}
space: {type: g1_4split, degree: 4, blending: linear, refinement: nested}
)yaml",
                   2, "g1_4split");
}

TEST(VtkMacroFidelity, TrigonometricTMesh) {
  compare_drawings(R"yaml(
problem: {pde: poisson, exact: "sin(2*x)*sin(y)", boundary: {all: dirichlet}}
domain: {type: rectangle, min: [0, 0], max: [3.141592653589793, 3.141592653589793]}
space: {type: tmesh, section: trig, n: 3, regularity: 1, frequency: 1, elements: [2, 2]}
)yaml",
                   2, "tmesh_trig");
}

}  // namespace
}  // namespace iga
