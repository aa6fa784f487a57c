// embed_clamped_plate: iga-run used as a library, without a config file.
//
// Solves the clamped plate  Δ²u = f on the unit square, u = ∂u/∂n = 0 on the boundary, with
// exact solution u = (cos 4πx − 1)(cos 4πy − 1), on cubic C2 B-splines of 4, 8, ..., 64 elements
// per direction, and prints L2 / H1 / H2 errors with rates (expected 4, 3, 2). The same study
// from a config: `iga-run configs/bspline-biharmonic.yaml`.
//
// Sample run:   ./build/embed_clamped_plate
#include <cstdio>
#include <memory>

#include "solver/problem.hpp"
#include "solver/solve_problem.hpp"
#include "spaces/bspline/tensor_bspline_space.hpp"

int main() {
  using namespace iga;

  // 1. The problem: source and boundary data are derived from the exact solution symbolically.
  const SymbolicFunction u = SymbolicFunction::parse("(cos(4*pi*x)-1)*(cos(4*pi*y)-1)", "example");
  const ProblemSpec problem = manufactured_problem(Pde::biharmonic, u, {{"all", BoundaryKind::clamped, "example"}});

  // 2. The geometry: the unit square as a (bilinear) patch.
  const auto square = std::make_shared<const PatchGeometry>(PatchGeometry::rectangle({0, 0}, {1, 1}));

  LevelResult previous;
  for (int level = 0; level < 5; ++level) {
    // 3. The space: cubic C2 B-splines on a uniform mesh of n x n elements.
    const int n = 4 << level;
    const auto space = std::make_shared<TensorBSplineSpace>(square, KnotVector::uniform(3, 2, n),
                                                            KnotVector::uniform(3, 2, n));
    // 4. Assemble, impose the clamped conditions, solve with CHOLMOD, measure errors.
    const DiscreteSolution s = solve_problem(*space, problem, SolverKind::cholmod);
    const LevelResult& r = s.result;
    // 5. Report, with rates from the previous level.
    if (level == 0) std::printf("%6s %8s %12s %6s %12s %6s %12s %6s\n", "n", "dofs", "L2", "rate", "H1", "rate", "H2", "rate");
    auto k = [&](std::optional<double> a, std::optional<double> b) {
      return level == 0 ? 0.0 : rate(a, b, previous.h, r.h).value_or(0.0);
    };
    std::printf("%6d %8d %12.4e %6.2f %12.4e %6.2f %12.4e %6.2f\n", n, r.dofs, *r.l2, k(previous.l2, r.l2), *r.h1,
                k(previous.h1, r.h1), *r.h2, k(previous.h2, r.h2));
    previous = r;
  }
  return 0;
}
