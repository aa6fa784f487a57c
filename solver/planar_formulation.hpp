#pragma once
/// @file
/// Poisson and biharmonic problems on planar domains (problem.hpp) as a Formulation: the form of
/// the config summed in double-double, the source and natural boundary terms (Neumann flux,
/// ∫ Δu ∂v/∂n on simply supported plate edges), the essential data by boundary projection, the
/// errors in L2, H1 and H2.

#include <memory>
#include <optional>

#include "assembly/assembler.hpp"
#include "solver/boundary_edge_kinds.hpp"
#include "solver/formulation.hpp"

namespace iga {

/// Validate the problem's boundary part names against the space; throws InputError.
void check_boundary_parts(const Space& space, const ProblemSpec& problem);

class PlanarFormulation final : public Formulation {
 public:
  using Formulation::Formulation;
  void check() const override;
  Eigen::VectorXd load(const WorkShare& share) const override;
  Constraints constraints() const override;
  std::vector<FormTerm> terms() const override { return {Form(problem().form)}; }
  SplitMatrix matrix() const override;
  bool has_exact() const override { return problem().exact.has_value(); }
  ErrorNorms errors(const Eigen::VectorXd& coefficients, const WorkShare& share) const override;
  bool reports_energy() const override { return true; }
  Messages messages() const override;

 private:
  const BoundarySplit& boundary() const;
  /// The assembler of whole matrices and loads (built once, when a process assembles everything).
  const Assembler& assembler() const;
  mutable std::optional<BoundarySplit> boundary_;
  mutable std::unique_ptr<Assembler> assembler_;
};

}  // namespace iga
