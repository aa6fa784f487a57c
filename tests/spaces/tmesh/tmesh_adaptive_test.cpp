// Adaptive refinement: admissible refined T-meshes with the right dimension, the residual
// indicator (zero for an exact discrete solution), Dörfler marking, and an adaptive L-shape study
// that beats uniform refinement at equal DOFs.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "assembly/error_indicator.hpp"
#include "solver/dorfler_marking.hpp"
#include "config/errors.hpp"
#include "solver/solve_problem.hpp"
#include "solver/study.hpp"
#include "spaces/tmesh/tmesh_refinement.hpp"
#include "spaces/tmesh/tmesh_space.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {

const TMeshSpace& as_tmesh(const SpacePtr& s) { return dynamic_cast<const TMeshSpace&>(*s); }

const char* kLShapeSpace =
    "domain: {type: l_shape, min: [-1, -1], max: [1, 1]}\n"
    "space: {type: tmesh, section: poly, n: 3, regularity: 1, elements: [4, 4]}\n";

/// Cells of `mesh` having the lattice point of physical (0, 0) on their boundary.
std::vector<int> cells_at_origin(const TMeshSpace& s) {
  std::vector<int> out;
  for (int c = 0; c < s.num_elements(); ++c) {
    Point2 lo, hi;
    s.cell_box(c, lo, hi);
    if (lo.x() <= 1e-14 && hi.x() >= -1e-14 && lo.y() <= 1e-14 && hi.y() >= -1e-14) out.push_back(c);
  }
  return out;
}

std::string study_yaml(const std::string& refinement) {
  return std::string(
             "problem:\n"
             "  pde: poisson\n"
             "  exact: \"(x^2 + y^2)^(1/3) * sin(2/3 * (atan2(x - y, -x - y) + 3*pi/4))\"\n"
             "  boundary: {all: dirichlet}\n") +
         kLShapeSpace + "refinement: " + refinement + "\noutput: {vtk: false, plot: false}\n";
}

StudyResult run(const std::string& yaml) { return test::run_study_from_yaml(yaml, "adaptive"); }

}  // namespace

TEST(TMeshRefinement, GradedRefinementStaysAdmissibleWithFormulaDimension) {
  SpacePtr space = test::space_from_yaml(kLShapeSpace);
  int previous_dim = space->dimension();
  for (int step = 0; step < 8; ++step) {
    // Mark the corner cells and, every other step, one far-away cell too.
    std::vector<int> marked = cells_at_origin(as_tmesh(space));
    if (step % 2) marked.push_back(0);
    space = space->refined(marked);
    ASSERT_TRUE(space);
    const TMeshSpace& t = as_tmesh(space);
    EXPECT_EQ(t.mesh().admissibility_problem(), "") << step;
    EXPECT_EQ(t.dimension(), t.mesh().dimension_formula(1, 1)) << step;
    EXPECT_GT(t.dimension(), previous_dim);
    EXPECT_LT(t.extraction().corner_mismatch, 1e-9);
    previous_dim = t.dimension();
    // 2:1 balance between side neighbours.
    for (auto [a, b] : side_neighbours(t.mesh())) {
      const double ha = t.mesh().width(a), hb = t.mesh().width(b);
      EXPECT_LE(std::max(ha, hb), 2.0 * std::min(ha, hb) + 1e-14) << a << " " << b;
    }
  }
  // Eight corner refinements of the 4x4 L-shape: the smallest cell is 0.5 / 2^8.
  double hmin = 1.0;
  const TMeshSpace& t = as_tmesh(space);
  for (int c = 0; c < t.num_elements(); ++c) hmin = std::min(hmin, t.mesh().width(c));
  EXPECT_DOUBLE_EQ(hmin, 0.5 / 256);
}

TEST(TMeshRefinement, BalanceAddsCellsAndSpacesWithoutRefinementSayNull) {
  SpacePtr space = test::space_from_yaml(kLShapeSpace);
  const int before = space->num_elements();
  // Twice the same corner cell: the second time its unrefined neighbours are split for 2:1 balance.
  space = space->refined({cells_at_origin(as_tmesh(space)).front()});
  EXPECT_EQ(space->num_elements(), before + 3);
  // The smallest cell at the corner is a child of the first split, its larger neighbours must split.
  int smallest = -1;
  for (int c : cells_at_origin(as_tmesh(space)))
    if (smallest < 0 || as_tmesh(space).mesh().width(c) < as_tmesh(space).mesh().width(smallest)) smallest = c;
  const int mid = space->num_elements();
  space = space->refined({smallest});
  EXPECT_GT(space->num_elements(), mid + 3);
  const SpacePtr bspline = test::space_from_yaml(
      "domain: {type: rectangle, min: [0, 0], max: [1, 1]}\nspace: {type: bspline, degree: 2, elements: [2, 2]}\n");
  EXPECT_EQ(bspline->refined({0}), nullptr);
}

