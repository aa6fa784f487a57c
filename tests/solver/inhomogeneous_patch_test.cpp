// Patch tests for every space: a polynomial inside the space, with inhomogeneous Dirichlet
// (Poisson), clamped and simply supported (biharmonic) data, is solved to round-off at every level
// of a refinement study — relative errors in L2, H1 and H2 stay at the level double coefficients
// can represent instead of growing like h⁻⁴ (the biharmonic condition number).
//
// Each polynomial has a large low-degree part (1 + x ...): the stiffness matrix maps it to zero
// only in exact arithmetic, so it shows how well the essential data and the residuals are handled.
//
// Studies whose finest levels pass 1e5 DOFs have those levels in an instance of their own
// (name ending in _large), so ctest runs them as separate entries.
//
// Scaled down in Debug and sanitizer builds, where the finest levels take many minutes: there the
// last level is min(last, IGA_PATCH_TEST_MAX_LEVEL) with a default of 2 (unlimited in Release);
// a _large instance then runs that level instead. Set IGA_PATCH_TEST_MAX_LEVEL to run more.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "assembly/assembler.hpp"
#include "solver/solve_problem.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {

struct PatchStudy {
  const char* name;
  const char* yaml;
  int first_level, last_level;
  double floor_multiple = 30;  ///< H2 bound in units of the coefficients' rounding floor (below)
};

// Relative bounds: 1e-11 in L2 and H1. In H2 the coefficients themselves set a floor: rounding
// each c_j to double moves it by up to ε|c_j|, which changes |u_h|²_H2 by Σ_j K_jj (ε c_j)² on
// average (K the Hessian-form matrix, K_jj ~ h⁻² growing with refinement). The H2 bound is 1e-11
// plus a generous multiple of that floor, computed from the solution and the space.
constexpr double kTolerance = 1e-11;
// G1 basis functions are combinations of Bernstein polynomials found by double-precision QR and
// SVD: the rounding of those combinations is a second floor of the same form, larger by the
// conditioning of the local problems (the Poisson case, whose solve is accurate to L2 1e-15,
// sits at 65x the coefficients' floor on level 4).
constexpr double kG1FloorMultiple = 300;

#if defined(NDEBUG) && !defined(__SANITIZE_ADDRESS__)
constexpr int kDefaultMaxLevel = 99;
#else
constexpr int kDefaultMaxLevel = 2;
#endif

/// The finest level this build runs (see the file comment).
int max_level() {
  const char* v = std::getenv("IGA_PATCH_TEST_MAX_LEVEL");
  return v && *v ? std::atoi(v) : kDefaultMaxLevel;
}

double h2_rounding_floor(const Space& space, const Eigen::VectorXd& c) {
  const SparseMatrix k = Assembler(space).matrix(BilinearForm::hessian, assembly_quadrature_degree(space));
  return std::numeric_limits<double>::epsilon() * std::sqrt(k.diagonal().dot(c.cwiseAbs2()));
}

