// The generic assembler: colouring, pattern, symmetric matrices with the right kernels, and
// results independent of the number of threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/SparseCholesky>

#include <set>

#include "assembly/assembler.hpp"
#include "test_support.hpp"

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

TEST(Assembly, ColouringSeparatesElementsThatShareFunctions) {
  const SpacePtr space = test::space_from_yaml(kCubic);
  const ElementDofTable table = collect_element_dofs(*space);
  const auto colours = colour_elements(table, space->dimension());
  // Cubic C2 elements (i, j), (k, l) share a function iff |i-k| <= 3 and |j-l| <= 3: on 5x3
  // elements, any 4 consecutive columns of all 3 rows conflict pairwise, so 12 colours are needed.
  EXPECT_GE(colours.size(), 12u);
  EXPECT_LE(colours.size(), 16u);
  std::vector<int> seen(space->num_elements(), 0);
  for (const auto& group : colours) {
    std::set<int> used;
    for (int e : group) {
      ++seen[e];
      for (const int* d = table.begin(e); d != table.begin(e + 1); ++d) EXPECT_TRUE(used.insert(*d).second);
    }
  }
  for (int count : seen) EXPECT_EQ(count, 1);
}

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
  const SpacePtr space = test::space_from_yaml(kAnnulus, 1);
  const Assembler assembler(*space);
  omp_set_num_threads(1);
  const SparseMatrix A1 = assembler.matrix(BilinearForm::hessian, 6);
  omp_set_num_threads(2);
  const SparseMatrix A2 = assembler.matrix(BilinearForm::hessian, 6);
  // Each entry receives at most one contribution per colour, in colour order: bitwise equal.
  ASSERT_EQ(A1.nonZeros(), A2.nonZeros());
  for (int k = 0; k < A1.nonZeros(); ++k) ASSERT_EQ(A1.valuePtr()[k], A2.valuePtr()[k]);
}
