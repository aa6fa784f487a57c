#pragma once
/// @file
/// The generic parallel assembler: written once against the Space interface, used by every space.
/// Construction precomputes the element index table, the sparsity pattern and an element
/// colouring; each assembly then runs colour by colour with one ElementValues per thread and adds
/// into the precomputed pattern without locks.

#include <Eigen/Core>
#include <vector>

#include "assembly/fields.hpp"
#include "assembly/integrators.hpp"
#include "assembly/sparsity.hpp"
#include "assembly/split_matrix.hpp"

namespace iga {

class Assembler {
 public:
  /// The space must outlive the assembler.
  explicit Assembler(const Space& space);

  /// Global matrix of `form`, integrated with rules of polynomial degree `quad_degree`.
  SparseMatrix matrix(BilinearForm form, int quad_degree) const;
  /// The same matrix with element matrices and sums in long double, kept as high + low parts:
  /// what the residual of iterative refinement needs (see split_matrix.hpp). About as fast as
  /// `matrix` when the basis evaluation dominates; the long double products cost more at high degree.
  SplitMatrix matrix_extended(BilinearForm form, int quad_degree) const;
  /// Load vector ∫ f N_i.
  Eigen::VectorXd load(const ScalarField& f, int quad_degree) const;
  /// The same with f evaluated at all points of an element at once (row 0 of its values).
  Eigen::VectorXd load(const BatchField& f, int quad_degree) const;

  /// What a boundary integral tests against.
  enum class BoundaryTest { value, normal_derivative };
  /// ∫_Γ g v ds (value) or ∫_Γ g ∂v/∂n ds (normal_derivative) over the given edges.
  Eigen::VectorXd boundary_load(const std::vector<BoundaryEdge>& edges, const BoundaryField& g, BoundaryTest test,
                                int quad_degree) const;

  const ElementDofTable& element_dofs() const { return table_; }
  int num_colours() const { return static_cast<int>(colours_.size()); }

 private:
  /// Run work(e, ev, scratch) on every element e, colour by colour, in parallel: one ElementValues
  /// (for work to reinit when it needs quadrature data) and one Scratch per thread, so threads share
  /// nothing mutable but the output, which elements of one colour never touch at the same place.
  template <class Scratch, class Work>
  void for_each_element(unsigned flags, Work&& work) const;

  const Space& space_;
  ElementDofTable table_;
  SparseMatrix pattern_;
  std::vector<std::vector<int>> colours_;
};

}  // namespace iga