TEST(ErrorIndicator, ZeroForAnExactDiscreteSolutionAndNotOtherwise) {
  const SpacePtr space = test::space_from_yaml(kLShapeSpace, 1)->refined({0, 5});
  auto indicator = [&](const std::string& exact) {
    const ProblemSpec p = test::problem_from_yaml("problem: {pde: poisson, exact: \"" + exact +
                                                  "\", boundary: {all: dirichlet}}\n");
    const DiscreteSolution sol = solve_problem(*space, p, SolverKind::cholmod);
    const SymbolicFunction f = p.source;
    return poisson_residual_indicators(*space, sol.coefficients, [f](const Point2& x) { return f(x); },
                                       space->error_quadrature_degree());
  };
  // A cubic is in the C1 cubic spline space: u_h = u, f + Δu_h = 0.
  const std::vector<double> exact = indicator("x^3 - 3*x*y^2 + x^2*y + 2*y^2");
  ASSERT_EQ(static_cast<int>(exact.size()), space->num_elements());
  EXPECT_LT(total_indicator(exact), 1e-9);
  // A quartic is not: the indicator sees it.
  EXPECT_GT(total_indicator(indicator("x^4 + y^4")), 1e-3);
}

TEST(DorflerMarking, SmallestBulkInDecreasingOrder) {
  const std::vector<double> eta{1.0, 3.0, 0.5, 2.0};  // squares 1, 9, 0.25, 4: total 14.25
  EXPECT_EQ(dorfler_marking(eta, 0.5), (std::vector<int>{1}));     // 9 >= 7.125
  EXPECT_EQ(dorfler_marking(eta, 0.7), (std::vector<int>{1, 3}));  // 13 >= 9.975
  EXPECT_EQ(dorfler_marking(eta, 1.0), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_TRUE(dorfler_marking({0.0, 0.0}, 0.5).empty());
  EXPECT_THROW(dorfler_marking(eta, 0.0), std::invalid_argument);
}

TEST(AdaptiveStudy, LShapeBeatsUniformAtEqualDofs) {
  const StudyResult uniform = run(study_yaml("{levels: 3}"));
  const StudyResult adaptive = run(study_yaml("{type: adaptive, marking: 0.5, max_dofs: 900, levels: 40}"));
  ASSERT_EQ(uniform.rows.size(), 3u);
  const LevelResult& u = uniform.rows.back();  // 900 DOFs
  const LevelResult& a = adaptive.rows.back();
  EXPECT_LE(a.dofs, u.dofs);
  EXPECT_EQ(adaptive.stop_reason, "max_dofs");
  // Measured: uniform 1.45e-1 at 900 DOFs, adaptive 7.9e-4 at 808 DOFs.
  EXPECT_LT(*a.h1 * 50.0, *u.h1);
  // Uniform is stuck at the singularity's N^(-1/3); adaptive is far faster over its last half.
  // Uniform, levels 1 -> 2 (260 -> 900 DOFs): measured 0.376, approaching 1/3 from above.
  const LevelResult& u1 = uniform.rows[1];
  const double uniform_rate = std::log(*u1.h1 / *u.h1) / std::log(double(u.dofs) / u1.dofs);
  EXPECT_NEAR(uniform_rate, 1.0 / 3.0, 0.06);
  const LevelResult& mid = adaptive.rows[adaptive.rows.size() / 2];
  const double adaptive_rate = std::log(*mid.h1 / *a.h1) / std::log(double(a.dofs) / mid.dofs);
  EXPECT_GT(adaptive_rate, 1.5);
  ASSERT_TRUE(adaptive.estimators.back().has_value());
  EXPECT_GT(*adaptive.estimators.back(), 0.0);
  EXPECT_FALSE(uniform.estimators.back().has_value());
}

TEST(AdaptiveStudy, StopsOnceTheEstimatorIsBelowTheTolerance) {
  // Measured estimators of this run: 2.0, 1.4, 0.87, ... 0.136 (level 6), 0.087 (level 7).
  const StudyResult r = run(study_yaml("{type: adaptive, marking: 0.5, tolerance: 0.1, levels: 40}"));
  EXPECT_EQ(r.stop_reason, "tolerance");
  ASSERT_GE(r.estimators.size(), 2u);
  EXPECT_LE(*r.estimators.back(), 0.1);
  EXPECT_GT(*r.estimators[r.estimators.size() - 2], 0.1);
  EXPECT_LT(r.rows.size(), 40u);
}

TEST(AdaptiveStudy, ConfigErrors) {
  auto parse = [](const std::string& yaml) {
    parse_study(ConfigNode::load_string(yaml, "bad.yaml"), "bad.yaml", 0,
                (test::scratch_folder() / "bad").string());
  };
  EXPECT_THROW(parse(study_yaml("{type: adaptive, markng: 0.5}")), InputError);
  EXPECT_THROW(parse(study_yaml("{type: adaptive, marking: 1.5}")), InputError);
  EXPECT_THROW(parse(study_yaml("{levels: 3, marking: 0.5}")), InputError);
  EXPECT_THROW(parse(study_yaml("{type: adaptiv}")), InputError);
  EXPECT_THROW(parse(study_yaml("{type: adaptive, tolerance: 0}")), InputError);
  EXPECT_THROW(parse(study_yaml("{levels: 3, tolerance: 1e-4}")), InputError);
  const std::string bspline = std::string(
      "problem: {pde: poisson, exact: \"x*y\", boundary: {all: dirichlet}}\n"
      "domain: {type: rectangle, min: [0, 0], max: [1, 1]}\n"
      "space: {type: bspline, degree: 2, elements: [2, 2]}\n"
      "refinement: {type: adaptive}\n");
  try {
    parse(bspline);
    ADD_FAILURE() << "bspline accepted for adaptive refinement";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("does not support local refinement"), std::string::npos) << e.what();
  }
}
