#include "solver/level_difference.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

#include "assembly/parallel.hpp"
#include "config/progress.hpp"
#include "quadrature/quadrature_rule.hpp"

namespace iga {

namespace {

/// Reference points of a fine element's four anchors: three corners of its reference cell, which
/// fix an affine map into the coarse element's reference cell, and the centre, which checks it.
QuadratureRule anchor_rule(CellShape shape) {
  QuadratureRule r;
  r.points = {{0, 0}, {1, 0}, {0, 1}, shape == CellShape::quadrilateral ? Point2(0.5, 0.5) : Point2(1.0 / 3, 1.0 / 3)};
  r.weights.assign(4, 0.0);
  return r;
}

/// Coarse-element rules of one thread, one per affine placement of a fine element in a coarse one
/// (a uniform refinement has a handful: the children's positions). Handing the same rule object to
/// the coarse evaluator again lets it reuse its tables instead of tabulating its basis anew.
class PlacementRules {
 public:
  const QuadratureRule& rule(const QuadratureRule& fine, const Point2& origin, const Eigen::Matrix2d& linear) {
    std::array<long long, 7> key{};
    const double values[6] = {origin.x(), origin.y(), linear(0, 0), linear(1, 0), linear(0, 1), linear(1, 1)};
    for (int i = 0; i < 6; ++i) key[i] = std::llround(values[i] * 1e9);
    key[6] = static_cast<long long>(fine.points.size());
    auto it = rules_.find(key);
    if (it != rules_.end() && it->second.fine == fine.points) return it->second.coarse;
    // Evaluators keep tables for a bounded number of rules: beyond that, a scratch rule.
    Entry& entry = it != rules_.end() || rules_.size() < 48 ? rules_[key] : scratch_;
    entry.fine = fine.points;
    entry.coarse.points.resize(fine.points.size());
    for (std::size_t k = 0; k < fine.points.size(); ++k) entry.coarse.points[k] = origin + linear * fine.points[k];
    entry.coarse.weights.assign(fine.points.size(), 0.0);
    return entry.coarse;
  }

 private:
  struct Entry {
    std::vector<Point2> fine;
    QuadratureRule coarse;
  };
  std::map<std::array<long long, 7>, Entry> rules_;
  Entry scratch_;
};

void resize_values(FunctionValues& v, int q, bool hessians) {
  v.value.resize(q);
  v.dx.resize(q);
  v.dy.resize(q);
  if (hessians) v.dxx.resize(q), v.dxy.resize(q), v.dyy.resize(q);
}

}  // namespace

std::function<RulePtr(int)> difference_rule(const Space& fine) {
  const int degree = fine.affine_elements() ? std::min(fine.error_quadrature_degree(), 2 * fine.degree())
                                            : fine.error_quadrature_degree();
  const QuadratureRule plain_triangle = triangle_rule(degree), plain_square = tensor_gauss(degree);
  const RulePtr own = fine.num_elements() > 0 ? fine.quadrature(0, degree) : nullptr;
  const std::size_t plain = fine.num_elements() > 0 && fine.cell_shape(0) == CellShape::triangle
                                ? plain_triangle.points.size()
                                : plain_square.points.size();
  if (!own || own->points.size() <= 32 * plain)
    return [&fine, degree](int e) { return fine.quadrature(e, degree); };
  // 16 equal sub-cells: the uniform 4 x 4 grid of squares, or of triangles.
  constexpr int m = 4;
  std::vector<QuadratureRule> triangles, squares;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const Point2 o(static_cast<double>(i) / m, static_cast<double>(j) / m);
      const double d = 1.0 / m;
      squares.push_back(map_to_box(plain_square, o, o + Point2(d, d)));
      if (i + j < m) triangles.push_back(map_to_triangle(plain_triangle, o, o + Point2(d, 0), o + Point2(0, d)));
      if (i + j + 1 < m)
        triangles.push_back(map_to_triangle(plain_triangle, o + Point2(d, d), o + Point2(0, d), o + Point2(d, 0)));
    }
  const auto triangle = std::make_shared<const QuadratureRule>(concatenate(triangles));
  const auto square = std::make_shared<const QuadratureRule>(concatenate(squares));
  return [&fine, triangle, square](int e) -> RulePtr {
    return fine.cell_shape(e) == CellShape::triangle ? triangle : square;
  };
}

