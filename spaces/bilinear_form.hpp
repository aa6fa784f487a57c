#pragma once
/// @file
/// Tags of the standard bilinear forms. The forms themselves are integrator objects
/// (assembly/integrators.hpp); a tag names one where data choose it (a problem's form) and is the
/// key under which a space's ClosedForms gives element matrices without quadrature.

#include <string>

namespace iga {

enum class BilinearForm {
  mass,       ///< ∫ u v
  laplace,    ///< ∫ ∇u·∇v                       (Poisson)
  bilaplace,  ///< ∫ Δu Δv                        (biharmonic; natural condition Δu = 0)
  hessian,    ///< ∫ D²u : D²v                    (biharmonic; same solution when u, ∂u/∂n are fixed)
};
inline constexpr int kNumBilinearForms = 4;

inline std::string to_string(BilinearForm form) {
  static constexpr const char* names[kNumBilinearForms] = {"mass", "laplace", "bilaplace", "hessian"};
  return names[static_cast<int>(form)];
}

}  // namespace iga
