#pragma once
/// @file
/// Test oracle (notes §3.6): the dimension of the C^(r1,r2) generalized spline space on a T-mesh
/// as the null space of the smoothness constraints on per-cell Bernstein coefficients. Slow
/// (dense SVD); meant for small meshes in tests, never for building spaces.

#include "spaces/tmesh/tmesh.hpp"

namespace iga {

/// Jumps of D_t^beta (beta <= r2) across horizontal and D_s^alpha (alpha <= r1) across vertical
/// shared side pieces at 3(n+1) Chebyshev points each; dimension = unknowns - numerical rank with
/// relative tolerance `tol` on the singular values.
int brute_force_dimension(const TMesh& mesh, int r1, int r2, double tol = 1e-12);

}  // namespace iga
