#include "solver/data_finiteness.hpp"

#include <climits>
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

/// Corners and edge midpoints of the reference cell (a pole on a mesh line meets both; more points
/// per edge would cost as much as assembling). Built once and kept alive: evaluators may cache
/// tables by the address of a rule.
QuadratureRule vertex_and_edge_points(CellShape shape) {
  QuadratureRule rule;
  for (double t : {0.0, 0.5})
    for (int e = 0; e < num_edges(shape); ++e) rule.points.push_back(reference_edge_point(shape, e, t));
  rule.weights.assign(rule.points.size(), 0.0);
  return rule;
}

/// Points of one boundary edge: its two ends and three Gauss points (few edges: be thorough).
QuadratureRule edge_points(CellShape shape, int edge) {
  QuadratureRule rule;
  for (double t : {0.0, 1.0}) rule.points.push_back(reference_edge_point(shape, edge, t));
  for (const Point2& t : gauss_legendre(3).points) rule.points.push_back(reference_edge_point(shape, edge, t.x()));
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
  Finding best;
#pragma omp parallel if (items >= 512)
  {
    Finding mine;
    auto evaluator = space.make_evaluator();
    PointValues geometry;
#pragma omp for schedule(dynamic, 64)
    for (int i = 0; i < items; ++i) {
      const auto [element, rule] = item(i);
      if (element >= mine.element) continue;
      evaluator->evaluate_geometry(element, *rule, geometry);
      for (int q = 0; q < geometry.x.cols() && element < mine.element; ++q)
        for (size_t d = 0; d < data.size(); ++d)
          if (!std::isfinite(data[d].f(Point2(geometry.x.col(q))))) {
            mine = {element, static_cast<int>(d), geometry.x.col(q)};
            break;
          }
    }
#pragma omp critical(iga_data_finiteness)
    if (mine.element < best.element) best = mine;
  }
  return best;
}

[[noreturn]] void report(const std::vector<Datum>& data, const Finding& f, const char* place) {
  const Datum& d = data[f.datum];
  throw InputError(d.where + ": " + d.what + " is not finite at (" + format_number(f.x.x()) + ", " +
                   format_number(f.x.y()) + "), " + place + " of element " + std::to_string(f.element) +
                   " (a pole or a singularity on a mesh line, or a log or root of a negative number?)");
}

}  // namespace

void check_data_finite(const Space& space, const ProblemSpec& problem) {
  std::vector<Datum> everywhere;
  if (problem.exact) {
    const SymbolicFunction& u = *problem.exact;
    const SymbolicFunction ux = u.diff_x(), uy = u.diff_y();
    const std::string& w = problem.data_where;
    everywhere = {{w, "the exact solution", u},
                  {w, "the x-derivative of the exact solution", ux},
                  {w, "the y-derivative of the exact solution", uy},
                  {w, "the second derivative u_xx of the exact solution", ux.diff_x()},
                  {w, "the second derivative u_xy of the exact solution", ux.diff_y()},
                  {w, "the second derivative u_yy of the exact solution", uy.diff_y()}};
  }
  everywhere.push_back({problem.source_where, problem.exact ? "the source term derived from it" : "the source term",
                        problem.source});
  const QuadratureRule quad = vertex_and_edge_points(CellShape::quadrilateral);
  const QuadratureRule tri = vertex_and_edge_points(CellShape::triangle);
  const Finding inside = first_non_finite(space, everywhere, space.num_elements(), [&](int e) {
    return std::pair<int, const QuadratureRule*>(e, space.cell_shape(e) == CellShape::triangle ? &tri : &quad);
  });
  if (inside.datum >= 0) report(everywhere, inside, "a vertex or edge point");

  if (problem.exact) return;  // the boundary data are derived from it: checked above
  std::vector<Datum> on_boundary = {{problem.data_where, "the boundary value u", problem.value},
                                    {problem.data_where, "the boundary data laplace_u", problem.laplacian}};
  if (problem.gradient_x && problem.gradient_y) {
    on_boundary.push_back({problem.data_where, "the x-derivative of u", *problem.gradient_x});
    on_boundary.push_back({problem.data_where, "the y-derivative of u", *problem.gradient_y});
  } else {
    on_boundary.push_back({problem.data_where, "the boundary data dudn", problem.normal_derivative});
  }
  const std::vector<BoundaryEdge> edges = space.boundary_edges("all");
  std::vector<QuadratureRule> rules;  // per (shape, edge), kept alive for the evaluators
  for (CellShape shape : {CellShape::quadrilateral, CellShape::triangle})
    for (int e = 0; e < 4; ++e) rules.push_back(edge_points(shape, e % num_edges(shape)));
  const Finding on_edge = first_non_finite(space, on_boundary, static_cast<int>(edges.size()), [&](int i) {
    const BoundaryEdge& b = edges[i];
    const int shape = space.cell_shape(b.element) == CellShape::triangle ? 1 : 0;
    return std::pair<int, const QuadratureRule*>(b.element, &rules[shape * 4 + b.local_edge]);
  });
  if (on_edge.datum >= 0) report(on_boundary, on_edge, "a boundary point");
}

}  // namespace iga
