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

/// The parts set_boundary_parts writes into the facts, by name ("all" too), and their names in order.
struct Parts {
  std::map<std::string, std::vector<BoundaryEdge>> edges;
  std::vector<std::string> names;
  explicit Parts(const PatchMesh& m) {
    SpaceFacts facts;
    set_boundary_parts(m, facts);
    edges["all"] = facts.all_boundary_edges;
    for (const auto& [name, e] : facts.boundary_parts) {
      names.push_back(name);
      edges[name] = e;
    }
  }
  const std::vector<BoundaryEdge>& operator()(const std::string& name) const { return edges.at(name); }
};

}  // namespace

TEST(G1BoundaryParts, SquareHasFourSidesOfLengthOne) {
  PatchMesh m = multipatch_domain("3p_square");
  for (int level = 0; level < 3; ++level, m = m.refined()) {
    const Parts parts(m);
    EXPECT_EQ(parts.names, (std::vector<std::string>{"left", "right", "bottom", "top"}));
    for (const char* side : {"left", "right", "bottom", "top"})
      EXPECT_NEAR(length(m, parts(side)), 1.0, 1e-14) << side << " level " << level;
    EXPECT_NEAR(length(m, parts("all")), 4.0, 1e-14);
  }
  // 3p_square: bottom is split at (0.4, 0) and right at (1, 0.7) on level 0; level 2 has 4x.
  const PatchMesh l0 = multipatch_domain("3p_square");
  const Parts p0(l0);
  EXPECT_EQ(p0("bottom").size(), 2u);
  EXPECT_EQ(p0("right").size(), 2u);
  EXPECT_EQ(p0("left").size(), 1u);
  EXPECT_EQ(Parts(l0.refined().refined())("top").size(), 4u);
  // Every left edge really lies on x = 0.
  for (const BoundaryEdge& e : p0("left"))
    for (int c : {0, 1}) EXPECT_EQ(l0.vertex(l0.face(e.element)[(e.local_edge + c) % 4]).x(), 0.0);
}

TEST(G1BoundaryParts, LShapeReentrantSidesAreOnlyInAll) {
  // (-1,1)^2 minus [0,1)x(-1,0]: left and top have length 2, right and bottom 1, the two
  // re-entrant sides (total 2) lie on no side of the bounding box.
  const PatchMesh m = multipatch_domain("lshape_8p").refined();
  const Parts parts(m);
  EXPECT_NEAR(length(m, parts("left")), 2.0, 1e-14);
  EXPECT_NEAR(length(m, parts("top")), 2.0, 1e-14);
  EXPECT_NEAR(length(m, parts("right")), 1.0, 1e-14);
  EXPECT_NEAR(length(m, parts("bottom")), 1.0, 1e-14);
  EXPECT_NEAR(length(m, parts("all")), 8.0, 1e-14);
}

TEST(G1BoundaryParts, UnknownOrEmptyPartIsRejectedWithTheValidNames) {
  const PatchMesh hex = multipatch_domain("3p_hexagon");
  EXPECT_LT(Parts(hex).names.size(), 4u);  // a regular hexagon touches at most two opposite sides of its box
  const G1Space space(std::make_shared<const PatchMesh>(multipatch_domain("3p_square")), 5);
  try {
    space.boundary_edges("front");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("valid: all, left, right, bottom, top"), std::string::npos) << e.what();
  }
  EXPECT_EQ(space.boundary_names().size(), 4u);
  EXPECT_EQ(space.boundary_edges("right").size(), 2u);
  EXPECT_THROW(space.boundary_edges("north"), InputError);
}
