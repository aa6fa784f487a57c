#pragma once
/// @file
/// Universal reference matrices of the 51 WS4 simplex splines on the unit triangle: the B_i are
/// affine-invariant (WS4 notes §9), so the element matrices of every triangle are combinations of
/// these (spaces/affine_element_matrices.hpp).

#include "spaces/affine_element_matrices.hpp"

namespace iga::ws4 {

/// ∫ ∂^α B_i ∂^β B_j over the reference triangle (51 x 51), exact sub-region by sub-region,
/// rounded once to double from long double. Built on first use (quadrature of degree 8 per
/// sub-triangle), then shared; thread-safe.
const ReferenceIntegrals<Eigen::MatrixXd>& ws4_reference_integrals();

/// The same integrals before rounding to double, for element matrices kept in long double.
const ReferenceIntegrals<LongDoubleMatrix>& ws4_reference_integrals_extended();

/// The same integrals in double-double, from pieces built in double-double (a fraction of a
/// second). The residuals of clamped and simply supported plates need them: the long double ones
/// carry ≈ 1e-18 of their size, which the h⁻⁴ conditioning turns into an L2 error of 1e-12 at
/// 9 226 DOFs, growing ×16 per refinement. Only the group `form` uses is filled (values, first or
/// second derivatives), built on first use with the threads of the calling context: call it
/// outside parallel regions (ClosedForms::prepare) so that element loops find it ready.
const ReferenceIntegrals<DoubleDoubleMatrix>& ws4_reference_integrals_double_double(BilinearForm form);

}  // namespace iga::ws4
