#pragma once
/// @file
/// Assembly restricted to a subset of the elements, for callers that own only part of a mesh (a
/// rank of a distributed solve). Element matrices and loads are handed to a callback instead of
/// being added into a global matrix, so the caller decides where they go (e.g. a distributed
/// matrix) and this layer stays free of any solver library. Written against the Space interface.

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "assembly/error_norms.hpp"
#include "assembly/fields.hpp"
#include "assembly/split_matrix.hpp"
#include "spaces/bilinear_form.hpp"
#include "spaces/space.hpp"

namespace iga {

/// Receives one element's system: global indices, matrix of the form and load ∫ f N_i (same order).
using ElementSystemSink =
    std::function<void(int element, const std::vector<int>& dofs, const Eigen::MatrixXd& matrix,
                       const Eigen::VectorXd& load)>;

/// Compute the element matrix of `form` and the load of `f` on each element of `elements` (rules of
/// degree `quad_degree`) and hand them to `sink`, serially and in the order given. The element
/// systems are computed in parallel batches (OpenMP), so `sink` itself need not be thread-safe.
void for_each_element_system(const Space& space, const std::vector<int>& elements, BilinearForm form,
                             const ScalarField& f, int quad_degree, const ElementSystemSink& sink);

/// Receives one element's system with the matrix in long double (see for_each_element_system_extended).
using ElementSystemSinkExtended =
    std::function<void(int element, const std::vector<int>& dofs, const MatrixXld& matrix, const Eigen::VectorXd& load)>;

/// The same with the element matrices in long double, not rounded to double (a space's extended
/// closed form, else quadrature sums in long double): for residuals of iterative refinement that
/// must see the matrix beyond its double rounding (split_matrix.hpp).
void for_each_element_system_extended(const Space& space, const std::vector<int>& elements, BilinearForm form,
                                      const ScalarField& f, int quad_degree, const ElementSystemSinkExtended& sink);

/// ∫_Γ g v ds (or ∫_Γ g ∂v/∂n ds when `normal_derivative`) over the given boundary edges only, as a
/// vector of length space.dimension() (nonzero only at functions active on those edges).
Eigen::VectorXd edge_load(const Space& space, const std::vector<BoundaryEdge>& edges, const BoundaryField& g,
                          bool normal_derivative, int quad_degree);

/// A physical point inside each element: the centroid of the element's quadrature points (a rule
/// of degree 1, weighted by the integration weights). For partitioning the mesh.
std::vector<Point2> element_centres(const Space& space);

/// Sums of squared errors over some elements (square roots of the totals give ErrorNorms), so that
/// partial sums from several owners can be added before the root is taken.
struct SquaredErrors {
  double l2 = 0, h1 = 0, h2 = 0;
};

/// The squared error integrals of error_norms, over `elements` only.
SquaredErrors squared_errors_on_elements(const Space& space, const std::vector<int>& elements,
                                         const Eigen::VectorXd& coefficients, const ExactSolution& exact,
                                         int quad_degree);

/// ErrorNorms from the squared integrals over all elements.
ErrorNorms error_norms_from_squares(const SquaredErrors& total, const ExactSolution& exact);

}  // namespace iga
