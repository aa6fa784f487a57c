#pragma once
/// @file
/// Poisson and biharmonic problems on planar domains (problem.hpp) as a Formulation: the form of
/// the config summed in double-double, the source and natural boundary terms (Neumann flux,
/// ∫ Δu ∂v/∂n on simply supported plate edges), the essential data by boundary projection, the
/// errors in L2, H1 and H2.

#include <optional>

#include "solver/boundary_edge_kinds.hpp"
#include "solver/formulation.hpp"

namespace iga {

class PlanarFormulation final : public Formulation {
 public:
  using Formulation::Formulation;
  /// The problem's boundary part names against the space's; throws InputError.
  void check() const override;
  Eigen::VectorXd load(const WorkShare& share) const override;
  Constraints constraints() const override;
  ErrorNorms errors(const Eigen::VectorXd& coefficients, const WorkShare& share) const override;
  bool reports_energy() const override { return true; }
  Messages messages() const override;

 private:
  bool extended_precision() const override { return true; }
  const BoundarySplit& boundary() const;
  mutable std::optional<BoundarySplit> boundary_;
};

}  // namespace iga
