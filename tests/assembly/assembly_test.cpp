// The generic assembler: pattern, symmetric matrices with the right kernels, and
// results independent of the number of threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <set>

#include "assembly/assembler.hpp"
#include "assembly/parallel.hpp"
#include "spaces/closed_forms.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {
const char* kCubic = R"yaml(
domain: {type: rectangle, min: [-1, 0.5], max: [2, 1.5]}
space: {type: bspline, degree: 3, regularity: 2, elements: [5, 3]}
)yaml";
const char* kAnnulus = R"yaml(
domain: {type: quarter_annulus, inner: 1, outer: 2}
space: {type: bspline, degree: 2, regularity: 1, elements: [4, 3]}
)yaml";
}  // namespace

TEST(Assembly, PatternHoldsEveryElementCoupling) {
  const SpacePtr space = test::space_from_yaml(kCubic);
  const ElementDofTable table = collect_element_dofs(*space);
  const SparseMatrix pattern = sparsity_pattern(table, space->dimension());
  // 1D: each cubic C2 B-spline overlaps with at most 7; the 8x6 functions of a 5x3 mesh give a
  // known count of couplings: sum over pairs of directions of overlaps.
  auto overlaps_1d = [](int n, int p) {
    int total = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) total += std::abs(i - j) <= p;
    return total;
  };
  EXPECT_EQ(pattern.nonZeros(), overlaps_1d(8, 3) * overlaps_1d(6, 3));
}

TEST(Assembly, PatternIsExactlyTheSetOfElementCouplings) {
  // Spaces whose dofs come in runs active on the same elements (vertex, edge and cell dofs of a
  // macro-element; B-splines of one knot span) and one without.
  for (const char* yaml : {"domain: {type: unit_square}\nspace: {type: ws4, elements: 3}\n",
                           "domain: {type: multipatch, name: 3p_square}\nspace: {type: g1, degree: 5}\n", kCubic}) {
    const SpacePtr space = test::space_from_yaml(yaml);
    const ElementDofTable table = collect_element_dofs(*space);
    const SparseMatrix pattern = sparsity_pattern(table, space->dimension());
    std::set<std::pair<int, int>> couplings;
    for (int e = 0; e < table.num_elements(); ++e)
      for (const int* i = table.begin(e); i != table.begin(e + 1); ++i)
        for (const int* j = table.begin(e); j != table.begin(e + 1); ++j) couplings.insert({*j, *i});
    std::set<std::pair<int, int>> stored;
    for (int col = 0; col < pattern.outerSize(); ++col) {
      for (SparseMatrix::InnerIterator it(pattern, col); it; ++it) stored.insert({col, static_cast<int>(it.row())});
      // Rows sorted and distinct within each column.
      const int* inner = pattern.innerIndexPtr();
      EXPECT_TRUE(std::is_sorted(inner + pattern.outerIndexPtr()[col], inner + pattern.outerIndexPtr()[col + 1]));
    }
    EXPECT_EQ(static_cast<std::size_t>(pattern.nonZeros()), stored.size()) << yaml;
    EXPECT_EQ(stored, couplings) << yaml;
  }
}

TEST(Assembly, StiffnessIsSymmetricAndAnnihilatesConstants) {
  const SpacePtr space = test::space_from_yaml(kAnnulus);
  const Assembler assembler(*space);
  const SparseMatrix K = assembler.matrix(BilinearForm::laplace, 8);
  const SparseMatrix Kt = K.transpose();
  EXPECT_LT((K - Kt).norm(), 1e-13 * K.norm());
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(space->dimension());
  EXPECT_LT((K * ones).norm(), 1e-12 * K.norm());
  // Mass matrix: 1^T M 1 is the area of the quarter annulus (exact NURBS geometry).
  const SparseMatrix M = assembler.matrix(BilinearForm::mass, 10);
  EXPECT_NEAR(ones.dot(M * ones), 3.0 * M_PI / 4.0, 1e-12);
}

TEST(Assembly, BiharmonicFormsVanishOnLinearFunctions) {
  const SpacePtr space = test::space_from_yaml(kCubic);
  const Assembler assembler(*space);
  // B-splines reproduce x and y; interpolate u = 2 + 3x - y through the Greville-free route:
  // the coefficient vector of a linear function is found by an L2 projection.
  const SparseMatrix M = assembler.matrix(BilinearForm::mass, 8);
  const Eigen::VectorXd b = assembler.load([](const Point2& p) { return 2 + 3 * p.x() - p.y(); }, 8);
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(M);
  const Eigen::VectorXd u = ldlt.solve(b);
  for (BilinearForm form : {BilinearForm::bilaplace, BilinearForm::hessian}) {
    const SparseMatrix B = assembler.matrix(form, 6);
    EXPECT_LT((B * u).norm(), 1e-9 * B.norm() * u.norm()) << to_string(form);
  }
}

