#pragma once
/// @file
/// Load vectors on surfaces in 3D whose data depend on the surface's own normal and curvature
/// at each quadrature point (Laplace–Beltrami sources computed from an exact solution).

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "assembly/fields.hpp"
#include "spaces/space.hpp"

namespace iga {

/// b_i = ∫_Γ f(x, n, H) N_i dA over all elements, with rules of degree `quad_degree`. The space
/// must have ambient_dimension() == 3 and fill normal3 and mean_curvature. `elements`, when
/// given, restricts the sum to those elements (a rank's share).
Eigen::VectorXd surface_load(const Space& space, const SurfaceSource& f, int quad_degree,
                             const std::vector<int>* elements = nullptr);

/// b_i = ∫_Γ f(e, x, n) N_i dA, where the data depend on the element e as well (a shell's pressure
/// p(x) s_e n: s_e orients the element's normal x_ξ × x_η, spaces/surface_orientation.hpp).
using ElementSurfaceSource = std::function<double(int element, const Eigen::Vector3d& x, const Eigen::Vector3d& n)>;
Eigen::VectorXd surface_element_load(const Space& space, const ElementSurfaceSource& f, int quad_degree,
                                     const std::vector<int>* elements = nullptr);

/// b_i = ∫_Γ f0(x, n, H) N_i + f2(x, n, H) Δ_Γ N_i dA: the load of a fourth-order surface problem
/// given as its bilinear form applied to a known function u, v ↦ ∫ Δ_Γu Δ_Γv + c u v (f2 = Δ_Γu,
/// f0 = c u, both computed pointwise from u). On a G1 surface, whose curvature jumps across patch
/// edges, this is the load whose solution is u; the strong form Δ_Γ²u + c u misses the edge terms.
Eigen::VectorXd surface_form_load(const Space& space, const SurfaceSource& f0, const SurfaceSource& f2,
                                  int quad_degree, const std::vector<int>* elements = nullptr);

}  // namespace iga
