#include "solver/data_finiteness.hpp"
#include "config/worth_threads.hpp"

#include <climits>
#include <algorithm>
#include <cmath>

#include "config/config_node.hpp"
#include "config/errors.hpp"

namespace iga {

namespace {

struct Datum {
  std::string where;  ///< config place
  std::string what;   ///< e.g. "the x-derivative of the exact solution"
  SymbolicFunction f;
};

/// Reference points at parameters `ts` of every edge of the cell, or of edge `only` (t = 0: the
/// corners, t = 0.5: the edge midpoints). Built once and kept alive: evaluators may cache tables
/// by the address of a rule.
QuadratureRule points_on_edges(CellShape shape, const std::vector<double>& ts, int only = -1) {
  QuadratureRule rule;
  for (double t : ts)
    for (int e = 0; e < num_edges(shape); ++e)
      if (only < 0 || e == only) rule.points.push_back(reference_edge_point(shape, e, t));
  rule.weights.assign(rule.points.size(), 0.0);
  return rule;
}

struct Finding {
  int element = INT_MAX;
  int datum = -1;
  Point2 x = Point2::Zero();
};

/// First (lowest element) place where one of `data` is not finite, over `items` pairs
/// item(i) = (element, reference points on it), at the physical images of those points.
template <class RuleOf>
Finding first_non_finite(const Space& space, const std::vector<Datum>& data, int items, const RuleOf& item) {
  // The physical points of every item first, then all data in one batch over large blocks of
  // points (their shared subexpressions once per point, the compiled program running over whole blocks).
  std::vector<Eigen::Index> offset(items + 1, 0);
  for (int i = 0; i < items; ++i) offset[i + 1] = offset[i] + item(i).second->size();
  Eigen::Matrix2Xd points(2, offset[items]);
  std::vector<int> owner(offset[items]);
#pragma omp parallel if (worth_threads(items))
  {
    auto evaluator = space.make_evaluator();
    PointValues geometry;
#pragma omp for schedule(dynamic, 64)
    for (int i = 0; i < items; ++i) {
      const auto [element, rule] = item(i);
      evaluator->evaluate_geometry(element, *rule, geometry);
      points.middleCols(offset[i], geometry.x.cols()) = geometry.x;
      std::fill(owner.begin() + offset[i], owner.begin() + offset[i + 1], element);
    }
  }
  std::vector<SymbolicFunction> functions;
  for (const Datum& d : data) functions.push_back(d.f);
  const FunctionBatch batch(functions);

  constexpr Eigen::Index block = 4096;
  const auto blocks = static_cast<int>((points.cols() + block - 1) / block);
  Finding best;
#pragma omp parallel if (blocks > 1)
  {
    Finding mine;
    Eigen::MatrixXd values;
#pragma omp for schedule(dynamic, 1)
    for (int b = 0; b < blocks; ++b) {
      const Eigen::Index first = b * block, count = std::min(block, points.cols() - first);
      batch.evaluate(points.middleCols(first, count), values);
      for (Eigen::Index k = 0; k < count; ++k) {
        const int element = owner[first + k];
        if (element >= mine.element) continue;
        for (int d = 0; d < values.rows(); ++d)
          if (!std::isfinite(values(d, k))) {
            mine = {element, d, points.col(first + k)};
            break;
          }
      }
    }
#pragma omp critical(iga_data_finiteness)
    if (mine.element < best.element) best = mine;
  }
  return best;
}

/// InputError naming the datum of `f` and `place` ("a vertex"), when `f` found one.
void report(const std::vector<Datum>& data, const Finding& f, const char* place) {
  if (f.datum < 0) return;
  const Datum& d = data[f.datum];
  throw InputError(d.where + ": " + d.what + " is not finite at (" + format_number(f.x.x()) + ", " +
                   format_number(f.x.y()) + "), " + place + " of element " + std::to_string(f.element) +
                   " (a pole or a singularity on a mesh line, or a log or root of a negative number?)");
}

/// Reports the first place where one of `data` is not finite at the points `ts` of every element edge.
void check_elements(const Space& space, const std::vector<Datum>& data, const std::vector<double>& ts,
                    const char* place) {
  const QuadratureRule quad = points_on_edges(CellShape::quadrilateral, ts);
  const QuadratureRule tri = points_on_edges(CellShape::triangle, ts);
  const Finding f = first_non_finite(space, data, space.num_elements(), [&](int e) {
    return std::pair<int, const QuadratureRule*>(e, space.cell_shape(e) == CellShape::triangle ? &tri : &quad);
  });
  report(data, f, place);
}

/// Reports the first place where one of `data` is not finite at the points `ts` of every boundary edge.
void check_boundary(const Space& space, const std::vector<Datum>& data, const std::vector<double>& ts,
                    const char* place) {
  const std::vector<BoundaryEdge> edges = space.boundary_edges("all");
  std::vector<QuadratureRule> rules;  // per (shape, edge), kept alive for the evaluators
  for (CellShape shape : {CellShape::quadrilateral, CellShape::triangle})
    for (int e = 0; e < 4; ++e) rules.push_back(points_on_edges(shape, ts, e % num_edges(shape)));
  const Finding f = first_non_finite(space, data, static_cast<int>(edges.size()), [&](int i) {
    const BoundaryEdge& b = edges[i];
    const int shape = space.cell_shape(b.element) == CellShape::triangle ? 1 : 0;
    return std::pair<int, const QuadratureRule*>(b.element, &rules[shape * 4 + b.local_edge]);
  });
  report(data, f, place);
}

}  // namespace

void check_data_finite(const Space& space, const ProblemSpec& problem) {
  // Values at vertices; derivatives and the derived source inside edges only: an integrable point
  // singularity at a vertex (a re-entrant corner's r^(2/3)) is fine, a singular line is not.
  if (problem.exact) {
    const SymbolicFunction& u = *problem.exact;
    const SymbolicFunction ux = u.diff_x(), uy = u.diff_y();
    const std::string& w = problem.data_where;
    const std::vector<Datum> value = {{w, "the exact solution", u}};
    check_elements(space, value, {0.0}, "a vertex");
    const std::vector<Datum> all = {{w, "the exact solution", u},
                                    {w, "the x-derivative of the exact solution", ux},
                                    {w, "the y-derivative of the exact solution", uy},
                                    {w, "the second derivative u_xx of the exact solution", ux.diff_x()},
                                    {w, "the second derivative u_xy of the exact solution", ux.diff_y()},
                                    {w, "the second derivative u_yy of the exact solution", uy.diff_y()},
                                    {problem.source_where, "the source term derived from it", problem.source}};
    check_elements(space, all, {0.5}, "an edge midpoint");
    return;  // the boundary data are derived from the exact solution: checked above
  }
  // A source given as such (not derived from an exact solution) is data like the boundary values:
  // infinite at a vertex, its load vector is finite only by the accident of the quadrature points.
  const std::vector<Datum> source = {{problem.source_where, "the source term", problem.source}};
  check_elements(space, source, {0.0}, "a vertex");
  check_elements(space, source, {0.5}, "an edge midpoint");

  const std::vector<Datum> value = {{problem.data_where, "the boundary value u", problem.value}};
  check_boundary(space, value, {0.0, 1.0}, "a boundary vertex");
  std::vector<Datum> data = {value.front(), {problem.data_where, "the boundary data laplace_u", problem.laplacian}};
  if (problem.gradient_x && problem.gradient_y) {
    data.push_back({problem.data_where, "the x-derivative of u", *problem.gradient_x});
    data.push_back({problem.data_where, "the y-derivative of u", *problem.gradient_y});
  } else {
    data.push_back({problem.data_where, "the boundary data dudn", problem.normal_derivative});
  }
  std::vector<double> gauss;
  for (const Point2& t : gauss_legendre(3).points) gauss.push_back(t.x());
  check_boundary(space, data, gauss, "a boundary point");
}

}  // namespace iga
