#pragma once
/// @file
/// Assembly restricted to a subset of the elements, for callers that own only part of a mesh (a
/// rank of a distributed solve). Element matrices come from the assembler's own kernel
/// (extended_element_matrix, assembler.hpp); error integrals take an element list themselves
/// (error_norms.hpp). Written against the Space interface.

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "assembly/fields.hpp"
#include "config/double_double.hpp"
#include "assembly/integrator.hpp"
#include "spaces/space.hpp"

namespace iga {

/// Receives one element's matrix: global indices of its rows and the matrix in double-double.
using ElementMatrixSink = std::function<void(int element, const std::vector<int>& dofs, const DoubleDoubleMatrix&)>;

/// The double-double matrix Σ terms of each element of `elements` (the kernel of
/// Assembler::matrix_extended: extended_element_matrix), handed to `sink` serially in the order
/// given; the matrices are computed in parallel batches (OpenMP), so `sink` need not be thread-safe.
/// With `components` > 1 the terms are vector-valued (a shell's) and the rows are the unknowns in
/// blocks (assembler.hpp).
void for_each_element_matrix(const Space& space, const std::vector<int>& elements, const std::vector<FormTerm>& terms,
                             int quad_degree, const ElementMatrixSink& sink, int components = 1);

/// ∫ f N_i over `elements` only (rules of degree `quad_degree`), as a vector of length
/// space.dimension(), contributions added in the order given (Assembler::load: all elements).
Eigen::VectorXd subset_load(const Space& space, const std::vector<int>& elements, const BatchField& f,
                            int quad_degree);

/// ∫_Γ g v ds (or ∫_Γ g ∂v/∂n ds when `normal_derivative`) over the given boundary edges only, as a
/// vector of length space.dimension() (nonzero only at functions active on those edges).
Eigen::VectorXd edge_load(const Space& space, const std::vector<BoundaryEdge>& edges, const BoundaryField& g,
                          bool normal_derivative, int quad_degree);

/// A physical point inside each element: the centroid of the element's quadrature points (a rule
/// of degree 1, weighted by the integration weights). For partitioning the mesh.
std::vector<Point2> element_centres(const Space& space);
/// The same for the elements first, …, last − 1 only.
std::vector<Point2> element_centres(const Space& space, int first, int last);

}  // namespace iga
