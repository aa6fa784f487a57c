#pragma once
/// @file
/// Ws4Evaluator: the evaluator specialisation of Ws4Space (element_core.hpp). evaluate is the
/// generic one on the explicit core (Ws4Space::make_generic_evaluator); one discrete WS4 function
/// and the transposed evaluation of load vectors are evaluated piece by piece, without the 51 x q
/// tables of the reference basis, which is where the time of error norms and loads goes.
///
/// On region r of the split, u_h = Σ_i b_i B_i with b = C_K c_K is one quartic: its 15 monomial
/// coefficients Σ_i b_i piece(r, i) cost a few hundred operations per region, and then each point
/// costs a Horner evaluation instead of a 51-term sum. The element map is affine, so the physical
/// derivatives are taken on the coefficients, once per region and element and for eight regions
/// at once (ws4_piece_kernels.hpp), rather than pushed forward point by point. Load vectors run
/// the same steps transposed: weighted monomial moments per region, then the pieces, then C_Kᵀ.
/// The pieces are those of each region's representative under the symmetries of the triangle
/// (ws4_piece_table.hpp): the regions of an orbit are contracted together, and the points are
/// taken in their representative's coordinates.

#include <Eigen/Core>
#include <array>
#include <map>
#include <memory>
#include <vector>

#include "spaces/space.hpp"

namespace iga::ws4 {

class Ws4Space;

/// Per-thread evaluation state of a Ws4Space (holds per-rule tables; not thread-safe).
class Ws4Evaluator final : public Space::Evaluator {
 public:
  explicit Ws4Evaluator(const Ws4Space& space);

  /// Every active function: the generic evaluator on the explicit core.
  void evaluate(int element, const QuadratureRule& rule, unsigned flags, PointValues& out) override {
    generic_->evaluate(element, rule, flags, out);
  }

  /// Value, gradient and Hessian of Σ c_i N_i at the points of `rule`, piece by piece; geometry
  /// receives dofs, x and jacobian.
  void evaluate_element_function(int element, const QuadratureRule& rule, const Eigen::VectorXd& local,
                                 unsigned flags, PointValues& geometry, FunctionValues& out) override;

  /// dofs, x and jacobian of `element` at the points of `rule` (no basis values).
  void evaluate_geometry(int element, const QuadratureRule& rule, PointValues& out) override;

  /// local(m) = Σ_q weights(q) N_m(x_q): per region the weighted monomial moments, then the pieces
  /// and the extraction.
  void integrate_values(int element, const QuadratureRule& rule, const PointValues& geometry,
                        const Eigen::VectorXd& weights, Eigen::VectorXd& local) override;

 private:
  /// The points of one rule grouped by split region.
  struct RuleTables {
    std::vector<Point2> points;  ///< copy, to detect a different rule at a reused address
    Eigen::Matrix<double, Eigen::Dynamic, 2> reference;  ///< the points: column 0 x, column 1 y
    /// The points relative to the center of their region, in the coordinates of the region's
    /// representative (Ws4PieceTable): column 0 x, column 1 y.
    Eigen::Matrix<double, Eigen::Dynamic, 2> local;
    std::vector<int> regions;  ///< distinct regions holding points (slots), in order of first appearance
    /// Maximal runs of consecutive points in one region: (slot in `regions`, first point, count),
    /// ordered by slot.
    std::vector<std::array<int, 3>> runs;
    /// The slots grouped by the orbit of their region (Ws4PieceTable::representative): group g is
    /// orbit_regions / orbit_slots [orbit_begin[g], orbit_begin[g + 1]).
    std::vector<int> orbit_regions, orbit_slots, orbit_begin;
  };
  const RuleTables& tables(const QuadratureRule& rule);
  void fill_geometry(int element, const RuleTables& t, PointValues& out) const;

  const Ws4Space& space_;
  std::unique_ptr<Space::Evaluator> generic_;
  std::map<const QuadratureRule*, RuleTables> cache_;
  Eigen::Matrix<double, 51, 1> c_, b_;
  std::vector<double> values_;  ///< u_h per slot: 15 rows over the slots (rounded up to a block)
  /// The polynomial coefficients of one block of slots (piece_kernels::rows x block_slots), or
  /// the 16 weighted moments per slot of the load vector.
  std::vector<double> slot_values_;
  std::array<double, 32> slot_maps_{};  ///< the slots' inverse Jacobians (piece_kernels::derivative_polynomials)
};

}  // namespace iga::ws4
