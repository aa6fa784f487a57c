#include "output/element_drawing.hpp"
#include "output/first_failure.hpp"

#include <vtkCellType.h>

#include <Eigen/Core>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>

#include "config/progress.hpp"
#include "config/worth_threads.hpp"
#include "output/lagrange_cells.hpp"
#include "output/point_merger.hpp"

namespace iga {

namespace {

/// The sample points of one element and the cells over them.
struct ElementPieces {
  const QuadratureRule* rule = nullptr;
  int cell_type = 0;                                     ///< VTK type of every cell of the element
  const std::vector<std::vector<int>>* cells = nullptr;  ///< local point indices per cell
};

/// The pieces whose points are `points` and cells `cells` (one rule per distinct point set).
ElementPieces pieces_of(ElementDrawing& drawing, const std::vector<Point2>& points, std::vector<std::vector<int>> cells,
                        int cell_type) {
  std::vector<double> key;
  key.reserve(2 * points.size() + 1);
  key.push_back(cell_type);
  for (const Point2& p : points) key.insert(key.end(), {p.x(), p.y()});
  auto [it, inserted] = drawing.pieces.try_emplace(std::move(key));
  if (inserted) {
    auto rule = std::make_shared<QuadratureRule>();
    rule->points = points;
    rule->weights.assign(points.size(), 0.0);
    it->second = {std::move(rule), std::move(cells)};
  }
  return {it->second.first.get(), cell_type, &it->second.second};
}

/// True for a reference point on the boundary of its cell: the only points another element can share.
bool on_cell_boundary(CellShape shape, const Point2& r) {
  constexpr double eps = 1e-12;
  if (r.x() < eps || r.y() < eps) return true;
  return shape == CellShape::quadrilateral ? (r.x() > 1 - eps || r.y() > 1 - eps) : r.x() + r.y() > 1 - eps;
}

}  // namespace

ElementDrawing draw_elements(const Space& space, bool lagrange_asked, int divisions, int samples) {
  const int num_elements = space.num_elements();
  const int order = space.degree();
  ElementDrawing drawing;
  const bool lagrange = lagrange_asked && order >= 1 && order <= 10 && elements_are_polynomial(space, order);
  drawing.lagrange = lagrange;
  // Elements that are not single polynomials (macro-elements, non-polynomial bases): Lagrange
  // cells of the space's degree interpolating u_h on the element (or a subdivision of it): not
  // exact, but far closer to the smooth u_h than linear sub-cells with many more points
  // (tests/output/vtk_macro_fidelity_test.cpp, docs/outputs.md "VTK file sizes").
  const bool subdivided = lagrange_asked && !lagrange && order >= 1 && order <= 10 && divisions >= 1;
  const bool high_order = lagrange || subdivided;

  // Pass 1 (serial, cheap): what each element draws.
  std::vector<ElementPieces> pieces(num_elements);
  drawing.offset.assign(num_elements + 1, 0);
  drawing.rule.resize(num_elements);
  std::map<CellShape, ElementPieces> lagrange_pieces;
  for (int e = 0; e < num_elements; ++e) {
    const CellShape shape = space.cell_shape(e);
    ElementPieces piece;
    if (lagrange) {
      auto it = lagrange_pieces.find(shape);
      if (it == lagrange_pieces.end()) {
        const std::vector<Point2> nodes = lagrange_nodes(shape, order);
        std::vector<int> all(nodes.size());
        for (std::size_t k = 0; k < nodes.size(); ++k) all[k] = static_cast<int>(k);
        it = lagrange_pieces.emplace(shape, pieces_of(drawing, nodes, {all}, lagrange_cell_type(shape))).first;
      }
      piece = it->second;
    } else if (subdivided) {
      auto it = lagrange_pieces.find(shape);
      if (it == lagrange_pieces.end()) {
        SubdividedLagrange cells = subdivided_lagrange(shape, order, divisions);
        it = lagrange_pieces.emplace(shape, pieces_of(drawing, cells.points, std::move(cells.cells),
                                                      lagrange_cell_type(shape))).first;
      }
      piece = it->second;
    } else {
      SampleCell sample = space.sample_cell(e, samples);
      const auto num_points = static_cast<int>(sample.points.size());
      int vertices = 0;
      for (const std::vector<int>& cell : sample.cells) {
        if ((cell.size() != 3 && cell.size() != 4) || (vertices && static_cast<int>(cell.size()) != vertices))
          throw std::logic_error("write_solution_vtu: sample cells of element " + std::to_string(e) +
                                 " are not all triangles or all quadrilaterals");
        vertices = static_cast<int>(cell.size());
        for (int v : cell)
          if (v < 0 || v >= num_points)
            throw std::logic_error("write_solution_vtu: sample cell of element " + std::to_string(e) +
                                   " refers to point " + std::to_string(v));
      }
      piece = pieces_of(drawing, sample.points, std::move(sample.cells), vertices == 4 ? VTK_QUAD : VTK_TRIANGLE);
    }
    pieces[e] = piece;
    drawing.rule[e] = piece.rule;
    drawing.offset[e + 1] = drawing.offset[e] + piece.rule->size();
  }
  const std::int64_t unmerged = drawing.offset[num_elements];

  // Pass 2 (parallel): the physical points, not yet merged.
  std::vector<double>& xyz = drawing.xyz;
  xyz.resize(3 * unmerged);
  FirstFailure failure;
#pragma omp parallel if (worth_threads(unmerged))
  {
    const std::unique_ptr<Space::Evaluator> evaluator = failure.make_evaluator(space);
    PointValues geometry;
#pragma omp for schedule(dynamic, 16)
    for (int e = 0; e < num_elements; ++e) {
      if (!evaluator) continue;
      try {
        progress_tick();
        evaluator->evaluate_geometry(e, *drawing.rule[e], geometry);
        const std::int64_t first = drawing.offset[e];
        const int q = static_cast<int>(drawing.offset[e + 1] - first);
        if (geometry.num_points() != q)
          throw std::logic_error("write_solution_vtu: element " + std::to_string(e) + " evaluated at " +
                                 std::to_string(geometry.num_points()) + " points instead of " + std::to_string(q));
        const bool ambient = geometry.x3.cols() == q;
        for (int k = 0; k < q; ++k) {
          double* x = &xyz[3 * (first + k)];
          x[0] = geometry.x(0, k);
          x[1] = geometry.x(1, k);
          x[2] = ambient ? geometry.x3(2, k) : 0.0;
        }
      } catch (...) {
        failure.keep();
      }
    }
  }
  failure.rethrow();

  // Pass 3 (serial): merge coinciding points. Only points on an element's boundary can coincide
  // with another element's, except inside linear sub-cells, whose pieces repeat their shared points.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (std::int64_t p = 0; p < unmerged; ++p)
    for (int d = 0; d < 3; ++d) lo(d) = std::min(lo(d), xyz[3 * p + d]), hi(d) = std::max(hi(d), xyz[3 * p + d]);
  const double diameter = unmerged > 0 ? (hi - lo).norm() : 1.0;
  PointMerger merger(1e-9 * std::max(diameter, 1e-300), static_cast<std::size_t>(unmerged / 2));
  drawing.merged_id.resize(unmerged);
  drawing.owner.assign(unmerged, 0);
  for (int e = 0; e < num_elements; ++e) {
    const CellShape shape = space.cell_shape(e);
    const QuadratureRule& rule = *drawing.rule[e];
    for (int k = 0; k < rule.size(); ++k) {
      const std::int64_t p = drawing.offset[e] + k;
      bool inserted = true;
      if (!high_order || on_cell_boundary(shape, rule.points[k]))
        drawing.merged_id[p] = merger.insert(Eigen::Vector3d(xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2]), inserted);
      else
        drawing.merged_id[p] = merger.append();  // an interior node belongs to this element alone
      drawing.owner[p] = inserted;
    }
  }
  drawing.num_points = merger.size();

  // The cells: one per Lagrange element, or the element's sub-cells.
  drawing.cell_offsets.push_back(0);
  for (int e = 0; e < num_elements; ++e)
    for (const std::vector<int>& cell : *pieces[e].cells) {
      for (int v : cell) drawing.connectivity.push_back(drawing.merged_id[drawing.offset[e] + v]);
      drawing.cell_offsets.push_back(static_cast<std::int64_t>(drawing.connectivity.size()));
      drawing.cell_types.push_back(static_cast<unsigned char>(pieces[e].cell_type));
      drawing.cell_element.push_back(e);
    }
  return drawing;
}

}  // namespace iga
