#include "solver/surface_problem.hpp"

#include <chrono>
#include <cmath>

#include "assembly/assembler.hpp"
#include "assembly/error_norms.hpp"
#include "assembly/surface_dirichlet.hpp"
#include "assembly/surface_load.hpp"
#include "config/errors.hpp"

namespace iga {

namespace {
SurfaceField field(const SymbolicFunction& f) {
  return [f](const Eigen::Vector3d& x) { return f.at(x); };
}
}  // namespace

SurfaceExactSolution surface_exact_solution(const ProblemSpec& problem) {
  SurfaceExactSolution s;
  if (!problem.surface_exact) return s;
  const SymbolicFunction& u = *problem.surface_exact;
  s.u = field(u);
  s.ux = field(u.diff_x());
  s.uy = field(u.diff_y());
  s.uz = field(u.diff_z());
  return s;
}

SurfaceSource surface_source(const ProblemSpec& problem) {
  if (problem.surface_source || !problem.surface_exact) {
    const SymbolicFunction f = problem.surface_source.value_or(SymbolicFunction::constant(0.0));
    return [f](const Eigen::Vector3d& x, const Eigen::Vector3d&, double) { return f.at(x); };
  }
  const SymbolicFunction u = *problem.surface_exact;
  const SymbolicFunction ux = u.diff_x(), uy = u.diff_y(), uz = u.diff_z();
  const SymbolicFunction uxx = ux.diff_x(), uxy = ux.diff_y(), uxz = ux.diff_z(), uyy = uy.diff_y(),
                         uyz = uy.diff_z(), uzz = uz.diff_z();
  const double c = problem.reaction;
  return [=](const Eigen::Vector3d& x, const Eigen::Vector3d& n, double H) {
    const Eigen::Vector3d g(ux.at(x), uy.at(x), uz.at(x));
    Eigen::Matrix3d D;
    D << uxx.at(x), uxy.at(x), uxz.at(x), uxy.at(x), uyy.at(x), uyz.at(x), uxz.at(x), uyz.at(x), uzz.at(x);
    const double laplace_beltrami = D.trace() - n.dot(D * n) - H * g.dot(n);
    return -laplace_beltrami + c * u.at(x);
  };
}

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
}  // namespace

DiscreteSolution solve_surface_problem(const Space& space, const ProblemSpec& problem, SolverKind solver,
                                       const ProgressSink& progress) {
  const auto say = [&](const std::string& msg) {
    if (progress) progress(msg);
  };
  if (space.ambient_dimension() != 3)
    throw InputError(problem.source_where + ": laplace_beltrami needs a space on a surface in 3D");
  const std::vector<BoundaryEdge> boundary = space.boundary_edges("all");
  const bool open = !boundary.empty();
  if (open && !problem.surface_dirichlet)
    throw InputError(problem.source_where +
                     ": this surface has a boundary: give Dirichlet data on it (problem.boundary: {all: dirichlet})");
  if (!open && problem.surface_dirichlet)
    throw InputError(problem.boundary.front().where + ": this surface is closed (it has no boundary for Dirichlet data)");
  DiscreteSolution out;
  LevelResult& r = out.result;
  r.h = space.mesh_size();
  r.dofs = space.dimension();
  r.elements = space.num_elements();
  r.free_dofs = space.dimension();
  const int qa = assembly_quadrature_degree(space);

  say("assembling");
  auto t0 = Clock::now();
  const Assembler assembler(space);
  const SparseMatrix M = assembler.matrix(BilinearForm::mass, qa);
  SparseMatrix A = assembler.matrix(BilinearForm::laplace, qa);
  if (problem.reaction > 0) A += problem.reaction * M;
  Eigen::VectorXd b = surface_load(space, surface_source(problem), qa);
  if (!b.allFinite())
    throw InputError(problem.source_where + ": the source term is not finite at some point of the surface");
  // Without reaction, constants (Σ N_i = 1) span the kernel: make the load orthogonal to them
  // (∫f = 0 holds for exact data only up to quadrature), pin one coefficient, and shift the
  // solution to zero mean afterwards.
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(space.dimension());
  const Eigen::VectorXd mass_of_one = M * ones;
  const double area = ones.dot(mass_of_one);
  const bool pure = problem.reaction == 0 && !open;
  if (pure) {
    b -= (b.sum() / area) * mass_of_one;
    A.prune([](Eigen::Index i, Eigen::Index j, double) { return i != 0 && j != 0; });
    A.coeffRef(0, 0) = 1.0;
    b(0) = 0.0;
  }

  Constraints constraints;
  if (open) {
    const SymbolicFunction g = *problem.surface_dirichlet;
    constraints = surface_dirichlet_constraints(
        space, boundary, [g](const Eigen::Vector3d& x) { return g.at(x); }, qa);
    r.free_dofs = static_cast<int>(constraints.free.size());
  }
  r.t_assemble = seconds_since(t0);

  say("factorizing and solving (" + std::to_string(r.free_dofs) + " unknowns)");
  t0 = Clock::now();
  if (open) {
    SparseMatrix A_free;
    Eigen::VectorXd b_free;
    reduce_system(A, b, constraints, A_free, b_free);
    out.coefficients = expand_solution(solve_linear_system(A_free, b_free, solver, out.solve), constraints);
  } else {
    out.coefficients = solve_linear_system(A, b, solver, out.solve);
  }
  if (pure) {
    out.coefficients.array() -= mass_of_one.dot(out.coefficients) / area;
    // With an exact solution, compare with its own mean: ∫u = Σ_i ∫u N_i.
    if (problem.surface_exact) {
      const SymbolicFunction u = *problem.surface_exact;
      const double mean =
          surface_load(space, [u](const Eigen::Vector3d& x, const Eigen::Vector3d&, double) { return u.at(x); },
                       space.error_quadrature_degree())
              .sum() / area;
      out.coefficients.array() += mean;
    }
  }
  r.t_solve = seconds_since(t0);

  if (problem.surface_exact) {
    say("computing errors");
    t0 = Clock::now();
    const ErrorNorms e =
        surface_error_norms(space, out.coefficients, surface_exact_solution(problem), space.error_quadrature_degree());
    if (!std::isfinite(e.l2) || !std::isfinite(e.h1.value_or(0)))
      throw InputError(problem.data_where + ": the exact solution or its gradient is not finite somewhere on the surface");
    r.l2 = e.l2;
    r.h1 = e.h1;
    r.t_errors = seconds_since(t0);
  }
  r.g1_jump = space.max_gradient_jump(out.coefficients);  // surface gradient jump of C1 spaces on surfaces
  return out;
}

}  // namespace iga
