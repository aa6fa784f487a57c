#include "solver/formulation.hpp"

namespace iga {

int assembly_quadrature_degree(const Space& space) {
  // 2p integrates products of basis functions on affine elements exactly, and data of degree p
  // against them (on tensor cells the Gauss rule of degree 2p is that of 2p + 1 anyway; on WS4's
  // 342 pieces it is 16 points instead of 19); non-affine maps get three more.
  return 2 * space.degree() + (space.affine_elements() ? 0 : 3);
}

Formulation::Formulation(const Space& space, const ProblemSpec& problem)
    : space_(space), problem_(problem), quadrature_degree_(assembly_quadrature_degree(space)) {}

}  // namespace iga
