#pragma once
/// @file
/// The bilinear forms iga-run assembles (shared by the assembler and by spaces that can give
/// element matrices in closed form).

namespace iga {

enum class BilinearForm {
  mass,       ///< ∫ u v
  laplace,    ///< ∫ ∇u·∇v                       (Poisson)
  bilaplace,  ///< ∫ Δu Δv                        (biharmonic; natural condition Δu = 0)
  hessian,    ///< ∫ D²u : D²v                    (biharmonic; same solution when u, ∂u/∂n are fixed)
};

}  // namespace iga
