#include "solver/planar_formulation.hpp"

#include <algorithm>

#include "config/errors.hpp"

namespace iga {

namespace {
BoundaryField boundary_field(const SymbolicFunction& f) {
  return [f](const Point2& x, const Point2&) { return f(x); };
}
}  // namespace

void PlanarFormulation::check() const {
  for (const BoundaryPart& part : problem().boundary)
    check_boundary_part(space(), part.name, part.where, "this " + space().type() + " domain");
}

const BoundarySplit& PlanarFormulation::boundary() const {
  if (!boundary_) boundary_ = split_boundary(space(), problem());
  return *boundary_;
}

Eigen::VectorXd PlanarFormulation::load(const WorkShare& share) const {
  const int qa = quadrature_degree();
  const FunctionBatch source_batch({problem().source});
  const BatchField source = [&source_batch](const Eigen::Matrix2Xd& x, Eigen::MatrixXd& values) {
    source_batch.evaluate(x, values);
  };
  Eigen::VectorXd b = share.elements ? subset_load(space(), *share.elements, source, qa) : assembler().load(source, qa);
  // Natural conditions: Neumann flux ∫ g_N v, and for simply supported plates ∫ Δu ∂v/∂n
  // (from ∫ Δ²u v = ∫ Δu Δv − ∫_Γ Δu ∂v/∂n when v = 0 on Γ).
  const int ne = space().num_elements();
  const std::vector<BoundaryEdge> neumann = edges_of_share(boundary().neumann, share, ne);
  const std::vector<BoundaryEdge> supported = edges_of_share(boundary().simply_supported, share, ne);
  if (!neumann.empty()) b += edge_load(space(), neumann, problem().normal_derivative_field(), false, qa);
  if (!supported.empty()) b += edge_load(space(), supported, boundary_field(problem().laplacian), true, qa);
  return b;
}

Constraints PlanarFormulation::constraints() const {
  return impose_essential(space(), boundary().essential, boundary_field(problem().value),
                          problem().normal_derivative_field(), quadrature_degree());
}

ErrorNorms PlanarFormulation::errors(const Eigen::VectorXd& coefficients, const WorkShare& share) const {
  return error_norms(space(), coefficients, problem().exact_solution(), space().error_quadrature_degree(),
                     share.elements);
}

Formulation::Messages PlanarFormulation::messages() const {
  return {problem().source_where +
              ": the source term or boundary flux is not finite at some point of the domain "
              "(a pole, or a log or root of a negative number?)",
          problem().data_where + ": the boundary data (u or du/dn) are not finite at some boundary point",
          problem().data_where + ": the exact solution or its derivatives are not finite somewhere in the domain"};
}

}  // namespace iga