TEST(Assembly, ResultDoesNotDependOnThreadCount) {
  const SpacePtr space = test::space_from_yaml(kAnnulus, 3);
  ASSERT_TRUE(worth_threads(space->num_elements()));  // else both runs would be serial
  const Assembler assembler(*space);
  omp_set_num_threads(1);
  const SparseMatrix A1 = assembler.matrix(BilinearForm::hessian, 6);
  omp_set_num_threads(2);
  const SparseMatrix A2 = assembler.matrix(BilinearForm::hessian, 6);
  // Each entry receives its contributions in element order whatever the threads: bitwise equal.
  ASSERT_EQ(A1.nonZeros(), A2.nonZeros());
  for (int k = 0; k < A1.nonZeros(); ++k) ASSERT_EQ(A1.valuePtr()[k], A2.valuePtr()[k]);
}

namespace {
/// Delegates to a B-spline space but supplies element matrices "in closed form": twice the
/// quadrature ones, so the test can see which path the assembler took.
class ClosedFormSpace final : public Space {
 public:
  explicit ClosedFormSpace(SpacePtr inner) : inner_(std::move(inner)), twice_(*inner_) {
    SpaceFacts facts = inner_->facts();
    facts.type = "closed-form test";
    facts.parameters = {};
    set_facts(std::move(facts));
  }
  std::unique_ptr<Evaluator> make_evaluator() const override { return inner_->make_evaluator(); }
  void element_dofs(int e, std::vector<int>& out) const override { inner_->element_dofs(e, out); }
  RulePtr quadrature(int e, int d) const override { return inner_->quadrature(e, d); }
  RulePtr edge_quadrature(int e, int edge, int d) const override { return inner_->edge_quadrature(e, edge, d); }
  const ClosedForms* closed_forms() const override { return &twice_; }

 private:
  class Twice final : public ClosedForms {
   public:
    explicit Twice(const Space& inner) : inner_(inner) {}

   protected:
    bool rounded(int e, BilinearForm form, Eigen::MatrixXd& local) const override {
      const Form integrator(form);
      ElementValues ev(inner_, integrator->flags());
      ev.reinit(e, *inner_.quadrature(e, 8));
      integrator->element_matrix(ev, local);  // the integrator, not ClosedForms::element_matrix
      local *= 2.0;
      return true;
    }

   private:
    const Space& inner_;
  };
  SpacePtr inner_;
  Twice twice_;
};
}  // namespace

TEST(Assembly, UsesClosedFormElementMatricesWhenTheSpaceHasThem) {
  const SpacePtr inner = test::space_from_yaml(kCubic);
  const ClosedFormSpace closed(inner);
  const SparseMatrix A = Assembler(*inner).matrix(BilinearForm::laplace, 8);
  const SparseMatrix B = Assembler(closed).matrix(BilinearForm::laplace, 8);
  EXPECT_LT((B - 2.0 * A).norm(), 1e-13 * A.norm());
}

namespace {
/// ∫ ∇u·∇v without the closed-form tag: a form the space's ClosedForms does not know.
class UntaggedStiffness final : public SymmetricSquaresIntegrator {
 public:
  using SymmetricSquaresIntegrator::SymmetricSquaresIntegrator;
  unsigned flags() const override { return update_gradients; }
  std::string name() const override { return "untagged stiffness"; }
  int operands(const PointValues& v, Scratch&, Operand (&out)[kMaxOperands]) const override {
    out[0] = {&v.dx, nullptr, 1};
    out[1] = {&v.dy, nullptr, 1};
    return 2;
  }
};
}  // namespace

TEST(Integrator, FormsWithoutClosedFormAreIntegratedAndCoefficientsScaleBothPaths) {
  const SpacePtr inner = test::space_from_yaml(kCubic);
  const ClosedFormSpace closed(inner);
  const SparseMatrix A = Assembler(*inner).matrix(BilinearForm::laplace, 8);
  // The untagged form is integrated (A), not taken from the closed forms (2A).
  const SparseMatrix U = Assembler(closed).matrix(Form(std::make_shared<const UntaggedStiffness>()), 8);
  EXPECT_LT((U - A).norm(), 1e-13 * A.norm());
  // A coefficient scales the quadrature and the closed-form element matrices alike (one rounding
  // of each entry of a sum of a few element contributions).
  const SparseMatrix A3 = Assembler(*inner).matrix(Form(BilinearForm::laplace, 3.0), 8);
  const SparseMatrix B3 = Assembler(closed).matrix(Form(BilinearForm::laplace, 3.0), 8);
  EXPECT_LT((A3 - 3.0 * A).norm(), 1e-15 * A3.norm());
  EXPECT_LT((B3 - 6.0 * A).norm(), 1e-13 * A3.norm());
  const SplitMatrix K3 = Assembler(*inner).matrix_extended(Form(stiffness_integrator(3.0)), 8);
  EXPECT_LT((K3.high - 3.0 * A).norm(), 1e-15 * A3.norm());
  EXPECT_EQ(Form(BilinearForm::hessian)->name(), "hessian");
  EXPECT_EQ(Form(BilinearForm::bilaplace)->flags(), unsigned(update_hessians));
}

