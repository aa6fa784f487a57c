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

namespace iga::ws4 {
namespace {

/// Every third element and the last: a set that is neither a run nor the whole mesh.
std::vector<int> some_elements(int n) {
  std::vector<int> e;
  for (int t = 0; t < n; t += 3) e.push_back(t);
  if (e.back() != n - 1) e.push_back(n - 1);
  return e;
}

/// u_h = Σ c_i N_i of the active functions at the degree-4 rule of the element, with derivatives.
FunctionValues evaluated(const Space& space, int element, const Eigen::VectorXd& local) {
  const std::unique_ptr<Space::Evaluator> ev = space.make_evaluator();
  PointValues geometry;
  FunctionValues out;
  ev->evaluate_element_function(element, *space.quadrature(element, 4), local,
                                update_values | update_gradients | update_hessians, geometry, out);
  return out;
}

TEST(Ws4BuildOn, TheSkeletonHasTheWholeNumberingAndGeometryAndNoElementData) {
  const auto whole = std::make_shared<const Ws4Space>(test::perturbed_square(4, 7));
  const auto skeleton = std::make_shared<const Ws4Space>(test::perturbed_square(4, 7), "triangulation",
                                                         SpaceExtent::skeleton);
  ASSERT_EQ(skeleton->num_elements(), 32);
  // 10 n_V + 6 n_E + 3 n_T on the 4 x 4 squares: 25 vertices, 56 edges, 32 triangles.
  EXPECT_EQ(skeleton->dimension(), 10 * 25 + 6 * 56 + 3 * 32);
  EXPECT_EQ(skeleton->dimension(), whole->dimension());
  EXPECT_EQ(skeleton->boundary_edges("all").size(), 16u);
  EXPECT_EQ(skeleton->shape_classes().size(), 0);
  const std::unique_ptr<Space::Evaluator> a = skeleton->make_evaluator(), b = whole->make_evaluator();
  std::vector<int> dofs_a, dofs_b;
  for (int t = 0; t < skeleton->num_elements(); ++t) {
    EXPECT_FALSE(skeleton->built_on(t));
    skeleton->element_dofs(t, dofs_a);
    whole->element_dofs(t, dofs_b);
    EXPECT_EQ(dofs_a, dofs_b) << t;
    // The geometry (element centres of the partition, mesh outlines) is the skeleton's.
    PointValues ga, gb;
    a->evaluate_geometry(t, *skeleton->quadrature(t, 1), ga);
    b->evaluate_geometry(t, *whole->quadrature(t, 1), gb);
    EXPECT_EQ(ga.x, gb.x) << t;
    EXPECT_EQ(ga.jacobian, gb.jacobian) << t;
  }
  PointValues values;
  EXPECT_THROW(a->evaluate(0, *skeleton->quadrature(0, 4), update_values, values), std::logic_error);
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
    EXPECT_EQ(space.dimension(), whole->dimension());
    EXPECT_LE(space.shape_classes().size(), static_cast<int>(elements.size()));
    if (perturbed) EXPECT_EQ(space.shape_classes().size(), static_cast<int>(elements.size()));
    Eigen::VectorXd local(Ws4Space::dofs_per_element);
    for (int m = 0; m < local.size(); ++m) local(m) = std::sin(1.0 + m);
    for (int t = 0; t < whole->num_elements(); ++t) {
      const bool in = std::binary_search(elements.begin(), elements.end(), t);
      ASSERT_EQ(space.built_on(t), in) << t;
      if (!in) {
        EXPECT_THROW(space.extraction(t), std::logic_error) << t;
        EXPECT_THROW(evaluated(space, t, local), std::logic_error) << t;
        continue;
      }
      EXPECT_EQ(space.extraction(t), whole->extraction(t)) << t;
      const FunctionValues u = evaluated(space, t, local), v = evaluated(*whole, t, local);
      EXPECT_EQ(u.value, v.value) << t;
      EXPECT_EQ(u.dx, v.dx) << t;
      EXPECT_EQ(u.dxx, v.dxx) << t;
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
