#pragma once
/// @file
/// The one generic evaluator: tables of the local basis → extraction C_e → push-forward through the
/// element map, for any core (spaces/element_core.hpp). Planar cores (Jet = GeometryJet) are pushed
/// forward by push_forward; surface cores (Jet = SurfaceJet) get the surface gradient and the
/// covariant Hessian (spaces/surface_values.hpp), the normal and the mean curvature. Templated on
/// the core so that the per-element calls are direct; what is computed follows the flags.
///
/// A space evaluated by it returns `std::make_unique<ExtractedEvaluator<Core>>(*this, Core{...})` from
/// make_evaluator and writes no evaluator of its own.

#include <map>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "geometry/surface_jet.hpp"
#include "spaces/element_core.hpp"
#include "spaces/push_forward.hpp"
#include "spaces/space.hpp"
#include "spaces/surface_values.hpp"

namespace iga {

template <class Core>
class ExtractedEvaluator final : public Space::Evaluator {
  static constexpr bool surface = std::is_same_v<typename Core::Jet, SurfaceJet>;
  /// A core whose local basis and map give derivatives of order 3 and 4 (T-meshes: tensor sections
  /// under a diagonal scaling) fills ∇Δu_h and Δ²u_h from the local coefficients C_eᵀ c.
  static constexpr bool has_higher_derivatives =
      requires(const Core& core, const QuadratureRule& rule, const Eigen::VectorXd& local, FunctionValues& out) {
        core.higher_derivatives(0, rule, local, 0u, out);
      };

 public:
  /// `core` is small (references into its space, which outlives the evaluator).
  ExtractedEvaluator(const Space& space, Core core) : Space::Evaluator(space), core_(std::move(core)) {}

  void evaluate(int element, const QuadratureRule& rule, unsigned flags, PointValues& out) override {
    const LocalTables& t = tables(element, rule, basis_order(flags));
    out.dofs = core_.active(element);
    core_.map(element, rule, t, map_order(flags), jets_);
    if constexpr (Core::identity) {
      push(t, flags, out);
    } else {
      extract_reference_derivatives(core_.extraction(element), t, flags, ref_);
      push(ref_, flags, out);
    }
  }

  /// u_h = Σ c_i N_i with the coefficients contracted first: C_eᵀ c is one local vector, then one
  /// row per table (instead of extracting every active function at every point). ∇Δu_h and Δ²u_h
  /// only from a core that has them (higher_derivatives, below).
  void evaluate_element_function(int element, const QuadratureRule& rule, const Eigen::VectorXd& element_coefficients,
                                 unsigned flags, PointValues& geometry, FunctionValues& out) override {
    const unsigned higher = flags & (update_laplacian_gradient | update_bilaplacian);
    if (higher && !has_higher_derivatives)
      throw std::logic_error("evaluate_function: this space provides derivatives up to order 2 only");
    const LocalTables& t = tables(element, rule, basis_order(flags));
    const std::vector<int>& dofs = core_.active(element);
    Eigen::VectorXd c = element_coefficients;
    if constexpr (!Core::identity) {  // the local coefficients C_eᵀ c
      local_.noalias() = core_.extraction(element).transpose() * c;
      c.swap(local_);
    }
    contract_local_derivatives(t, c, flags, one_);
    geometry.dofs = dofs;
    core_.map(element, rule, t, map_order(flags), jets_);
    push(one_, flags | update_values, single_);
    take_single_function(single_, flags, geometry, out);
    if constexpr (has_higher_derivatives) {
      if (higher) core_.higher_derivatives(element, rule, c, higher, out);
    }
  }

  /// Points and Jacobians alone (VTK points, data checks; the load vector's integrate_values).
  void evaluate_geometry(int element, const QuadratureRule& rule, PointValues& out) override {
    core_.map(element, rule, tables(element, rule, 0), 1, jets_);
    out.dofs = core_.active(element);
    if constexpr (surface) {
      take_surface_geometry(jets_, 0u, out);
    } else {
      take_geometry(jets_, out);
    }
  }

  /// Σ_q w_q N_i(x_q) = C_e (φ w): the tables' values times the weights, then the extraction.
  void integrate_values(int element, const QuadratureRule& rule, const PointValues& /*geometry*/,
                        const Eigen::VectorXd& weights, Eigen::VectorXd& local) override {
    const LocalTables& t = tables(element, rule, 0);
    if constexpr (Core::identity) {
      local.noalias() = t[0] * weights;
    } else {
      const Eigen::VectorXd weighted = t[0] * weights;
      local.noalias() = core_.extraction(element) * weighted;
    }
  }

  /// The tables of element's local basis at rule's points, built once per (rule, kind) and again
  /// when a higher order is asked (rules are shared by address; the points guard a reused address).
  /// Public for evaluator specialisations that contract them their own way.
  const LocalTables& tables(int element, const QuadratureRule& rule, int order) {
    const auto key = std::make_pair(&rule, core_.kind(element));
    auto it = cache_.find(key);
    if (it != cache_.end() && it->second.order >= order && it->second.points == rule.points) return it->second.t;
    if (it == cache_.end() && cache_.size() >= 64) cache_.clear();
    Entry& entry = cache_[key];
    entry.points = rule.points;
    entry.order = core_.tabulate(key.second, rule.points, order, entry.t);
    return entry.t;
  }

 private:
  /// The map's second derivatives: planar Hessians need them, and on surfaces the curvature too.
  static int map_order(unsigned flags) {
    return (flags & (update_hessians | update_surface_curvature)) ? 2 : 1;
  }

  /// Push-forward of reference data (ReferenceDerivatives, or the tables themselves when C_e = I)
  /// through jets_.
  template <class Reference>
  void push(const Reference& r, unsigned flags, PointValues& out) {
    if constexpr (surface) {
      const auto& [value, dxi, deta, dxixi, dxieta, detaeta] = members(r);
      take_surface_geometry(jets_, flags, out);
      if (flags & update_values) out.value = value;
      if (flags & (update_gradients | update_hessians)) complete_surface_gradients(jets_, dxi, deta, out);
      if (flags & update_hessians) complete_surface_hessians(jets_, dxi, deta, {dxixi, dxieta, detaeta}, out);
    } else {
      static_assert(!Core::identity, "planar cores state their extraction (push_forward reads ReferenceDerivatives)");
      push_forward(jets_, r, flags, out);
    }
  }

  using Refs = std::tuple<const Eigen::MatrixXd&, const Eigen::MatrixXd&, const Eigen::MatrixXd&,
                          const Eigen::MatrixXd&, const Eigen::MatrixXd&, const Eigen::MatrixXd&>;
  static Refs members(const ReferenceDerivatives& r) {
    return {r.value, r.dxi, r.deta, r.dxixi, r.dxieta, r.detaeta};
  }
  static Refs members(const LocalTables& t) { return {t[0], t[1], t[2], t[3], t[4], t[5]}; }

  struct Entry {
    std::vector<Point2> points;
    int order = -1;
    LocalTables t;
  };

  const Core core_;
  std::map<std::pair<const QuadratureRule*, int>, Entry> cache_;
  std::vector<typename Core::Jet> jets_;
  ReferenceDerivatives ref_, one_;
  Eigen::VectorXd local_;
  PointValues single_;
};

}  // namespace iga