ErrorNorms level_difference(const Space& fine, const Eigen::VectorXd& fine_coefficients, const PointLocator& coarse,
                            const Eigen::VectorXd& coarse_coefficients, bool hessians,
                            const std::function<RulePtr(int)>& rule_of) {
  keep_eigen_serial();
  const Space& coarse_space = coarse.space();
  const unsigned flags = update_values | update_gradients | (hessians ? update_hessians : 0u);
  const int ne = fine.num_elements();
  double total[3] = {0, 0, 0};
  long lost = 0;
#pragma omp parallel if (worth_threads(ne))
  {
    const std::unique_ptr<Space::Evaluator> fine_eval = fine.make_evaluator();
    const std::unique_ptr<Space::Evaluator> coarse_eval = coarse_space.make_evaluator();
    const QuadratureRule quad_anchors = anchor_rule(CellShape::quadrilateral),
                         triangle_anchors = anchor_rule(CellShape::triangle);
    PlacementRules placements;
    PointValues geometry, anchor_geometry, coarse_geometry;
    FunctionValues uf, uc, one;
    Eigen::VectorXd jxw;
    std::vector<Point2> reference;
    std::vector<bool> inside;
    std::vector<int> candidates;
    QuadratureRule points, single;
    single.weights = {0.0};
    double sums[3] = {0, 0, 0};
    long lost_here = 0;
#pragma omp for schedule(dynamic, 16) nowait
    for (int e = 0; e < ne; ++e) {
      progress_tick();
      const RulePtr rule = rule_of(e);
      fine_eval->evaluate_function(e, *rule, fine_coefficients, flags, geometry, uf);
      integration_weights(*rule, geometry, jxw);
      const int q = static_cast<int>(jxw.size());

      // The coarse element holding the fine element's centre, and the fine element's corners there.
      const CellShape shape = fine.cell_shape(e);
      const QuadratureRule& anchors = shape == CellShape::quadrilateral ? quad_anchors : triangle_anchors;
      fine_eval->evaluate_geometry(e, anchors, anchor_geometry);
      const Eigen::Matrix2Xd anchor_x = anchor_geometry.x;
      coarse.candidates(Point2(anchor_x.col(3)), candidates);
      int home = -1;
      bool placed = false;
      for (int c : candidates) {
        const Point2 start = coarse_space.cell_shape(c) == CellShape::quadrilateral ? Point2(0.5, 0.5)
                                                                                     : Point2(1.0 / 3, 1.0 / 3);
        coarse.invert_map(c, anchor_x, start, *coarse_eval, reference, inside);
        if (!inside[3]) continue;
        home = c;
        if (inside[0] && inside[1] && inside[2]) {
          // Nested: the fine reference cell sits affinely in the coarse one (checked at the centre).
          Eigen::Matrix2d linear;
          linear.col(0) = reference[1] - reference[0];
          linear.col(1) = reference[2] - reference[0];
          const Point2 centre = reference[0] + linear * anchors.points[3];
          if ((centre - reference[3]).norm() <= 1e-10) {
            const QuadratureRule& at = placements.rule(*rule, reference[0], linear);
            coarse_eval->evaluate_function(c, at, coarse_coefficients, flags, coarse_geometry, uc);
            placed = (Point2(coarse_geometry.x.col(0)) - Point2(geometry.x.col(0))).norm() <=
                      1e-9 * std::max(1e-300, (anchor_x.col(1) - anchor_x.col(0)).norm());
          }
        }
        break;
      }
      if (!placed) {
        // Not nested, or a curved relation: every point mapped into the home element, and those
        // outside it located one by one.
        inside.assign(q, false);
        resize_values(uc, q, hessians);
        if (home >= 0) {
          coarse.invert_map(home, geometry.x, reference[3], *coarse_eval, reference, inside);
          points.points = reference;
          points.weights.assign(q, 0.0);
          coarse_eval->evaluate_function(home, points, coarse_coefficients, flags, coarse_geometry, uc);
        }
        for (int k = 0; k < q; ++k) {
          if (inside[k]) continue;
          const auto at = coarse.locate(Point2(geometry.x.col(k)), *coarse_eval);
          if (!at) {
            ++lost_here;
            continue;
          }
          single.points = {at->reference};
          coarse_eval->evaluate_function(at->element, single, coarse_coefficients, flags, coarse_geometry, one);
          uc.value(k) = one.value(0);
          uc.dx(k) = one.dx(0);
          uc.dy(k) = one.dy(0);
          if (hessians) uc.dxx(k) = one.dxx(0), uc.dxy(k) = one.dxy(0), uc.dyy(k) = one.dyy(0);
        }
      }
      sums[0] += jxw.dot((uf.value - uc.value).cwiseAbs2());
      sums[1] += jxw.dot((uf.dx - uc.dx).cwiseAbs2() + (uf.dy - uc.dy).cwiseAbs2());
      if (hessians)
        sums[2] += jxw.dot((uf.dxx - uc.dxx).cwiseAbs2() + 2 * (uf.dxy - uc.dxy).cwiseAbs2() +
                           (uf.dyy - uc.dyy).cwiseAbs2());
    }
#pragma omp critical(iga_level_difference)
    {
      for (int i = 0; i < 3; ++i) total[i] += sums[i];
      lost += lost_here;
    }
  }
  if (lost > 0) throw std::runtime_error("level difference: a quadrature point of the fine mesh is outside the coarse mesh");
  ErrorNorms r;
  r.l2 = std::sqrt(total[0]);
  r.h1 = std::sqrt(total[1]);
  if (hessians) r.h2 = std::sqrt(total[2]);
  return r;
}

}  // namespace iga