const PatchStudy kStudies[] = {
    // ---- tensor-product B-splines
    {"bspline_poisson_dirichlet_p2", R"yaml(
problem: {pde: poisson, exact: "1 + x - 2*y + x^2 - 3*x*y + 0.5*y^2", boundary: {all: dirichlet}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 2, elements: [5, 5]}
)yaml", 0, 5},
    {"bspline_poisson_dirichlet_p2_large", R"yaml(
problem: {pde: poisson, exact: "1 + x - 2*y + x^2 - 3*x*y + 0.5*y^2", boundary: {all: dirichlet}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 2, elements: [5, 5]}
)yaml", 6, 6},
    {"bspline_clamped_p4", R"yaml(
problem: {pde: biharmonic, exact: "x^3*y + x^2*y^2 - y^4 + 1 + x", boundary: {all: clamped}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 4, elements: [5, 5]}
)yaml", 0, 5},
    {"bspline_clamped_p4_large", R"yaml(
problem: {pde: biharmonic, exact: "x^3*y + x^2*y^2 - y^4 + 1 + x", boundary: {all: clamped}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 4, elements: [5, 5]}
)yaml", 6, 6},
    {"bspline_simply_supported_p3", R"yaml(
problem: {pde: biharmonic, exact: "x^3 + x^2*y - y^3 + 2 + x", boundary: {all: simply_supported}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 3, elements: [5, 5]}
)yaml", 0, 5},
    {"bspline_simply_supported_p3_large", R"yaml(
problem: {pde: biharmonic, exact: "x^3 + x^2*y - y^3 + 2 + x", boundary: {all: simply_supported}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 3, elements: [5, 5]}
)yaml", 6, 6},
    // ---- WS4 C3 quartic macro-elements: quartics
    {"ws4_poisson_dirichlet", R"yaml(
problem: {pde: poisson, exact: "x^4 - 2*x^2*y^2 + x*y^3 + y^2 - x + 1", boundary: {all: dirichlet}}
domain: {type: unit_square}
space: {type: ws4, elements: 2}
)yaml", 0, 4},
    {"ws4_clamped", R"yaml(
problem: {pde: biharmonic, exact: "x^3*y + x^2*y^2 - y^4 + 1 + x", boundary: {all: clamped}}
domain: {type: unit_square}
space: {type: ws4, elements: 2}
)yaml", 0, 4},
    {"ws4_clamped_large", R"yaml(
problem: {pde: biharmonic, exact: "x^3*y + x^2*y^2 - y^4 + 1 + x", boundary: {all: clamped}}
domain: {type: unit_square}
space: {type: ws4, elements: 2}
)yaml", 5, 5},
    // The plates need the matrix and the residuals in double-double (docs/known-limits.md):
    // with long double ones WS4 clamped passed 1e-11 in H1 already at 35 850 DOFs.
    {"ws4_simply_supported", R"yaml(
problem: {pde: biharmonic, exact: "x^4 - 3*x^2*y^2 + x*y + y + 2", boundary: {all: simply_supported}}
domain: {type: unit_square}
space: {type: ws4, elements: 2}
)yaml", 0, 4},
    {"ws4_simply_supported_large", R"yaml(
problem: {pde: biharmonic, exact: "x^4 - 3*x^2*y^2 + x*y + y + 2", boundary: {all: simply_supported}}
domain: {type: unit_square}
space: {type: ws4, elements: 2}
)yaml", 5, 5},
    // ---- T-meshes, polynomial sections of degree 3 (bicubics), C1 across T-junctions
    {"tmesh_poisson_dirichlet", R"yaml(
problem: {pde: poisson, exact: "x^3*y^2 - 2*x*y^3 + x^2 + y + 1", boundary: {all: dirichlet}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: tmesh, section: poly, n: 3, regularity: 1, elements: [2, 2], refine: [[0, 0, 0.5, 0.5], [0.25, 0.25, 0.5, 0.5]]}
)yaml", 0, 5},
    {"tmesh_poisson_dirichlet_large", R"yaml(
problem: {pde: poisson, exact: "x^3*y^2 - 2*x*y^3 + x^2 + y + 1", boundary: {all: dirichlet}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: tmesh, section: poly, n: 3, regularity: 1, elements: [2, 2], refine: [[0, 0, 0.5, 0.5], [0.25, 0.25, 0.5, 0.5]]}
)yaml", 6, 6},
    {"tmesh_clamped", R"yaml(
problem: {pde: biharmonic, exact: "x^3*y^2 - 2*x*y^3 + x^2 + y + 1", boundary: {all: clamped}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: tmesh, section: poly, n: 3, regularity: 1, elements: [2, 2], refine: [[0, 0, 0.5, 0.5], [0.25, 0.25, 0.5, 0.5]]}
)yaml", 0, 4},
    {"tmesh_simply_supported", R"yaml(
problem: {pde: biharmonic, exact: "x^3*y^3 - x^2*y + 3*y^2 + x + 2", boundary: {all: simply_supported}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: tmesh, section: poly, n: 3, regularity: 1, elements: [2, 2], refine: [[0, 0, 0.5, 0.5], [0.25, 0.25, 0.5, 0.5]]}
)yaml", 0, 4},
    {"tmesh_clamped_large", R"yaml(
problem: {pde: biharmonic, exact: "x^3*y^2 - 2*x*y^3 + x^2 + y + 1", boundary: {all: clamped}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: tmesh, section: poly, n: 3, regularity: 1, elements: [2, 2], refine: [[0, 0, 0.5, 0.5], [0.25, 0.25, 0.5, 0.5]]}
)yaml", 5, 6},
    {"tmesh_simply_supported_large", R"yaml(
problem: {pde: biharmonic, exact: "x^3*y^3 - x^2*y + 3*y^2 + x + 2", boundary: {all: simply_supported}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: tmesh, section: poly, n: 3, regularity: 1, elements: [2, 2], refine: [[0, 0, 0.5, 0.5], [0.25, 0.25, 0.5, 0.5]]}
)yaml", 5, 6},
    // ---- G1 multipatch, degree 5: quintics. The bilinear patches of 3p_square make the
    // integrands rational, so coarse levels carry Gauss-quadrature error (level 0: 1e-10 in L2; the
// clamped plate's H2 at level 1: 2.5e-11), which falls like h^15, not round-off.
    {"g1_poisson_dirichlet", R"yaml(
problem: {pde: poisson, exact: "x^5 - 2*x^3*y^2 + x*y^4 + x^2*y - y^3 + 1 + x", boundary: {all: dirichlet}}
domain: {type: multipatch, name: 3p_square}
space: {type: g1, degree: 5}
)yaml", 1, 5, kG1FloorMultiple},
    {"g1_poisson_dirichlet_large", R"yaml(
problem: {pde: poisson, exact: "x^5 - 2*x^3*y^2 + x*y^4 + x^2*y - y^3 + 1 + x", boundary: {all: dirichlet}}
domain: {type: multipatch, name: 3p_square}
space: {type: g1, degree: 5}
)yaml", 6, 6, kG1FloorMultiple},
    {"g1_clamped", R"yaml(
problem: {pde: biharmonic, exact: "x^5 - 2*x^3*y^2 + x*y^4 + x^2*y - y^3 + 1 + x", boundary: {all: clamped}}
domain: {type: multipatch, name: 3p_square}
space: {type: g1, degree: 5}
)yaml", 2, 5, kG1FloorMultiple},
    {"g1_clamped_large", R"yaml(
problem: {pde: biharmonic, exact: "x^5 - 2*x^3*y^2 + x*y^4 + x^2*y - y^3 + 1 + x", boundary: {all: clamped}}
domain: {type: multipatch, name: 3p_square}
space: {type: g1, degree: 5}
)yaml", 6, 6, kG1FloorMultiple},
    {"g1_simply_supported", R"yaml(
problem: {pde: biharmonic, exact: "x^4*y - 3*x^2*y^3 + x*y + 2*y + 1", boundary: {all: simply_supported}}
domain: {type: multipatch, name: 3p_square}
space: {type: g1, degree: 5}
)yaml", 1, 5, kG1FloorMultiple},
};

