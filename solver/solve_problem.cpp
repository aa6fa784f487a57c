#include "solver/solve_problem.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <cmath>

#include "assembly/assembler.hpp"
#include "config/progress.hpp"
#include "assembly/boundary_conditions.hpp"
#include "solver/boundary_edge_kinds.hpp"
#include "solver/petsc_solve_problem.hpp"
#include "solver/surface_problem.hpp"
#include "config/errors.hpp"

namespace iga {

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

BoundaryField boundary_field(const SymbolicFunction& f) {
  return [f](const Point2& x, const Point2&) { return f(x); };
}
}  // namespace

int assembly_quadrature_degree(const Space& space) {
  // 2p integrates products of basis functions on affine elements exactly, and data of degree p
  // against them (on tensor cells the Gauss rule of degree 2p is that of 2p + 1 anyway; on WS4's
  // 342 pieces it is 16 points instead of 19); non-affine maps get three more.
  return 2 * space.degree() + (space.affine_elements() ? 0 : 3);
}


void check_boundary_parts(const Space& space, const ProblemSpec& problem) {
  const std::vector<std::string> names = space.boundary_names();
  for (const BoundaryPart& part : problem.boundary) {
    if (part.name == "all" || std::find(names.begin(), names.end(), part.name) != names.end()) continue;
    std::string list = "all";
    for (const auto& n : names) list += ", " + n;
    const std::string near = nearest_word(part.name, names);
    throw InputError(part.where + ": unknown boundary part '" + part.name + "' of this " + space.type() +
                     " domain (parts: " + list + ")" + (near.empty() ? "" : " (did you mean '" + near + "'?)"));
  }
}

LinearSystem assemble_linear_system(const Space& space, const ProblemSpec& problem, const ProgressSink& progress) {
  const auto say = [&](const std::string& msg) {
    if (progress) progress(msg);
  };
  const int qa = assembly_quadrature_degree(space);
  const BoundarySplit boundary = split_boundary(space, problem);
  const EssentialBoundary& essential = boundary.essential;
  const std::vector<BoundaryEdge>& neumann_edges = boundary.neumann;
  const std::vector<BoundaryEdge>& simply_supported_edges = boundary.simply_supported;

  say("assembling");
  LinearSystem sys;
  // Ticks: one per element of the matrix loop and of the load loop.
  std::optional<ProgressPhase> phase(std::in_place, "assembling", 2 * static_cast<std::int64_t>(space.num_elements()));
  const Assembler assembler(space);
  // Extended precision: the residuals below must see A's entries beyond their double rounding.
  sys.A = assembler.matrix_extended(problem.form, qa);
  const FunctionBatch source_batch({problem.source});
  sys.b = assembler.load(
      [&source_batch](const Eigen::Matrix2Xd& x, Eigen::MatrixXd& values) { source_batch.evaluate(x, values); }, qa);
  Eigen::VectorXd& b = sys.b;
  const BoundaryField dudn = problem.normal_derivative_field();
  // Natural conditions: Neumann flux ∫ g_N v, and for simply supported plates ∫ Δu ∂v/∂n
  // (from ∫ Δ²u v = ∫ Δu Δv − ∫_Γ Δu ∂v/∂n when v = 0 on Γ).
  if (!neumann_edges.empty()) b += assembler.boundary_load(neumann_edges, dudn, Assembler::BoundaryTest::value, qa);
  if (!simply_supported_edges.empty())
    b += assembler.boundary_load(simply_supported_edges, boundary_field(problem.laplacian),
                                 Assembler::BoundaryTest::normal_derivative, qa);
  // NaN or inf data (sqrt of a negative number, a pole inside the domain) is bad input, not a
  // numerical failure: say which datum it was before the solver reports a singular system.
  if (!b.allFinite())
    throw InputError(problem.source_where +
                     ": the source term or boundary flux is not finite at some point of the domain "
                     "(a pole, or a log or root of a negative number?)");
  sys.constraints = impose_essential(space, essential, boundary_field(problem.value), dudn, qa);
  if (!sys.constraints.values.allFinite())
    throw InputError(problem.data_where + ": the boundary data (u or du/dn) are not finite at some boundary point");
  reduce_system(sys.A, sys.b, sys.constraints, sys.A_free, sys.b_free);
  phase.reset();
  return sys;
}

DiscreteSolution solve_problem(const Space& space, const ProblemSpec& problem, SolverKind solver,
                               const ProgressSink& progress, const PetscSettings& petsc) {
  if (solver == SolverKind::petsc) return solve_problem_petsc(space, problem, petsc, progress);
  const auto say = [&](const std::string& msg) {
    if (progress) progress(msg);
  };
  if (problem.pde == Pde::laplace_beltrami) return solve_surface_problem(space, problem, solver, progress);
  check_boundary_parts(space, problem);
  DiscreteSolution out;
  LevelResult& r = out.result;
  r.h = space.mesh_size();
  r.dofs = space.dimension();
  r.elements = space.num_elements();

  auto t0 = Clock::now();
  const LinearSystem sys = assemble_linear_system(space, problem, progress);
  const SplitMatrix& A = sys.A;
  const Eigen::VectorXd& b = sys.b;
  const Constraints& constraints = sys.constraints;
  const SparseMatrix& A_free = sys.A_free;
  const Eigen::VectorXd& b_free = sys.b_free;
  r.t_assemble = seconds_since(t0);
  r.free_dofs = static_cast<int>(constraints.free.size());
  out.boundary_constrained = static_cast<int>(constraints.constrained.size());

  say("factorizing and solving (" + std::to_string(r.free_dofs) + " unknowns)");
  t0 = Clock::now();
  std::optional<ProgressPhase> phase(std::in_place, "factorizing", 0);
  const Eigen::VectorXd u_free =
      solve_linear_system(A_free, b_free, solver, out.solve, [&](const Eigen::VectorXd& x) {
        return reduced_residual(A, b, constraints, x);
      });
  out.coefficients = expand_solution(u_free, constraints);
  r.energy = out.coefficients.dot(A.high * out.coefficients);  // a(u_h, u_h), for studies without an exact solution
  phase.reset();
  r.t_solve = seconds_since(t0);

  r.g1_jump = space.max_gradient_jump(out.coefficients);
  if (problem.exact) {
    say("computing errors");
    t0 = Clock::now();
    phase.emplace("error norms", space.num_elements());
    const ErrorNorms e = error_norms(space, out.coefficients, problem.exact_solution(), space.error_quadrature_degree());
    if (!std::isfinite(e.l2) || !std::isfinite(e.h1.value_or(0)) || !std::isfinite(e.h2.value_or(0)))
      throw InputError(problem.data_where + ": the exact solution or its derivatives are not finite somewhere in the domain");
    r.l2 = e.l2;
    r.h1 = e.h1;
    r.h2 = e.h2;
    phase.reset();
    r.t_errors = seconds_since(t0);
  }
  return out;
}

}  // namespace iga