TEST(Assembly, DoubleDoubleElementMatricesAgreeWithLongDouble) {
  // Quadrature path (curved elements): the double-double sums (compiled for FMA where the CPU has
  // it) against the long double ones, on the same basis values. They differ by the long double
  // sums' rounding alone: at most q u Σ_k |A_ik| w_k |A_jk| (u = 2⁻⁶⁴, q points, per form term).
  // Compiled for FMA, Dekker's splitting would lose bits here (a contracted product breaks it).
  const SpacePtr space = test::space_from_yaml(kAnnulus);
  ElementValues ev(*space, update_values | update_gradients | update_hessians);
  for (BilinearForm form : {BilinearForm::mass, BilinearForm::laplace, BilinearForm::bilaplace, BilinearForm::hessian})
    for (int e = 0; e < space->num_elements(); e += 5) {
      ev.reinit(e, *space->quadrature(e, 8));
      const PointValues& v = ev.values();
      const Eigen::VectorXd& w = ev.jxw();
      std::vector<Eigen::MatrixXd> terms;
      if (form == BilinearForm::mass) terms = {v.value};
      if (form == BilinearForm::laplace) terms = {v.dx, v.dy};
      if (form == BilinearForm::bilaplace) terms = {v.dxx + v.dyy};
      if (form == BilinearForm::hessian) terms = {v.dxx, std::sqrt(2.0) * v.dxy, v.dyy};
      Eigen::MatrixXd magnitude = Eigen::MatrixXd::Zero(v.num_functions(), v.num_functions());
      for (const Eigen::MatrixXd& a : terms) magnitude += a.cwiseAbs() * w.cwiseAbs().asDiagonal() * a.cwiseAbs().transpose();
      // The long double path rounds Δφ = φ_xx + φ_yy to double first (2⁻⁵³ relative).
      const double rounding =
          (ev.num_points() + 2) * std::ldexp(1.0, -64) + (form == BilinearForm::bilaplace ? std::ldexp(1.0, -52) : 0.0);
      DoubleDoubleMatrix dd;
      MatrixXld ld;
      Form(form)->element_matrix(ev, dd);
      Form(form)->element_matrix(ev, ld);
      for (Eigen::Index j = 0; j < ld.cols(); ++j)
        for (Eigen::Index i = 0; i < ld.rows(); ++i) {
          const long double exact = static_cast<long double>(dd.hi(i, j)) + static_cast<long double>(dd.lo(i, j));
          EXPECT_LE(std::abs(exact - ld(i, j)), rounding * terms.size() * magnitude(i, j))
              << to_string(form) << " element " << e;
          EXPECT_EQ(dd(i, j), dd(j, i));
        }
    }
}

TEST(Assembly, ExtendedResidualKeepsTheLowPartsOfEntriesAndProducts) {
  // K = tridiag(−1, 3 + 2⁻⁶⁰, −1) (the low part held apart), x = 2¹⁰ (1, …, 1), b = K_high x: the
  // exact residual is −2⁻⁵⁰ in every row, which a double residual would round to zero. Enough
  // rows for the parallel, FMA-compiled path (blocks of 256 rows).
  const int n = 2000;
  const SparseMatrix pattern = test::tridiagonal(n, 3.0);
  std::vector<DoubleDouble> values(pattern.nonZeros());
  for (int col = 0; col < n; ++col)
    for (SparseMatrix::InnerIterator it(pattern, col); it; ++it) {
      const auto p = &it.value() - pattern.valuePtr();
      values[p] = it.row() == col ? DoubleDouble(3.0, std::ldexp(1.0, -60)) : DoubleDouble(-1.0);
    }
  const SplitMatrix K = split_matrix(pattern, values);
  const std::vector<long double> x(n, 1024.0L);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) b(i) = 1024.0 * ((i > 0 && i + 1 < n) ? 1.0 : 2.0);
  const std::vector<long double> r = residual_extended(K, x, b);
  for (int i = 0; i < n; ++i) EXPECT_EQ(r[i], -std::ldexp(1.0L, -50)) << "row " << i;
}