class InhomogeneousPatch : public ::testing::TestWithParam<PatchStudy> {};

}  // namespace

TEST_P(InhomogeneousPatch, PolynomialIsSolvedToRoundOffAtEveryLevel) {
  const PatchStudy& c = GetParam();
  const ProblemSpec problem = test::problem_from_yaml(c.yaml);
  const int last = std::min(c.last_level, max_level()), first = std::min(c.first_level, last);
  if (last < c.last_level)
    std::printf("%s: scaled down to levels %d..%d in this build (IGA_PATCH_TEST_MAX_LEVEL)\n", c.name, first, last);
  for (int level = first; level <= last; ++level) {
    const SpacePtr space = test::space_from_yaml(c.yaml, level);
    const DiscreteSolution s = solve_problem(*space, problem, SolverKind::cholmod);
    // The norms of u itself: the errors of the zero function.
    const ErrorNorms u = error_norms(*space, Eigen::VectorXd::Zero(space->dimension()), problem.exact_solution(),
                                     space->error_quadrature_degree());
    ASSERT_TRUE(s.result.l2 && s.result.h1 && s.result.h2 && u.h1 && u.h2);
    const double l2 = *s.result.l2 / u.l2, h1 = *s.result.h1 / *u.h1, h2 = *s.result.h2 / *u.h2;
    const double floor = h2_rounding_floor(*space, s.coefficients) / *u.h2;
    std::printf("%-28s level %d dofs %7d  L2 %.2e  H1 %.2e  H2 %.2e  (relative; H2 rounding floor %.1e)\n", c.name,
                level, space->dimension(), l2, h1, h2, floor);
    EXPECT_LT(l2, kTolerance) << c.name << " level " << level;
    EXPECT_LT(h1, kTolerance) << c.name << " level " << level;
    EXPECT_LT(h2, kTolerance + c.floor_multiple * floor) << c.name << " level " << level;
  }
}

INSTANTIATE_TEST_SUITE_P(AllSpaces, InhomogeneousPatch, ::testing::ValuesIn(kStudies),
                         [](const auto& info) { return std::string(info.param.name); });
