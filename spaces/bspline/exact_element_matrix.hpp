#pragma once
/// @file
/// Element matrices of tensor-product B-splines on an affine patch in double-double, without
/// quadrature: 1D integrals of the span's B-splines from a double-double Bézier extraction and
/// exact Bernstein integrals, combined with the element's constant Jacobian.
///
/// Why: a matrix integrated from double basis values inherits their rounding, and near the
/// boundary (open knot vectors, extraction entries such as 1/3) that rounding is the same on every
/// element along an edge: Σ_j D²N_j ≠ 0 there by ~ε h⁻², so the matrix no longer maps constants
/// and linears to zero. For the biharmonic problem that bias acts like a boundary moment and
/// leaves an error growing like h⁻² however accurately the system is then solved.

#include <Eigen/Core>

#include "spaces/affine_element_matrices.hpp"
#include "spaces/bspline/knot_vector.hpp"

namespace iga {

/// ∫_0^1 N_a^(k)(s) N_c^(l)(s) ds for the p+1 B-splines active on span `span` (reference
/// coordinate s ∈ [0,1] of the span, derivatives in s), k, l = 0..2: entry [k][l] is (p+1) x (p+1).
using SpanIntegrals = DerivativeMoments<DoubleDoubleMatrix>;
SpanIntegrals span_integrals(const KnotVector& knots, int span);

}  // namespace iga
