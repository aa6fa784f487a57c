/// @file
/// A G1 space built on some of its elements (BuildsOnElements, what one rank of a distributed
/// solve keeps): the skeleton has the whole numbering and geometry and no extraction, the space
/// built on a set of elements evaluates them bit for bit as the whole space does, and asking it for
/// another element is a programming error.

#include <gtest/gtest.h>

#include <memory>

#include "spaces/g1/g1_space.hpp"
#include "spaces/g1/multipatch_domains.hpp"
#include "tests/support/build_on_checks.hpp"

namespace iga {
namespace {

TEST(G1BuildOn, APartOfTheSkeletonEvaluatesItsElementsAsTheWholeSpaceAndRefusesTheOthers) {
  // The three-patch square refined twice: 48 quads with an extraordinary vertex of valence 3.
  const auto mesh = std::make_shared<const PatchMesh>(multipatch_domain("3p_square").refined().refined());
  const auto whole = std::make_shared<const G1Space>(mesh, 5);
  const auto skeleton = std::make_shared<const G1Space>(mesh, 5, SpaceExtent::skeleton);
  ASSERT_EQ(skeleton->num_elements(), 48);
  test::expect_skeleton_of(*skeleton, *whole);
  // Every third face; then the same again, which solves the local problems a second time.
  std::vector<int> some;
  for (int e = 0; e < skeleton->num_elements(); e += 3) some.push_back(e);
  for (int round = 0; round < 2; ++round) test::expect_built_as_whole(*on_elements(skeleton, some), *whole, some, 6);
}

}  // namespace
}  // namespace iga
