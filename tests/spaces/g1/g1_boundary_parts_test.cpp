// Named boundary parts of multipatch domains (sides of the bounding box) and their use by G1Space.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "config/errors.hpp"
#include "spaces/g1/boundary_parts.hpp"
#include "spaces/g1/g1_space.hpp"
#include "spaces/g1/multipatch_domains.hpp"

using namespace iga;

namespace {

double length(const PatchMesh& m, const std::vector<BoundaryEdge>& edges) {
  double sum = 0;
  for (const BoundaryEdge& e : edges)
    sum += (m.vertex(m.face(e.element)[e.local_edge]) - m.vertex(m.face(e.element)[(e.local_edge + 1) % 4])).norm();
  return sum;
}

}  // namespace

TEST(G1BoundaryParts, SquareHasFourSidesOfLengthOne) {
  PatchMesh m = multipatch_domain("3p_square");
  for (int level = 0; level < 3; ++level, m = m.refined()) {
    EXPECT_EQ(boundary_part_names(m), (std::vector<std::string>{"left", "right", "bottom", "top"}));
    for (const char* side : {"left", "right", "bottom", "top"})
      EXPECT_NEAR(length(m, boundary_part_edges(m, side)), 1.0, 1e-14) << side << " level " << level;
    EXPECT_NEAR(length(m, boundary_part_edges(m, "all")), 4.0, 1e-14);
  }
  // 3p_square: bottom is split at (0.4, 0) and right at (1, 0.7) on level 0; level 2 has 4x.
  const PatchMesh l0 = multipatch_domain("3p_square");
  EXPECT_EQ(boundary_part_edges(l0, "bottom").size(), 2u);
  EXPECT_EQ(boundary_part_edges(l0, "right").size(), 2u);
  EXPECT_EQ(boundary_part_edges(l0, "left").size(), 1u);
  EXPECT_EQ(boundary_part_edges(l0.refined().refined(), "top").size(), 4u);
  // Every left edge really lies on x = 0.
  for (const BoundaryEdge& e : boundary_part_edges(l0, "left"))
    for (int c : {0, 1}) EXPECT_EQ(l0.vertex(l0.face(e.element)[(e.local_edge + c) % 4]).x(), 0.0);
}

TEST(G1BoundaryParts, LShapeReentrantSidesAreOnlyInAll) {
  // (-1,1)^2 minus [0,1)x(-1,0]: left and top have length 2, right and bottom 1, the two
  // re-entrant sides (total 2) lie on no side of the bounding box.
  const PatchMesh m = multipatch_domain("lshape_8p").refined();
  EXPECT_NEAR(length(m, boundary_part_edges(m, "left")), 2.0, 1e-14);
  EXPECT_NEAR(length(m, boundary_part_edges(m, "top")), 2.0, 1e-14);
  EXPECT_NEAR(length(m, boundary_part_edges(m, "right")), 1.0, 1e-14);
  EXPECT_NEAR(length(m, boundary_part_edges(m, "bottom")), 1.0, 1e-14);
  EXPECT_NEAR(length(m, boundary_part_edges(m, "all")), 8.0, 1e-14);
}

TEST(G1BoundaryParts, UnknownOrEmptyPartIsRejectedWithTheValidNames) {
  const PatchMesh hex = multipatch_domain("3p_hexagon");
  const std::vector<std::string> names = boundary_part_names(hex);
  EXPECT_LT(names.size(), 4u);  // a regular hexagon touches at most two opposite sides of its box
  try {
    boundary_part_edges(multipatch_domain("3p_square"), "front");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("valid: all, left, right, bottom, top"), std::string::npos) << e.what();
  }
  const G1Space space(std::make_shared<const PatchMesh>(multipatch_domain("3p_square")), 5);
  EXPECT_EQ(space.boundary_names().size(), 4u);
  EXPECT_EQ(space.boundary_edges("right").size(), 2u);
  EXPECT_THROW(space.boundary_edges("north"), InputError);
}
