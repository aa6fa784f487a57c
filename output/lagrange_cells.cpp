#include "output/lagrange_cells.hpp"

#include <vtkCellType.h>
#include <vtkIdList.h>
#include <vtkLagrangeQuadrilateral.h>
#include <vtkLagrangeTriangle.h>
#include <vtkNew.h>
#include <vtkPoints.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

namespace iga {

namespace {

int num_nodes(CellShape shape, int order) {
  return shape == CellShape::quadrilateral ? (order + 1) * (order + 1) : (order + 1) * (order + 2) / 2;
}

/// A VTK Lagrange cell of `order` with its point lists sized, ready for GetParametricCoords and
/// InterpolateFunctions (VTK deduces the order from the number of points).
vtkSmartPointer<vtkNonLinearCell> make_cell(CellShape shape, int order) {
  const int n = num_nodes(shape, order);
  vtkSmartPointer<vtkNonLinearCell> cell;
  if (shape == CellShape::quadrilateral) {
    auto quad = vtkSmartPointer<vtkLagrangeQuadrilateral>::New();
    quad->GetPointIds()->SetNumberOfIds(n);
    quad->GetPoints()->SetNumberOfPoints(n);
    quad->Initialize();
    quad->SetOrder(order, order);
    cell = quad;
  } else {
    auto triangle = vtkSmartPointer<vtkLagrangeTriangle>::New();
    triangle->GetPointIds()->SetNumberOfIds(n);
    triangle->GetPoints()->SetNumberOfPoints(n);
    triangle->Initialize();
    cell = triangle;
  }
  return cell;
}

/// Points off the nodal lattice of any order up to 12, inside the reference cell and on its
/// mid-lines (where a split macro-element changes polynomial piece).
std::vector<Point2> check_points(CellShape shape) {
  if (shape == CellShape::quadrilateral) return {{0.3141, 0.7183}, {0.8312, 0.2271}, {0.5, 0.1173}, {0.4619, 0.5}};
  return {{0.2113, 0.1271}, {0.1733, 0.6412}, {0.5, 0.2383}, {0.3319, 0.3319}};
}

}  // namespace

SubdividedLagrange subdivided_lagrange(CellShape shape, int order, int divisions) {
  const std::vector<Point2> nodes = lagrange_nodes(shape, order);
  const int m = std::max(1, divisions);
  const double step = 1.0 / m;
  // Sub-cells as origin + linear map of the reference cell (counterclockwise, like the cell).
  std::vector<std::pair<Point2, Eigen::Matrix2d>> maps;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      if (shape == CellShape::quadrilateral) {
        maps.emplace_back(Point2(i * step, j * step), Eigen::Matrix2d::Identity() * step);
      } else if (i + j < m) {
        maps.emplace_back(Point2(i * step, j * step), Eigen::Matrix2d::Identity() * step);
        if (i + j + 1 < m)  // the upside-down triangle of the grid square
          maps.emplace_back(Point2((i + 1) * step, (j + 1) * step), Eigen::Matrix2d::Identity() * -step);
      }
    }
  SubdividedLagrange out;
  std::map<std::pair<long long, long long>, int> index;
  for (const auto& [origin, linear] : maps) {
    std::vector<int> cell;
    for (const Point2& r : nodes) {
      const Point2 x = origin + linear * r;
      const auto key = std::make_pair(std::llround(x.x() * 1e12), std::llround(x.y() * 1e12));
      const auto [it, inserted] = index.try_emplace(key, static_cast<int>(out.points.size()));
      if (inserted) out.points.push_back(x);
      cell.push_back(it->second);
    }
    out.cells.push_back(std::move(cell));
  }
  return out;
}

std::vector<Point2> lagrange_nodes(CellShape shape, int order) {
  const auto cell = make_cell(shape, order);
  const double* pc = cell->GetParametricCoords();
  std::vector<Point2> nodes(num_nodes(shape, order));
  for (std::size_t k = 0; k < nodes.size(); ++k) nodes[k] = Point2(pc[3 * k], pc[3 * k + 1]);
  return nodes;
}

int lagrange_cell_type(CellShape shape) {
  return shape == CellShape::quadrilateral ? VTK_LAGRANGE_QUADRILATERAL : VTK_LAGRANGE_TRIANGLE;
}

bool elements_are_polynomial(const Space& space, int order, int max_checked) {
  if (order < 1) return false;
  const int ne = space.num_elements();
  const int checked = std::min(ne, std::max(1, max_checked));
  const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
  struct Shape {
    QuadratureRule rule;  // nodes, then the check points
    Eigen::MatrixXd weights;  // Lagrange basis at each check point (nodes x checks)
    int nodes = 0;
  };
  std::map<CellShape, Shape> shapes;
  PointValues values;
  for (int i = 0; i < checked; ++i) {
    const int e = static_cast<int>((static_cast<long long>(i) * ne) / checked);
    const CellShape shape = space.cell_shape(e);
    auto [it, inserted] = shapes.try_emplace(shape);
    Shape& s = it->second;
    if (inserted) {
      s.rule.points = lagrange_nodes(shape, order);
      s.nodes = static_cast<int>(s.rule.points.size());
      const auto cell = make_cell(shape, order);
      const std::vector<Point2> checks = check_points(shape);
      s.weights.resize(s.nodes, static_cast<int>(checks.size()));
      for (std::size_t c = 0; c < checks.size(); ++c) {
        const double pc[3] = {checks[c].x(), checks[c].y(), 0.0};
        cell->InterpolateFunctions(pc, s.weights.col(static_cast<int>(c)).data());
        s.rule.points.push_back(checks[c]);
      }
      s.rule.weights.assign(s.rule.points.size(), 0.0);
    }
    evaluator->evaluate(e, s.rule, update_values, values);
    const Eigen::MatrixXd& v = values.value;  // functions x points
    const Eigen::MatrixXd interpolated = v.leftCols(s.nodes) * s.weights;
    const Eigen::MatrixXd actual = v.rightCols(s.weights.cols());
    const double scale = std::max(1.0, v.cwiseAbs().maxCoeff());
    // Equispaced interpolation of degree <= 12 loses at most a few digits to its Lebesgue constant.
    if (!((interpolated - actual).cwiseAbs().maxCoeff() <= 1e-8 * scale)) return false;
  }
  return true;
}

}  // namespace iga
