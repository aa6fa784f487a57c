/// @file
/// A 4-split G1 space built on some of its elements (BuildsOnElements, what one rank of a
/// distributed solve keeps), on a nested level: the skeleton has the whole numbering, geometry and
/// inherited gluing and no extraction; the space built on a set of faces evaluates them bit for bit
/// as the whole space does (it solves the local problems of those faces' vertices and edges, every
/// time it is asked), and asking it for another face is refused.

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "spaces/g1_4split/g1_4split_meshes.hpp"
#include "spaces/g1_4split/g1_4split_space.hpp"
#include "tests/support/build_on_checks.hpp"

namespace iga {
namespace {

TEST(G14BuildOn, APartOfANestedSkeletonEvaluatesItsFacesAsTheWholeSpaceAndRefusesTheOthers) {
  G14Options o;
  o.degree = 5;
  o.blending = Blending::q1;
  o.level = 1;  // the fan5 pentagon's 20 faces: gluing inherited from level 0
  const auto whole = std::make_shared<const G14Space>(g14_domain("fan5"), o);
  o.extent = SpaceExtent::skeleton;
  const auto skeleton = std::make_shared<const G14Space>(g14_domain("fan5"), o);
  ASSERT_EQ(skeleton->num_elements(), 20);
  test::expect_skeleton_of(*skeleton, *whole);
  // Every third face, twice: each build solves its faces' local problems again.
  std::vector<int> some;
  for (int e = 0; e < skeleton->num_elements(); e += 3) some.push_back(e);
  for (int round = 0; round < 2; ++round) test::expect_built_as_whole(*on_elements(skeleton, some), *whole, some, 6);
  // A space built on some faces asked for another: built again from the same skeleton.
  const SpacePtr first = on_elements(skeleton, some), second = on_elements(first, {1});
  std::vector<int> a;
  second->element_dofs(1, a);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(static_cast<Eigen::Index>(a.size()));
  EXPECT_EQ(test::element_function(*second, 1, ones, 6).value, test::element_function(*whole, 1, ones, 6).value);
  second->element_dofs(0, a);
  EXPECT_THROW(test::element_function(*second, 0, Eigen::VectorXd::Ones(static_cast<Eigen::Index>(a.size())), 6),
               std::logic_error);
}

}  // namespace
}  // namespace iga
