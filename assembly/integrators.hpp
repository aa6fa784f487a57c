#pragma once
/// @file
/// Element integrators: stateless functions from evaluated basis data to local matrices/vectors.
/// Callers provide the output arrays (resized here), so threads never share scratch.

#include <Eigen/Core>
#include <string>

#include "spaces/bilinear_form.hpp"
#include "assembly/fields.hpp"
#include "assembly/split_matrix.hpp"
#include "spaces/element_values.hpp"

namespace iga {


/// Update flags an element loop needs for `form`.
unsigned flags_for(BilinearForm form);
std::string to_string(BilinearForm form);

/// Local matrix of `form` on the element last evaluated by `ev` (n x n, n = ev.num_functions()).
void element_matrix(BilinearForm form, const ElementValues& ev, Eigen::MatrixXd& local);

/// The same local matrix with the quadrature sums in long double (the basis values stay double):
/// the exact Gram matrix of the evaluated functions, to long double precision.
void element_matrix_extended(BilinearForm form, const ElementValues& ev, MatrixXld& local);

/// The same local matrix in double-double: every product of basis values and weights exact, the
/// quadrature sums compensated (what Assembler::matrix_extended uses).
void element_matrix_double_double(BilinearForm form, const ElementValues& ev, DoubleDoubleMatrix& local);

/// Local load ∫ f v (n entries).
void element_load(const ScalarField& f, const ElementValues& ev, Eigen::VectorXd& local);

}  // namespace iga
