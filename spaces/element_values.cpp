#include "spaces/element_values.hpp"

#include <Eigen/LU>  // Matrix2d::determinant

#include <cmath>

namespace iga {

ElementValues::ElementValues(const Space& space, unsigned flags)
    : space_(space), flags_(flags), evaluator_(space.make_evaluator()) {}

void ElementValues::reinit(int element, const QuadratureRule& rule) {
  evaluator_->evaluate(element, rule, flags_, data_);
  integration_weights(rule, data_, jxw_);
}

void ElementValues::reinit_edge(int element, int edge, const QuadratureRule& rule) {
  evaluator_->evaluate(element, rule, flags_, data_);
  const Point2 tau = reference_edge_tangent(space_.cell_shape(element), edge);
  const int q = rule.size();
  jxw_.resize(q);
  normal_.resize(2, q);
  for (int k = 0; k < q; ++k) {
    const Eigen::Matrix2d& J = data_.jacobian[k];
    const Point2 t = J * tau;
    const double len = t.norm();
    jxw_(k) = rule.weights[k] * len;
    // Reference edges run counterclockwise, so (t_y, -t_x) points out of an orientation-preserving
    // element; a reflecting map (det J < 0) reverses that.
    const double sign = J.determinant() > 0 ? 1.0 : -1.0;
    normal_.col(k) = sign * Point2(t.y(), -t.x()) / len;
  }
}

}  // namespace iga
