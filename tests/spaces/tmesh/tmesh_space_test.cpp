// TMeshSpace: dimension, C^r continuity across every edge (T-junction edges included), linear
// independence, Hermite self-consistency and exact solution of a problem whose solution is in the space.
#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <cstdio>
#include <numbers>
#include <random>

#include "solver/solve_problem.hpp"
#include "tests/spaces/tmesh/brute_force_dimension.hpp"
#include "spaces/tmesh/tmesh_space.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {

constexpr double pi = std::numbers::pi;

/// The dyadic hierarchical T-mesh of the notes (§7.5) on [0, pi]^2 through the config path.
std::string dyadic_yaml(const std::string& section, int n, int r, double w = 1.0) {
  return "domain: {type: rectangle, min: [0, 0], max: [3.141592653589793, 3.141592653589793]}\n"
         "space: {type: tmesh, section: " + section + ", n: " + std::to_string(n) + ", regularity: " + std::to_string(r) +
         ", frequency: " + std::to_string(w) + ", elements: [2, 2], refine: [[0, 0, 0.5, 0.5], [0.25, 0.25, 0.5, 0.5]]}\n";
}

const TMeshSpace& as_tmesh(const SpacePtr& s) { return dynamic_cast<const TMeshSpace&>(*s); }

/// Max relative jump of D^(a,b) (a, b <= r) of a random spline across every shared side piece,
/// and the max jump of the second normal derivative (a negative control for r = 1).
std::pair<double, double> max_jumps(const TMeshSpace& space, int r, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> U(-1, 1);
  Eigen::VectorXd u(space.dimension());
  for (int k = 0; k < u.size(); ++k) u(k) = U(gen);
  const TMesh& mesh = space.mesh();
  auto ev = space.make_evaluator();
  PointValues pv;
  double jump = 0.0, scale = 0.0, control = 0.0;
  // Physical derivatives at a physical point of a cell: value, dx, dy, dxy, dxx, dyy.
  auto derivs = [&](int c, Point2 x) {
    Point2 lo, hi;
    space.cell_box(c, lo, hi);
    QuadratureRule rule;
    rule.points = {(x - lo).cwiseQuotient(hi - lo)};
    rule.weights = {1.0};
    ev->evaluate(c, rule, update_values | update_gradients | update_hessians, pv);
    Eigen::Matrix<double, 6, 1> d = Eigen::Matrix<double, 6, 1>::Zero();
    for (int a = 0; a < pv.num_functions(); ++a) {
      const double ua = u(pv.dofs[a]);
      d(0) += ua * pv.value(a, 0);
      d(1) += ua * pv.dx(a, 0);
      d(2) += ua * pv.dy(a, 0);
      d(3) += ua * pv.dxy(a, 0);
      d(4) += ua * pv.dxx(a, 0);
      d(5) += ua * pv.dyy(a, 0);
    }
    return d;
  };
  const auto& cells = mesh.cells();
  for (int a = 0; a < mesh.num_cells(); ++a)
    for (int b = 0; b < mesh.num_cells(); ++b)
      for (int dir = 0; dir < 2; ++dir) {
        const TCell &A = cells[a], &B = cells[b];
        const bool horizontal = dir == 0;
        if (horizontal ? A.y1 != B.y0 : A.x1 != B.x0) continue;
        const auto lo = horizontal ? std::max(A.x0, B.x0) : std::max(A.y0, B.y0);
        const auto hi = horizontal ? std::min(A.x1, B.x1) : std::min(A.y1, B.y1);
        if (lo >= hi) continue;
        for (double t : {0.0, 0.13, 0.5, 0.77, 1.0}) {
          const double z = lo + t * double(hi - lo);
          const Point2 x = horizontal ? mesh.point(0, A.y1) + Point2(z * mesh.unit().x(), 0)
                                      : mesh.point(A.x1, 0) + Point2(0, z * mesh.unit().y());
          const auto da = derivs(a, x), db = derivs(b, x);
          const int checked = r == 0 ? 1 : 4;  // C^1: value, dx, dy, dxy
          for (int k = 0; k < checked; ++k) {
            jump = std::max(jump, std::abs(da(k) - db(k)));
            scale = std::max(scale, std::abs(da(k)));
          }
          const int normal2 = horizontal ? 5 : 4;
          const int normal1 = horizontal ? 2 : 1;
          control = std::max(control, std::abs(da(r == 0 ? normal1 : normal2) - db(r == 0 ? normal1 : normal2)));
        }
      }
  return {jump / scale, control / scale};
}

