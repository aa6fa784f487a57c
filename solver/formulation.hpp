#pragma once
/// @file
/// What a problem poses on a space, as the solve pipeline (solver/pipeline.hpp) needs it: the
/// load, the essential conditions, the matrix (whole, or element by element from its terms), the
/// errors. The pipeline's seam between kinds of problem — planar second- and fourth-order problems
/// (planar_formulation.hpp), Laplace–Beltrami on surfaces (surface_problem.hpp) — so that the
/// steps themselves are written once for every problem and every solver backend.

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "assembly/assembler.hpp"
#include "assembly/boundary_conditions.hpp"
#include "assembly/element_subset_assembly.hpp"
#include "assembly/error_norms.hpp"
#include "assembly/split_matrix.hpp"
#include "solver/problem.hpp"

namespace iga {

/// Quadrature degree used for assembly with a space of local degree p (documented in docs/problems.md;
/// error norms use Space::error_quadrature_degree).
int assembly_quadrature_degree(const Space& space);

/// The part of a solve this process does: the elements it integrates over (all of them when
/// `elements` is null, as in a serial run) and how its partial sums become totals (a sum over the
/// MPI ranks; the value itself when serial). Loads, errors and the sums below add up over the shares.
struct WorkShare {
  const std::vector<int>* elements = nullptr;
  /// The shares are the MPI ranks' (petsc_session.hpp): sum, max and first are collective. Else
  /// each returns the value itself.
  bool over_ranks = false;
  double sum(double part) const;
  /// For processes that hold parts of a space (rank_part.hpp): the largest of the values, and the
  /// value of the lowest process that has one (not NaN).
  double max(double part) const;
  double first(double value) const;
};

/// The edges of `edges` on the share's elements, in their order (all of them when the share is the
/// whole space); `num_elements`: the space's.
std::vector<BoundaryEdge> edges_of_share(const std::vector<BoundaryEdge>& edges, const WorkShare& share,
                                         int num_elements);

class Formulation {
 public:
  Formulation(const Space& space, const ProblemSpec& problem);
  virtual ~Formulation() = default;
  Formulation(const Formulation&) = delete;
  Formulation& operator=(const Formulation&) = delete;

  const Space& space() const { return space_; }
  const ProblemSpec& problem() const { return problem_; }
  /// Components of the unknown field on the scalar space: 1, or 3 for a shell's displacement.
  /// The unknowns are numbered in blocks, component c of function i at c · dimension + i
  /// (assembler.hpp): loads, constraints and coefficients have unknowns() entries.
  virtual int components() const { return 1; }
  int unknowns() const { return components() * space_.dimension(); }
  int quadrature_degree() const { return quadrature_degree_; }
  /// The problem's operator as Σ coefficient · form (ProblemSpec::terms): what the backends
  /// assemble, whole (matrix) or element by element (for_each_element_matrix).
  const std::vector<FormTerm>& terms() const { return problem_.terms; }

  /// Input errors seen from the space alone (boundary part names, surface without boundary
  /// data, ...), before any work.
  virtual void check() const {}
  /// The load of the share's elements, natural boundary terms on their edges included; the
  /// shares' loads add up to the whole load (length: unknowns()).
  virtual Eigen::VectorXd load(const WorkShare& share) const = 0;
  /// The essential conditions (every process computes them whole: a boundary-sized problem).
  virtual Constraints constraints() const = 0;
  /// The whole matrix Σ terms, for a process that assembles every element: terms() for the
  /// linear system; a mass term too for an eigenproblem K x = λ M x under the same constraints.
  /// Summed in double-double where extended_precision() says (one term then). A formulation with
  /// terms beyond the element integrals (the C0 interior penalty edges) adds them here.
  virtual SplitMatrix matrix(const std::vector<FormTerm>& terms) const;
  /// The matrix terms beyond the element integrals that belong to one element each (a shell's
  /// Nitsche terms on the edges that hold its rotation), for the elements of `elements` that have
  /// some, handed to `sink` with rows numbered as for_each_element_matrix's: what a backend that
  /// assembles element by element (PETSc) adds to the terms'. matrix() includes them. None here.
  virtual void for_each_extra_element_matrix(const std::vector<int>& /*elements*/,
                                             const ElementMatrixSink& /*sink*/) const {}
  /// The coefficients after the solve (problems fixed up to a constant shift to their mean here).
  virtual void finish(Eigen::VectorXd& /*coefficients*/, const WorkShare& /*share*/) const {}
  /// An exact solution (in x, y or in x, y, z) to measure the errors against.
  virtual bool has_exact() const { return problem_.exact || problem_.surface_exact; }
  /// Errors over the share's elements against the exact solution.
  virtual ErrorNorms errors(const Eigen::VectorXd& coefficients, const WorkShare& share) const = 0;
  /// What the last load() / constraints() decided that a user should see (where point loads
  /// were placed, which coefficients were pinned): printed as progress messages.
  virtual std::vector<std::string> notes() const { return {}; }
  /// True when a(u_h, u_h) means the energy of the solution (reported for planar problems).
  virtual bool reports_energy() const { return false; }
  /// True when a process holding only part of the space (rank_part.hpp) computes its share of
  /// the load and the conditions the serial run would: false where the conditions come from a
  /// choice over the whole space (a pinned coefficient) or from another space (a lift's planar one).
  virtual bool works_on_parts() const;

  /// Input errors the pipeline raises when data turn out not finite, naming their config place.
  struct Messages {
    std::string load, boundary_data, exact;
  };
  virtual Messages messages() const = 0;

 protected:
  /// True when refinement residuals need the matrix entries beyond their double rounding
  /// (split_matrix.hpp): plates, whose error floor grows like h⁻⁴ otherwise.
  virtual bool extended_precision() const { return false; }
  /// The assembler of whole matrices and loads (built once, when a process assembles everything).
  const Assembler& assembler() const;

 private:
  const Space& space_;
  const ProblemSpec& problem_;
  int quadrature_degree_;
  mutable std::unique_ptr<Assembler> assembler_;
};

}  // namespace iga
