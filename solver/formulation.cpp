#include "solver/formulation.hpp"

#include <stdexcept>

#include "solver/petsc_session.hpp"
#include "spaces/lifted_space.hpp"

namespace iga {

int assembly_quadrature_degree(const Space& space) {
  // 2p integrates products of basis functions on affine elements exactly, and data of degree p
  // against them (on tensor cells the Gauss rule of degree 2p is that of 2p + 1 anyway; on WS4's
  // 342 pieces it is 16 points instead of 19); non-affine maps get three more.
  return 2 * space.degree() + (space.affine_elements() ? 0 : 3);
}

double WorkShare::sum(double part) const { return over_ranks ? sum_over_ranks(part) : part; }
double WorkShare::max(double part) const { return over_ranks ? max_over_ranks(part) : part; }
double WorkShare::first(double value) const { return over_ranks ? first_known_over_ranks(value) : value; }

std::vector<BoundaryEdge> edges_of_share(const std::vector<BoundaryEdge>& edges, const WorkShare& share,
                                         int num_elements) {
  if (!share.elements) return edges;
  std::vector<char> mine(num_elements, 0);
  for (int e : *share.elements) mine[e] = 1;
  std::vector<BoundaryEdge> out;
  for (const BoundaryEdge& be : edges)
    if (mine[be.element]) out.push_back(be);
  return out;
}

bool Formulation::works_on_parts() const { return !dynamic_cast<const LiftedSpace*>(&space_); }

Formulation::Formulation(const Space& space, const ProblemSpec& problem)
    : space_(space), problem_(problem), quadrature_degree_(assembly_quadrature_degree(space)) {}

const Assembler& Formulation::assembler() const {
  if (!assembler_) assembler_ = std::make_unique<Assembler>(space_, components());
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
    if (A.nonZeros() == 0) {
      A = std::move(term);
      continue;
    }
    // Every term is assembled into a copy of the assembler's one pattern: add the value arrays
    // (a sparse sum would merge the same structure again and allocate a third matrix).
    if (term.nonZeros() != A.nonZeros()) throw std::logic_error("Formulation::matrix: the terms' patterns differ");
    Eigen::Map<Eigen::VectorXd>(A.valuePtr(), A.nonZeros()) +=
        Eigen::Map<const Eigen::VectorXd>(term.valuePtr(), term.nonZeros());
  }
  return {std::move(A), Eigen::VectorXd()};  // moved: a copy of the whole matrix cost 2-3 % of a study
}

}  // namespace iga
