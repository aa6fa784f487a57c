/// @file
/// A WS4 space built on some of its elements (BuildsOnElements, what one rank of a distributed
/// solve builds): the skeleton answers everything but the per-element data for every element, the
/// space built on a set of elements evaluates them bit for bit as the whole space does, and asking
/// it for another element is a programming error.

#include <gtest/gtest.h>

#include <numeric>
#include <stdexcept>

#include "spaces/builds_on_elements.hpp"
#include "spaces/closed_forms.hpp"
#include "spaces/ws4/ws4_space.hpp"
#include "tests/spaces/ws4/ws4_test_meshes.hpp"
#include "tests/support/build_on_checks.hpp"

namespace iga::ws4 {
namespace {

/// Every third element and the last: a set that is neither a run nor the whole mesh.
std::vector<int> some_elements(int n) {
  std::vector<int> e;
  for (int t = 0; t < n; t += 3) e.push_back(t);
  if (e.back() != n - 1) e.push_back(n - 1);
  return e;
}

TEST(Ws4BuildOn, TheSkeletonHasTheWholeNumberingAndGeometryAndNoElementData) {
  const auto whole = std::make_shared<const Ws4Space>(test::perturbed_square(4, 7));
  const auto skeleton = std::make_shared<const Ws4Space>(test::perturbed_square(4, 7), "triangulation",
                                                         SpaceExtent::skeleton);
  ASSERT_EQ(skeleton->num_elements(), 32);
  // 10 n_V + 6 n_E + 3 n_T on the 4 x 4 squares: 25 vertices, 56 edges, 32 triangles.
  EXPECT_EQ(skeleton->dimension(), 10 * 25 + 6 * 56 + 3 * 32);
  EXPECT_EQ(skeleton->boundary_edges("all").size(), 16u);
  EXPECT_EQ(skeleton->shape_classes().size(), 0);
  test::expect_skeleton_of(*skeleton, *whole);
  Eigen::MatrixXd k;
  EXPECT_THROW(skeleton->closed_forms()->element_matrix(0, BilinearForm::laplace, k), std::logic_error);
}

TEST(Ws4BuildOn, BuiltElementsEvaluateBitForBitAsInTheWholeSpaceAndOthersAreRefused) {
  // A perturbed mesh (every element its own shape class) and a structured one (classes shared,
  // represented in the part by other elements than in the whole).
  for (const bool perturbed : {true, false}) {
    Triangulation mesh = perturbed ? test::perturbed_square(6, 3) : Triangulation::rectangle(6, 6, {0, 0}, {1, 1});
    const auto whole = std::make_shared<const Ws4Space>(mesh);
    const auto skeleton = std::make_shared<const Ws4Space>(mesh, "triangulation", SpaceExtent::skeleton);
    const std::vector<int> elements = some_elements(whole->num_elements());
    const SpacePtr built = on_elements(skeleton, elements);
    const auto& space = dynamic_cast<const Ws4Space&>(*built);
    EXPECT_LE(space.shape_classes().size(), static_cast<int>(elements.size()));
    if (perturbed) EXPECT_EQ(space.shape_classes().size(), static_cast<int>(elements.size()));
    test::expect_built_as_whole(space, *whole, elements, 4);
    for (int t = 0; t < whole->num_elements(); ++t) {
      const bool in = std::binary_search(elements.begin(), elements.end(), t);
      if (!in) {
        EXPECT_THROW(space.extraction(t), std::logic_error) << t;
        continue;
      }
      EXPECT_EQ(space.extraction(t), whole->extraction(t)) << t;
      for (BilinearForm form : {BilinearForm::laplace, BilinearForm::bilaplace}) {
        DoubleDoubleMatrix p, q;
        ASSERT_TRUE(space.closed_forms()->element_matrix(t, form, p));
        ASSERT_TRUE(whole->closed_forms()->element_matrix(t, form, q));
        EXPECT_EQ(p.hi, q.hi) << t;
        EXPECT_EQ(p.lo, q.lo) << t;
      }
    }
    // A space built on every element is the whole space; asking again for built elements keeps it.
    EXPECT_EQ(on_elements(built, {elements.front()}), built);
    std::vector<int> all(whole->num_elements());
    std::iota(all.begin(), all.end(), 0);
    EXPECT_EQ(on_elements(whole, all), SpacePtr(whole));
  }
}

}  // namespace
}  // namespace iga::ws4
