/// @file
/// A 4-split G1 space built on some of its elements (BuildsOnElements, what one rank of a
/// distributed solve keeps), on a nested level: the skeleton has the whole numbering, geometry and
/// inherited gluing and no extraction; the space built on a set of faces evaluates them bit for bit
/// as the whole space does (the level's basis is rebuilt from the level's topology and gluing
/// when the skeleton's own extractions are gone), and asking it for another face is refused.

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "spaces/builds_on_elements.hpp"
#include "spaces/g1_4split/g1_4split_meshes.hpp"
#include "spaces/g1_4split/g1_4split_space.hpp"

namespace iga {
namespace {

/// u_h = Σ c_i N_i of the face's active functions with derivatives at a degree-6 rule.
FunctionValues evaluated(const Space& space, int element, const Eigen::VectorXd& local) {
  const std::unique_ptr<Space::Evaluator> ev = space.make_evaluator();
  PointValues geometry;
  FunctionValues out;
  ev->evaluate_element_function(element, *space.quadrature(element, 6), local,
                                update_values | update_gradients | update_hessians, geometry, out);
  return out;
}

TEST(G14BuildOn, APartOfANestedSkeletonEvaluatesItsFacesAsTheWholeSpaceAndRefusesTheOthers) {
  G14Options o;
  o.degree = 5;
  o.blending = Blending::q1;
  o.level = 1;  // the fan5 pentagon's 20 faces: gluing inherited from level 0
  const auto whole = std::make_shared<const G14Space>(g14_domain("fan5"), o);
  o.extent = SpaceExtent::skeleton;
  const auto skeleton = std::make_shared<const G14Space>(g14_domain("fan5"), o);
  ASSERT_EQ(skeleton->num_elements(), 20);
  EXPECT_EQ(skeleton->dimension(), whole->dimension());
  std::vector<int> a, b;
  const std::unique_ptr<Space::Evaluator> ev = skeleton->make_evaluator(), ew = whole->make_evaluator();
  for (int e = 0; e < skeleton->num_elements(); ++e) {
    EXPECT_FALSE(skeleton->built_on(e));
    skeleton->element_dofs(e, a);
    whole->element_dofs(e, b);
    EXPECT_EQ(a, b) << e;
    PointValues g, h;  // the geometry: element centres of the partition, mesh outlines
    ev->evaluate_geometry(e, *skeleton->quadrature(e, 1), g);
    ew->evaluate_geometry(e, *whole->quadrature(e, 1), h);
    EXPECT_EQ(g.x, h.x) << e;
  }
  PointValues values;
  EXPECT_THROW(ev->evaluate(0, *skeleton->quadrature(0, 6), update_values, values), std::logic_error);

  // Every third face: first from the skeleton's extractions, then from a rebuilt basis.
  std::vector<int> some;
  for (int e = 0; e < skeleton->num_elements(); e += 3) some.push_back(e);
  for (int round = 0; round < 2; ++round) {
    const SpacePtr built = on_elements(skeleton, some);
    for (int e = 0; e < built->num_elements(); ++e) {
      built->element_dofs(e, a);
      Eigen::VectorXd local(static_cast<Eigen::Index>(a.size()));
      for (Eigen::Index m = 0; m < local.size(); ++m) local(m) = std::cos(0.7 + static_cast<double>(m));
      if (e % 3 != 0) {
        EXPECT_THROW(evaluated(*built, e, local), std::logic_error) << e;
        continue;
      }
      const FunctionValues u = evaluated(*built, e, local), v = evaluated(*whole, e, local);
      EXPECT_EQ(u.value, v.value) << round << " " << e;
      EXPECT_EQ(u.dx, v.dx) << round << " " << e;
      EXPECT_EQ(u.dyy, v.dyy) << round << " " << e;
    }
  }
  // A space built on some faces asked for another: built again from the same skeleton.
  const SpacePtr first = on_elements(skeleton, some), second = on_elements(first, {1});
  second->element_dofs(1, a);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(static_cast<Eigen::Index>(a.size()));
  EXPECT_EQ(evaluated(*second, 1, ones).value, evaluated(*whole, 1, ones).value);
  second->element_dofs(0, a);
  EXPECT_THROW(evaluated(*second, 0, Eigen::VectorXd::Ones(static_cast<Eigen::Index>(a.size()))), std::logic_error);
}

}  // namespace
}  // namespace iga
