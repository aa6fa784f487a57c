#pragma once
/// @file
/// The generic parallel assembler: written once against the Space interface, used by every space.
/// Construction precomputes the element index table and the sparsity pattern; each assembly runs
/// over blocks of consecutive elements with one ElementValues per thread and adds into the
/// precomputed pattern without locks, each thread the columns it owns.

#include <Eigen/Core>
#include <vector>

#include "assembly/fields.hpp"
#include "assembly/integrators.hpp"
#include "assembly/sparsity.hpp"
#include "assembly/split_matrix.hpp"

namespace iga {

/// A vector field with `components` components on one scalar space (a shell's displacement):
/// the unknowns are numbered in blocks, component c of function i at c · dimension + i, and an
/// element's rows are its functions for component 0, then for component 1, ... (the row order of
/// a vector-valued integrator's element matrix, assembly/shell_integrators.hpp). `dofs`: one
/// element's functions, expanded in place to its unknowns (unchanged for one component).
void expand_component_dofs(std::vector<int>& dofs, int components, int dimension);
/// The same for every element of a table.
ElementDofTable component_dofs(const ElementDofTable& scalar, int components, int dimension);

class Assembler {
 public:
  /// The space must outlive the assembler. With components > 1 the matrices are those of a
  /// vector field on the space (a shell's displacement), unknowns in blocks: component c of
  /// function i is unknown c · dimension + i, and the forms must be vector-valued integrators of
  /// as many components (element rows: the functions for component 0, then 1, ...;
  /// assembly/shell_integrators.hpp).
  explicit Assembler(const Space& space, int components = 1);

  /// Global matrix of `form` (closed-form element matrices where the space has them, else
  /// integrated with rules of polynomial degree `quad_degree`).
  SparseMatrix matrix(const Form& form, int quad_degree) const;
  /// The same matrix with element matrices and sums in double-double, kept as high + low parts:
  /// what the residual of iterative refinement needs (see split_matrix.hpp). About as fast as
  /// `matrix` when the basis evaluation dominates; the double-double sums cost more at high degree.
  SplitMatrix matrix_extended(const Form& form, int quad_degree) const;
  /// Load vector ∫ f N_i (of the scalar space).
  Eigen::VectorXd load(const ScalarField& f, int quad_degree) const;
  /// The same with f evaluated at all points of an element at once (row 0 of its values).
  Eigen::VectorXd load(const BatchField& f, int quad_degree) const;

  const ElementDofTable& element_dofs() const { return table_; }

 private:
  /// Add the element matrices of `form` (Local: double or double-double) into `values` (a value
  /// array aligned with the pattern's, or the two arrays of a SplitMatrix); in parallel without
  /// locks (see the definition).
  template <class Local, class Values>
  void assemble(const Integrator& form, int quad_degree, Values values) const;

  const Space& space_;
  ElementDofTable table_;
  SparseMatrix pattern_;
  int components_ = 1;
  int max_local_ = 0;  ///< most active unknowns on one element
};

/// One element's matrix of `form` in double-double, computed as matrix_extended computes it (the
/// same kernel, for callers that assemble some elements themselves: a rank of a distributed solve).
/// Returns `scratch` or a matrix the space shares; `dofs` gets the global indices of its rows
/// (with `components` > 1, a vector field's unknowns in blocks, as the assembler numbers them).
/// Call prepare_extended_element_matrices once first (not from threads).
const DoubleDoubleMatrix& extended_element_matrix(const Space& space, int element, const Integrator& form, int quad_degree,
                                                  ElementValues& ev, DoubleDoubleMatrix& scratch,
                                                  std::vector<int>& dofs, int components = 1);
void prepare_extended_element_matrices(const Space& space, const Integrator& form);

}  // namespace iga
