#pragma once
/// @file
/// The explicit core of a space, element by element. A space is, on each element e:
///  - a *local basis* φ_1..φ_L on the reference cell (Bernstein on the triangle or square, a
///    tensor B-spline of a 4-split face, ...) that tabulates itself at the points of a rule up to a
///    derivative order (LocalTables). Elements with the same local basis share a *kind* (a cell
///    shape, the one face B-spline), so tables are built once per (rule, kind);
///  - its *active global indices* (the order of Space::element_dofs);
///  - the *extraction* C_e, **active × local**: N_i = Σ_l C_e(i, l) φ_l, i.e. N = C_e φ. It is
///    viewed row-major (Extraction), one row per active function: the same bytes as a column-major
///    local × active matrix, so a space that stores that needs no copy (extraction_view);
///  - a *geometry map* giving jets at the rule's points: GeometryJet into R² (push_forward.hpp) or
///    SurfaceJet into R³ (geometry/surface_jet.hpp).
///
/// The generic evaluator (spaces/extracted_evaluator.hpp) does tables → C_e → push-forward from
/// these four; a space supplies a *core* type with these members (no virtual call per element):
///
///   using Jet = GeometryJet;                 // or SurfaceJet: planar or surface push-forward
///   static constexpr bool identity = false;  // true: C_e = I (the active functions are the φ_l)
///   int kind(int e) const;                   // which local basis element e uses
///   int tabulate(int kind, const std::vector<Point2>& points, int order, LocalTables& t) const;
///                                            // fills t[0 .. (order+1)(order+2)/2 - 1] (at least),
///                                            // returns the order it filled
///   const std::vector<int>& active(int e) const;   // (or by value)
///   Extraction extraction(int e) const;      // not called when identity
///   void map(int e, const QuadratureRule& rule, const LocalTables& t, int order, std::vector<Jet>& jets) const;
///                                            // jets at rule's points; second derivatives when order 2
///                                            // (t: the kind's tables there, for isoparametric maps)
///   // optional: ∇Δu_h and Δ²u_h of the function with local coefficients `local` (C_eᵀ c)
///   void higher_derivatives(int e, const QuadratureRule& rule, const Eigen::VectorXd& local, unsigned flags,
///                           FunctionValues& out) const;

#include <Eigen/SparseCore>
#include <stdexcept>

#include <memory>

#include "spaces/space.hpp"

namespace iga {

/// Reference tables of a local basis at q points, L × q each: value, ∂ξ, ∂η, ∂ξξ, ∂ξη, ∂ηη.
using LocalTables = Eigen::MatrixXd[6];

/// C_e, active × local, row-major (see above).
using Extraction = Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor>>;

/// The active × local view of a compressed column-major local × active matrix (its transpose,
/// without a copy: the column of active function i is row i of the view).
inline Extraction extraction_view(const Eigen::SparseMatrix<double>& local_by_active) {
  if (!local_by_active.isCompressed()) throw std::logic_error("extraction_view: the extraction is not compressed");
  return Extraction(local_by_active.cols(), local_by_active.rows(), local_by_active.nonZeros(),
                    local_by_active.outerIndexPtr(), local_by_active.innerIndexPtr(), local_by_active.valuePtr());
}

/// A space whose evaluator is an *evaluator specialisation* — a fast kernel that beats the
/// generic path (B-spline sum factorization, WS4 piece kernels, T-mesh diagonal maps) — still has
/// an explicit core, and offers the generic evaluator on it (ExtractedEvaluator) through this
/// capability, so that check_space can hold the fast kernel against it ("evaluator vs extraction").
/// A space evaluated by the generic evaluator itself does not need it.
class FastEvaluator {
 public:
  virtual ~FastEvaluator() = default;
  virtual std::unique_ptr<Space::Evaluator> make_generic_evaluator() const = 0;
};

/// The derivative order a request needs from the local basis (0 values, 1 gradients, 2 Hessians).
inline int basis_order(unsigned flags) {
  return (flags & update_hessians) ? 2 : (flags & update_gradients) ? 1 : 0;
}

}  // namespace iga
