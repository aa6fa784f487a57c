#pragma once
/// @file
/// TensorBSplineSpace: tensor-product B-splines on one patch, the baseline of every smooth space.
///
/// Elements are the nonzero knot span pairs, numbered ex + ey * n_ex. The reference cell [0,1]^2
/// of an element maps affinely onto its parameter box, then through the PatchGeometry. Global
/// functions N_i(u) M_j(v) are numbered i + j * n_u. The local basis of an element is the tensor
/// Bernstein basis; its (p_u+1)(p_v+1) active functions are (C_v ⊗ C_u) times it, with the 1D
/// Bézier extraction operators C_u, C_v. Active functions are ordered a + b * (p_u+1) (a along u).

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>

#include "spaces/bspline/exact_element_matrix.hpp"
#include "spaces/bspline/knot_vector.hpp"
#include "spaces/bspline/patch_geometry.hpp"
#include "spaces/closed_forms.hpp"
#include "spaces/element_core.hpp"
#include "spaces/gauss_rule_cache.hpp"
#include "spaces/push_forward.hpp"
#include "spaces/space.hpp"

namespace iga {

/// Its evaluator is a specialisation (element_core.hpp): sum factorization over the two 1D
/// extractions instead of the (p_u+1)(p_v+1)-square extraction of the explicit core, which
/// make_generic_evaluator evaluates through the generic path for check_space.
class TensorBSplineSpace final : public Space, public FastEvaluator {
 public:
  /// Spline space of `knots_u` x `knots_v` on `geometry`. Both knot vectors must cover [0,1] and
  /// contain every breakpoint of the geometry (so the map is smooth on each element);
  /// std::invalid_argument otherwise.
  TensorBSplineSpace(std::shared_ptr<const PatchGeometry> geometry, KnotVector knots_u, KnotVector knots_v);

  std::unique_ptr<Evaluator> make_evaluator() const override;
  /// The explicit core: tensor Bernstein on the square, C_v ⊗ C_u, the patch map.
  std::unique_ptr<Evaluator> make_generic_evaluator() const override;
  void element_dofs(int element, std::vector<int>& out) const override;

  /// Shared tensor Gauss rule exact for `degree` per direction (built once per degree).
  RulePtr quadrature(int element, int degree) const override;
  /// Shared Gauss rule on edge `edge` of the reference square (built once per edge and degree).
  RulePtr edge_quadrature(int element, int edge, int degree) const override;

  /// On affine patches: the exact element matrix from double-double span integrals
  /// (spaces/bspline/exact_element_matrix.hpp), so that the matrix annihilates what it should.
  const ClosedForms* closed_forms() const override { return &closed_forms_; }

  const PatchGeometry& geometry() const { return *geometry_; }
  const KnotVector& knots_u() const { return knots_u_; }
  const KnotVector& knots_v() const { return knots_v_; }
  int num_elements_u() const { return knots_u_.num_spans(); }
  int num_elements_v() const { return knots_v_.num_spans(); }
  /// Parameter box [lo, hi] of an element.
  void element_box(int element, Point2& lo, Point2& hi) const;
  /// The element map's jets at the points of `rule` (second derivatives only when `hess`).
  void element_jets(int element, const QuadratureRule& rule, bool hess, std::vector<GeometryJet>& jets) const;
  /// Smallest continuity order of the interior knots of both directions (degree when there are none).
  int regularity() const;

 private:
  class TensorEvaluator;
  struct Core;
  class ExactMatrices final : public ClosedForms {
   public:
    explicit ExactMatrices(const TensorBSplineSpace& space) : space_(space) {}
    ExactMatrices(const ExactMatrices&) = delete;

   protected:
    bool double_double(int element, BilinearForm form, DoubleDoubleMatrix& local) const override;

   private:
    const TensorBSplineSpace& space_;
  };
  double compute_mesh_size() const;
  /// type "bspline"; parameters degree, regularity (C^r over interior knots; "-" with one element
  /// per direction), elements (n_ex x n_ey), domain; continuity: regularity(), lowered where the
  /// geometry map itself is less smooth; boundary parts left (u = 0), right (u = 1), bottom
  /// (v = 0), top (v = 1), each in increasing element order, "all" bottom, right, top, left.
  SpaceFacts make_facts() const;

  std::shared_ptr<const PatchGeometry> geometry_;
  KnotVector knots_u_, knots_v_;
  int n_u_, n_v_;
  /// Bézier extraction of each element column (along u) and row (along v), active × local (p+1)².
  std::vector<Eigen::MatrixXd> extraction_u_, extraction_v_;
  std::vector<int> geometry_span_u_, geometry_span_v_;  ///< geometry span of each element column/row
  // Span integrals of each element column and row, built on first use of the closed form.
  mutable std::once_flag span_integrals_once_;
  mutable std::vector<SpanIntegrals> span_integrals_u_, span_integrals_v_;

  // Shared rule caches: the space is used by several threads, hence the mutex.
  GaussRuleCache rules_;
  ExactMatrices closed_forms_{*this};
};

}  // namespace iga
