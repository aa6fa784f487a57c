/// @file
/// A G1 space built on some of its elements (BuildsOnElements, what one rank of a distributed
/// solve keeps): the skeleton has the whole numbering and geometry and no extraction, the space
/// built on a set of elements evaluates them bit for bit as the whole space does, and asking it for
/// another element is a programming error.

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "spaces/builds_on_elements.hpp"
#include "spaces/g1/g1_space.hpp"
#include "spaces/g1/multipatch_domains.hpp"

namespace iga {
namespace {

/// u_h = Σ c_i N_i of the element's active functions with derivatives at a degree-6 rule.
FunctionValues evaluated(const Space& space, int element, const Eigen::VectorXd& local) {
  const std::unique_ptr<Space::Evaluator> ev = space.make_evaluator();
  PointValues geometry;
  FunctionValues out;
  ev->evaluate_element_function(element, *space.quadrature(element, 6), local,
                                update_values | update_gradients | update_hessians, geometry, out);
  return out;
}

TEST(G1BuildOn, APartOfTheSkeletonEvaluatesItsElementsAsTheWholeSpaceAndRefusesTheOthers) {
  // The three-patch square refined twice: 48 quads with an extraordinary vertex of valence 3.
  const auto mesh = std::make_shared<const PatchMesh>(multipatch_domain("3p_square").refined().refined());
  const auto whole = std::make_shared<const G1Space>(mesh, 5);
  const auto skeleton = std::make_shared<const G1Space>(mesh, 5, SpaceExtent::skeleton);
  ASSERT_EQ(skeleton->num_elements(), 48);
  EXPECT_EQ(skeleton->dimension(), whole->dimension());
  std::vector<int> a, b;
  const std::unique_ptr<Space::Evaluator> ev = skeleton->make_evaluator();
  for (int e = 0; e < skeleton->num_elements(); ++e) {
    EXPECT_FALSE(skeleton->built_on(e));
    skeleton->element_dofs(e, a);
    whole->element_dofs(e, b);
    EXPECT_EQ(a, b) << e;
    PointValues g;  // the geometry: element centres of the partition, mesh outlines
    ev->evaluate_geometry(e, *skeleton->quadrature(e, 1), g);
  }
  PointValues values;
  EXPECT_THROW(ev->evaluate(0, *skeleton->quadrature(0, 6), update_values, values), std::logic_error);

  // Every third face; then the same again, which solves the local problems a second time.
  std::vector<int> some;
  for (int e = 0; e < skeleton->num_elements(); e += 3) some.push_back(e);
  for (int round = 0; round < 2; ++round) {
    const SpacePtr built = on_elements(skeleton, some);
    for (int e = 0; e < built->num_elements(); ++e) {
      const bool in = e % 3 == 0;
      built->element_dofs(e, a);
      Eigen::VectorXd local(static_cast<Eigen::Index>(a.size()));
      for (Eigen::Index m = 0; m < local.size(); ++m) local(m) = std::cos(0.3 + static_cast<double>(m));
      if (!in) {
        EXPECT_THROW(evaluated(*built, e, local), std::logic_error) << e;
        continue;
      }
      const FunctionValues u = evaluated(*built, e, local), v = evaluated(*whole, e, local);
      EXPECT_EQ(u.value, v.value) << e;
      EXPECT_EQ(u.dx, v.dx) << e;
      EXPECT_EQ(u.dxy, v.dxy) << e;
    }
  }
}

}  // namespace
}  // namespace iga
