// The operator as data: ProblemSpec::terms as the config reader sets it, and Formulation::matrix of
// any term list (the stiffness of the problem, a mass term for the eigenproblem that comes next).
#include <gtest/gtest.h>

#include "solver/planar_formulation.hpp"
#include "solver/surface_problem.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

/// The integrator names and coefficients of the problem's terms.
std::vector<std::pair<std::string, double>> terms_of(const std::string& yaml) {
  std::vector<std::pair<std::string, double>> out;
  for (const FormTerm& t : test::problem_from_yaml(yaml).terms) out.emplace_back(t->name(), t->coefficient());
  return out;
}

using Terms = std::vector<std::pair<std::string, double>>;

TEST(FormulationTerms, TheConfigChoosesTheIntegrators) {
  EXPECT_EQ(terms_of("problem: {pde: poisson, exact: \"x*y\", boundary: {all: dirichlet}}"), (Terms{{"laplace", 1.0}}));
  EXPECT_EQ(terms_of("problem: {pde: biharmonic, exact: \"x*y\", boundary: {all: clamped}}"),
            (Terms{{"bilaplace", 1.0}}));
  EXPECT_EQ(terms_of("problem: {pde: biharmonic, form: hessian, exact: \"x*y\", boundary: {all: clamped}}"),
            (Terms{{"hessian", 1.0}}));
  EXPECT_EQ(terms_of("problem: {pde: laplace_beltrami, exact: \"x\", reaction: 2.5}"),
            (Terms{{"laplace", 1.0}, {"mass", 2.5}}));
  EXPECT_EQ(terms_of("problem: {pde: laplace_beltrami, exact: \"x\", reaction: 0}"), (Terms{{"laplace", 1.0}}));
}

/// 1ᵀ A 1 summed in long double.
long double total(const SparseMatrix& A) {
  long double s = 0;
  for (int k = 0; k < A.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(A, k); it; ++it) s += it.value();
  return s;
}

TEST(FormulationMatrix, AssemblesAnyTermList) {
  // Cubic B-splines on [0, 2] x [0, 1]: a partition of unity, so 1ᵀ M 1 = ∫ 1 = the area (2), and
  // the stiffness annihilates the constants (K 1 = 0 up to round-off of entries of size ~1).
  const std::string yaml = R"(
problem: {pde: poisson, exact: "x*y", boundary: {all: dirichlet}}
domain: {type: rectangle, min: [0, 0], max: [2, 1]}
space: {type: bspline, degree: 3, elements: [8, 4]}
)";
  const SpacePtr space = test::space_from_yaml(yaml);
  const ProblemSpec problem = test::problem_from_yaml(yaml);
  const PlanarFormulation f(*space, problem);
  const SplitMatrix M = f.matrix({mass_integrator()});
  EXPECT_NEAR(static_cast<double>(total(M.high)), 2.0, 1e-13);
  const SplitMatrix K = f.matrix(f.terms());
  EXPECT_LE((K.high * Eigen::VectorXd::Ones(K.rows())).lpNorm<Eigen::Infinity>(), 1e-13);
  // Planar matrices keep what the double rounding lost (a low part per entry), for one term.
  EXPECT_EQ(K.low.size(), K.high.nonZeros());
  EXPECT_THROW(f.matrix({stiffness_integrator(), mass_integrator()}), std::logic_error);
}

TEST(FormulationMatrix, SurfaceTermsAddUpInDouble) {
  // −Δ_Γu + c u on a sphere: 1ᵀ(K + c M)1 = c 1ᵀ M 1 (constants are in the kernel of K).
  const std::string yaml = R"(
problem: {pde: laplace_beltrami, exact: "x*y", reaction: 3}
domain: {type: surface, mesh: icosphere, level: 0}
space: {type: surface, degree: 2}
)";
  const SpacePtr space = test::space_from_yaml(yaml);
  const ProblemSpec problem = test::problem_from_yaml(yaml);
  const SurfaceFormulation f(*space, problem);
  const SplitMatrix A = f.matrix(f.terms()), M = f.matrix({mass_integrator()});
  EXPECT_EQ(A.low.size(), 0);  // summed in double: no low part
  const double area = static_cast<double>(total(M.high));
  EXPECT_GT(area, 1.0);
  EXPECT_NEAR(static_cast<double>(total(A.high)), 3 * area, 1e-12 * area);
}

}  // namespace
}  // namespace iga
