#pragma once
/// @file
/// ElementValues: the one evaluation cache shared by the assembler, the error norms, boundary
/// conditions and the VTK writer (after deal.II's FEValues). It owns a per-thread Evaluator of
/// the space and adds the integration weights (JxW) and, on edges, outward unit normals.

#include <memory>

#include "spaces/space.hpp"

namespace iga {

class ElementValues {
 public:
  /// @param flags which arrays of PointValues to compute (update_values | ...).
  ElementValues(const Space& space, unsigned flags);

  /// Evaluate on element `element` at the points of `rule` (reference coordinates);
  /// jxw(q) = w_q |det J(x_q)|.
  void reinit(int element, const QuadratureRule& rule);
  /// Evaluate on edge `edge` of element `element`; `rule` is an edge rule in reference-cell
  /// coordinates (Space::edge_quadrature). jxw(q) = w_q |J tau| (arc length), normal() is the
  /// outward unit normal.
  void reinit_edge(int element, int edge, const QuadratureRule& rule);

  const PointValues& values() const { return data_; }
  const std::vector<int>& dofs() const { return data_.dofs; }
  int num_functions() const { return data_.num_functions(); }
  int num_points() const { return data_.num_points(); }
  const Eigen::VectorXd& jxw() const { return jxw_; }
  /// Outward unit normals (2 x q), valid after reinit_edge.
  const Eigen::Matrix2Xd& normal() const { return normal_; }
  const Space& space() const { return space_; }

 private:
  const Space& space_;
  unsigned flags_;
  std::unique_ptr<Space::Evaluator> evaluator_;
  PointValues data_;
  Eigen::VectorXd jxw_;
  Eigen::Matrix2Xd normal_;
};

}  // namespace iga