/// Smallest / largest singular value of the values of all global functions at (n+1)^2 points per cell.
double independence(const Space& s, int n) {
  QuadratureRule rule;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) rule.points.push_back({(i + 0.3) / (n + 1), (j + 0.6) / (n + 1)}), rule.weights.push_back(1);
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(s.num_elements() * rule.size(), s.dimension());
  auto ev = s.make_evaluator();
  PointValues pv;
  for (int c = 0; c < s.num_elements(); ++c) {
    ev->evaluate(c, rule, update_values, pv);
    for (int a = 0; a < pv.num_functions(); ++a)
      for (int q = 0; q < rule.size(); ++q) M(c * rule.size() + q, pv.dofs[a]) = pv.value(a, q);
  }
  const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXd>(M).singularValues();
  return sv(sv.size() - 1) / sv(0);
}

}  // namespace

TEST(TmeshSpace, DimensionEqualsFormulaAndBruteForce) {
  const int cases[][2] = {{3, 1}, {2, 0}, {5, 1}, {3, 0}, {5, 2}};
  const int expected[] = {52, 45, 180, 97, -1};
  for (int k = 0; k < 5; ++k) {
    const auto [n, r] = cases[k];
    const SpacePtr s = test::space_from_yaml(dyadic_yaml("trig", n, r));
    const TMeshSpace& t = as_tmesh(s);
    EXPECT_EQ(t.dimension(), t.mesh().dimension_formula(r, r));
    if (expected[k] > 0) EXPECT_EQ(t.dimension(), expected[k]);
    EXPECT_LT(t.extraction().corner_mismatch, 1e-9) << n << " " << r;
  }
  const SpacePtr s = test::space_from_yaml(dyadic_yaml("hyperbolic", 4, 1, 2.0), 1);
  EXPECT_EQ(s->dimension(), brute_force_dimension(as_tmesh(s).mesh(), 1, 1));
}

TEST(TmeshSpace, SmoothAcrossEveryEdgeIncludingTJunctions) {
  for (const auto& [section, n, r] : {std::tuple<std::string, int, int>{"trig", 3, 1}, {"trig", 2, 0}, {"poly", 5, 1},
                                      {"hyperbolic", 3, 1}, {"trig", 4, 1}}) {
    const SpacePtr s = test::space_from_yaml(dyadic_yaml(section, n, r), 1);
    const auto [jump, control] = max_jumps(as_tmesh(s), r, 7);
    std::printf("C^%d %s n=%d: max relative jump %.2e, D^(r+1) jump %.2e\n", r, section.c_str(), n, jump, control);
    EXPECT_LT(jump, 1e-11) << section << " n=" << n << " r=" << r;
    EXPECT_GT(control, 1e-3) << section << " n=" << n << " r=" << r;  // not smoother than claimed
  }
}

TEST(TmeshSpace, BasisIsLinearlyIndependent) {
  const SpacePtr s = test::space_from_yaml(dyadic_yaml("trig", 3, 1));
  EXPECT_GT(independence(*s, 3), 1e-8);
}

TEST(TmeshSpace, PoissonSolutionInTheSpaceIsReproduced) {
  // sin x sin y lies in the trig w = 1 space for every n >= 2: round-off error (notes §8.5).
  for (const auto& [n, r] : {std::pair{2, 0}, {3, 1}, {3, 0}}) {
    const std::string yaml = dyadic_yaml("trig", n, r) +
                             "problem: {pde: poisson, exact: \"sin(x)*sin(y)\", boundary: {all: dirichlet}}\n";
    const SpacePtr s = test::space_from_yaml(yaml);
    const DiscreteSolution sol = solve_problem(*s, test::problem_from_yaml(yaml), SolverKind::cholmod);
    std::printf("sin x sin y, trig n=%d r=%d: L2 %.2e H1 %.2e\n", n, r, *sol.result.l2, *sol.result.h1);
    EXPECT_LT(*sol.result.l2, 1e-12) << n << " " << r;
    EXPECT_LT(*sol.result.h1, 1e-11) << n << " " << r;
  }
}

