#include "solver/formulation.hpp"

#include <stdexcept>

namespace iga {

int assembly_quadrature_degree(const Space& space) {
  // 2p integrates products of basis functions on affine elements exactly, and data of degree p
  // against them (on tensor cells the Gauss rule of degree 2p is that of 2p + 1 anyway; on WS4's
  // 342 pieces it is 16 points instead of 19); non-affine maps get three more.
  return 2 * space.degree() + (space.affine_elements() ? 0 : 3);
}

Formulation::Formulation(const Space& space, const ProblemSpec& problem)
    : space_(space), problem_(problem), quadrature_degree_(assembly_quadrature_degree(space)) {}

const Assembler& Formulation::assembler() const {
  if (!assembler_) assembler_ = std::make_unique<Assembler>(space_);
  return *assembler_;
}

SplitMatrix Formulation::matrix(const std::vector<FormTerm>& terms) const {
  if (extended_precision()) {
    if (terms.size() != 1) throw std::logic_error("Formulation::matrix: extended precision for one term only");
    return assembler().matrix_extended(terms.front(), quadrature_degree_);
  }
  SparseMatrix A;
  for (const FormTerm& t : terms) {
    SparseMatrix term = assembler().matrix(t, quadrature_degree_);
    A = A.nonZeros() ? SparseMatrix(A + term) : std::move(term);
  }
  return {A, Eigen::VectorXd()};
}

}  // namespace iga
