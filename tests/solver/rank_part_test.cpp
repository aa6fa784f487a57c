// The parts of a space that the ranks of a distributed solve work on (solver/rank_part.hpp,
// spaces/space_part.hpp), without MPI: two parts computed in one process. What each computes on
// its own elements adds up to what the whole space computes, and what each computes from its
// boundary band — the essential conditions — is the whole's, function for function (including the
// pivoted choice among dependent boundary traces, which once depended on a part's element order).

#include <gtest/gtest.h>

#include <set>

#include "solver/rank_part.hpp"
#include "solver/solve_problem.hpp"
#include "spaces/closed_forms.hpp"
#include "spaces/ws4/ws4_space.hpp"
#include "tests/spaces/ws4/ws4_test_meshes.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

constexpr int kParts = 2;

/// `smaller`: the mesh has elements without a boundary edge, so each part is less than the whole
/// (on a coarse mesh every element is in every part's boundary band).
void expect_parts_add_up(const char* yaml, int level, bool smaller) {
  SCOPED_TRACE(yaml);
  const ProblemSpec problem = test::problem_from_yaml(yaml);
  const SpacePtr whole = test::space_from_yaml(yaml, level);
  const auto f = make_formulation(*whole, problem);
  const Eigen::VectorXd load = f->load({});
  const Constraints c = f->constraints();
  Eigen::VectorXd summed = Eigen::VectorXd::Zero(whole->dimension());
  std::multiset<int> owned;
  for (int r = 0; r < kParts; ++r) {
    const std::shared_ptr<const SpacePart> part = rank_part(whole, r, kParts);
    const std::vector<int>& own = part->owned_elements();
    for (int e : own) owned.insert(part->elements()[e]);
    if (smaller) EXPECT_LT(part->dimension(), whole->dimension());
    const auto fp = make_formulation(*part, problem);
    const Eigen::VectorXd b = fp->load(WorkShare{&own});
    for (int i = 0; i < part->dimension(); ++i) summed(part->global_dofs()[i]) += b(i);
    // The conditions: the same functions constrained, to the same values, the same basis change.
    const Constraints cp = fp->constraints();
    ASSERT_EQ(cp.values.size(), part->dimension());
    std::vector<int> constrained;
    for (int i : cp.constrained) constrained.push_back(part->global_dofs()[i]);
    std::vector<int> expected;
    for (int i : c.constrained)
      if (part->local_dof(i) >= 0) expected.push_back(i);
    EXPECT_EQ(constrained, expected) << "part " << r;
    for (int i = 0; i < part->dimension(); ++i)
      EXPECT_EQ(cp.values(i), c.values(part->global_dofs()[i])) << "part " << r << ", function " << i;
    EXPECT_EQ(cp.basis_change.size() > 0, c.basis_change.size() > 0);
  }
  // Every element is some part's own, once.
  EXPECT_EQ(owned.size(), static_cast<std::size_t>(whole->num_elements()));
  EXPECT_EQ(std::set<int>(owned.begin(), owned.end()).size(), owned.size());
  // The loads add up (sums over elements in another grouping: round-off apart).
  EXPECT_LE((summed - load).cwiseAbs().maxCoeff(), 1e-14 * load.cwiseAbs().maxCoeff());
}

TEST(RankPart, LoadsAddUpAndConditionsAreTheWholeSpaces) {
  expect_parts_add_up(R"yaml(
problem: {pde: poisson, exact: "sin(pi*x)*sin(2*pi*y)", boundary: {all: dirichlet}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 3, elements: [4, 4]}
)yaml",
                      2, true);
  expect_parts_add_up(R"yaml(
problem: {pde: biharmonic, exact: "sin(2*x + 0.3)*cos(3*y)", boundary: {all: clamped}}
domain: {type: multipatch, name: 3p_square}
space: {type: g1, degree: 5}
)yaml",
                      2, true);
}

TEST(RankPart, DependentBoundaryTracesArePivotedAsByTheWholeSpace) {
  // fan3: linearly dependent boundary traces at the valence-3 corners, a column-pivoted choice of
  // the functions to constrain and a basis change for the others (boundary_conditions.hpp). Level 0:
  // three elements, one part owning one and the other two, each part all three.
  expect_parts_add_up(R"yaml(
problem: {pde: poisson, exact: "sin(2*x+0.3)*cos(3*y)", boundary: {all: dirichlet}}
domain: {type: multipatch, name: fan3}
space: {type: g1_4split, degree: 4, blending: linear, refinement: nested}
)yaml",
                      0, false);
}

// A mesh-based space built as its skeleton (spaces/builds_on_elements.hpp): each part builds the
// per-element data of its own elements only, and computes what the part of the whole space does.
TEST(RankPart, APartOfASkeletonBuildsItsElementsOnlyAndMatchesThePartOfTheWholeSpace) {
  const ws4::Triangulation mesh = test::perturbed_square(8, 5);
  const auto whole = std::make_shared<const ws4::Ws4Space>(mesh);
  const auto skeleton = std::make_shared<const ws4::Ws4Space>(mesh, "triangulation", SpaceExtent::skeleton);
  for (int rank = 0; rank < 2; ++rank) {
    const auto from_whole = rank_part(whole, rank, 2), from_skeleton = rank_part(skeleton, rank, 2);
    EXPECT_EQ(from_skeleton->elements(), from_whole->elements());
    EXPECT_EQ(from_skeleton->global_dofs(), from_whole->global_dofs());
    const auto& built = dynamic_cast<const ws4::Ws4Space&>(from_skeleton->whole());
    // Every element its own class: the part's extractions, not the whole's 128.
    EXPECT_EQ(built.shape_classes().size(), from_skeleton->num_elements());
    EXPECT_LT(from_skeleton->num_elements(), whole->num_elements());
    for (int e = 0; e < from_skeleton->num_elements(); ++e) {
      Eigen::MatrixXd p, q;
      ASSERT_TRUE(from_skeleton->closed_forms()->element_matrix(e, BilinearForm::laplace, p));
      ASSERT_TRUE(from_whole->closed_forms()->element_matrix(e, BilinearForm::laplace, q));
      EXPECT_EQ(p, q) << e;
    }
  }
}

}  // namespace
}  // namespace iga