TEST(TmeshSpace, RejectsBadConfigs) {
  // w h >= pi on the coarse cells: w = 2 with sides pi/2.
  EXPECT_THROW(test::space_from_yaml(dyadic_yaml("trig", 3, 1, 2.0)), InputError);
  EXPECT_NO_THROW(test::space_from_yaml(dyadic_yaml("trig", 3, 1, 2.0), 1));
  EXPECT_THROW(test::space_from_yaml(dyadic_yaml("trig", 3, 2)), InputError);  // n < 2r+1
  EXPECT_THROW(test::space_from_yaml(dyadic_yaml("trig", 1, 0)), InputError);
}

TEST(TmeshSpace, LShapeNonConforming) {
  const SpacePtr s = test::space_from_yaml(
      "domain: {type: l_shape, min: [0, 0], max: [2, 2]}\n"
      "space: {type: tmesh, section: poly, n: 3, regularity: 1, elements: [2, 2], refine: [[0, 0, 0.5, 0.5]]}\n");
  const TMeshSpace& t = as_tmesh(s);
  EXPECT_EQ(t.mesh().admissibility_problem(), "");
  EXPECT_EQ(s->dimension(), brute_force_dimension(t.mesh(), 1, 1));
  EXPECT_LT(max_jumps(t, 1, 3).first, 1e-11);
  EXPECT_EQ(s->boundary_edges("all").size(), 10u);
  // The notes' two-cell L-shape has its re-entrant corner inside a cell side: not expressible as
  // whole boundary element edges, so it is refused with the reason rather than mis-constrained.
  const std::int64_t U = 1024;
  TMesh two({{0, 2 * U, 0, U, 0, 0}, {0, U, U, 2 * U, 0, 0}}, {{SectionFamily::polynomial, 3, 0.0}}, {0, 0}, {1.0 / U, 1.0 / U});
  EXPECT_TRUE(two.has_partial_boundary_sides());
  EXPECT_EQ(hermite_extraction(two, 1).dimension, 24);  // the extraction itself handles it (not 28)
  try {
    TMeshSpace bad(two, 1, false, "L");
    FAIL() << "partial boundary side accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("partly on the boundary"), std::string::npos);
  }
  EXPECT_FALSE(t.mesh().has_partial_boundary_sides());
}

TEST(TmeshSpace, GenericBoundaryConditionsOnLShape) {
  // A bicubic polynomial lies in the poly n = 3 space: Dirichlet data through the generic boundary
  // projection, on a non-convex domain with T-junctions, must give it back to round-off.
  const std::string yaml =
      "domain: {type: l_shape, min: [0, 0], max: [2, 2]}\n"
      "space: {type: tmesh, section: poly, n: 3, regularity: 1, elements: [2, 2], refine: [[0, 0, 0.5, 0.5]]}\n"
      "problem: {pde: poisson, exact: \"x^3*y - 2*x*y^2 + y^3 + 1\", boundary: {all: dirichlet}}\n";
  for (int level = 0; level < 2; ++level) {
    const SpacePtr s = test::space_from_yaml(yaml, level);
    const DiscreteSolution sol = solve_problem(*s, test::problem_from_yaml(yaml), SolverKind::cholmod);
    std::printf("L-shape level %d: dofs %d, constrained %d, L2 %.2e, H2 %.2e\n", level, s->dimension(),
                sol.result.dofs - sol.result.free_dofs, *sol.result.l2, *sol.result.h2);
    EXPECT_LT(*sol.result.l2, 1e-11);
    EXPECT_LT(*sol.result.h2, 1e-9);
    EXPECT_GT(sol.result.dofs - sol.result.free_dofs, 0);  // coefficients fixed by the data
  }
  // Clamped plate on the same mesh: value and normal-derivative data together.
  const std::string plate =
      "domain: {type: l_shape, min: [0, 0], max: [2, 2]}\n"
      "space: {type: tmesh, section: poly, n: 3, regularity: 1, elements: [2, 2], refine: [[0, 0, 0.5, 0.5]]}\n"
      "problem: {pde: biharmonic, exact: \"x^3*y - 2*x*y^2 + y^3 + 1\", boundary: {all: clamped}}\n";
  const SpacePtr s = test::space_from_yaml(plate, 1);
  const DiscreteSolution sol = solve_problem(*s, test::problem_from_yaml(plate), SolverKind::cholmod);
  EXPECT_LT(*sol.result.l2, 1e-10);
}

TEST(TmeshSpace, PaperMixedSpaceS2) {
  // Fig. 7 reconstruction on [0, pi]^2 (units of pi/4): trig w = 1.9 on A, cosh 3 on B,
  // quintic polynomials elsewhere; (5,5)/(1,1): 132 functions, four d_e = 0 edges.
  const std::int64_t U = 1024;
  const int boxes[7][5] = {{0, 2, 0, 2, 1}, {0, 2, 2, 3, 2}, {2, 3, 2, 3, 0}, {0, 3, 3, 4, 0},
                           {3, 4, 2, 4, 0}, {2, 3, 0, 2, 0}, {3, 4, 0, 2, 0}};
  for (bool mixed : {true, false}) {
    std::vector<TCell> cells;
    for (const auto& b : boxes) {
      const int sec = mixed ? b[4] : 2;
      cells.push_back({b[0] * U, b[1] * U, b[2] * U, b[3] * U, sec, sec});
    }
    TMesh mesh(cells,
               {{SectionFamily::polynomial, 5, 0.0}, {SectionFamily::trigonometric, 5, 1.9}, {SectionFamily::hyperbolic, 5, 3.0}},
               {0, 0}, {pi / 4 / U, pi / 4 / U});
    const TMeshSpace space(mesh, 1, true, "fig7");
    EXPECT_EQ(space.dimension(), mixed ? 132 : 148);
    EXPECT_LT(space.extraction().corner_mismatch, 1e-9);
    const auto [jump, control] = max_jumps(space, 1, 11);
    std::printf("Fig. 7 %s: dim %d, max relative C1 jump %.2e, second-derivative jump %.2e\n", mixed ? "S2" : "S1",
                space.dimension(), jump, control);
    EXPECT_LT(jump, 1e-10);
    EXPECT_GT(control, 1e-3);
    EXPECT_GT(independence(space, 5), 1e-10);
  }
}

TEST(TmeshSpace, GeometryAndLoadIntegrationAgreeWithTheFullEvaluation) {
  // evaluate_geometry / integrate_values skip the table of every active function; they must give
  // what evaluate gives: the same points, Jacobians and DOFs, and Σ_q w_q N_a(x_q) to round-off.
  const SpacePtr space = test::space_from_yaml(dyadic_yaml("trig", 3, 1), 1);
  auto full = space->make_evaluator(), fast = space->make_evaluator();
  const RulePtr rule = space->quadrature(0, 7);
  Eigen::VectorXd w(rule->size());
  for (int k = 0; k < w.size(); ++k) w(k) = std::cos(3.0 * k) + 1.5;  // any weights
  PointValues pv, geometry;
  Eigen::VectorXd local;
  for (int e = 0; e < space->num_elements(); ++e) {
    full->evaluate(e, *rule, update_values, pv);
    fast->evaluate_geometry(e, *rule, geometry);
    ASSERT_EQ(geometry.dofs, pv.dofs);
    ASSERT_EQ(geometry.num_points(), pv.num_points());
    EXPECT_LE((geometry.x - pv.x).cwiseAbs().maxCoeff(), 1e-15 * pi);
    for (int k = 0; k < pv.num_points(); ++k) EXPECT_EQ(geometry.jacobian[k], pv.jacobian[k]);
    fast->integrate_values(e, *rule, geometry, w, local);
    const Eigen::VectorXd expected = pv.value * w;
    // Basis values are O(1) (largest Bernstein coefficient 1), |w| <= 2.5: sums of q terms.
    EXPECT_LE((local - expected).cwiseAbs().maxCoeff(), 1e-14 * rule->size()) << "element " << e;
  }
}
