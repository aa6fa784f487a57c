// space.refine_near: cells meeting a point, a box or a parametric curve refined `times` times,
// admissibly; cell counts, admissibility, dimension formula = constructed basis, config errors.
#include <gtest/gtest.h>

#include <string>

#include "config/errors.hpp"
#include "spaces/tmesh/tmesh_refinement.hpp"
#include "spaces/tmesh/tmesh_space.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {

/// Cubic C1 (n = 3, r = 1) on the unit square, 4 x 4 base cells, with the given refine_near list.
SpacePtr square_with(const std::string& refine_near, int n = 3, int r = 1) {
  return test::space_from_yaml("domain: {type: rectangle, min: [0, 0], max: [1, 1]}\n"
                               "space: {type: tmesh, section: poly, n: " + std::to_string(n) + ", regularity: " +
                               std::to_string(r) + ", elements: [4, 4], refine_near: " + refine_near + "}\n");
}

const TMeshSpace& as_tmesh(const SpacePtr& s) { return dynamic_cast<const TMeshSpace&>(*s); }

void expect_valid(const SpacePtr& space, int r) {
  const TMeshSpace& t = as_tmesh(space);
  EXPECT_EQ(t.mesh().admissibility_problem(), "");
  EXPECT_EQ(t.dimension(), t.mesh().dimension_formula(r, r));
  EXPECT_LT(t.extraction().corner_mismatch, 1e-9);
  for (auto [a, b] : side_neighbours(t.mesh()))
    EXPECT_LE(std::max(t.mesh().width(a), t.mesh().width(b)), 2.0 * std::min(t.mesh().width(a), t.mesh().width(b)) + 1e-14);
}

std::string error_of(const std::string& refine_near) {
  try {
    square_with(refine_near);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RefineNear, PointAtAVertexSplitsTheFourCellsAroundItEachTime) {
  // Each step splits the 4 cells at (0.5, 0.5) into 16, one level finer: +12 cells, no balancing.
  for (int times : {1, 2, 3}) {
    const SpacePtr s = square_with("[{point: [0.5, 0.5], times: " + std::to_string(times) + "}]");
    EXPECT_EQ(s->num_elements(), 16 + 12 * times) << times;
    expect_valid(s, 1);
  }
}

TEST(RefineNear, PointInsideACellAddsTheBalancingNeighbours) {
  // (0.125, 0.125) is the centre of the corner cell: step 1 splits it (+3); step 2 splits its four
  // children (+12), now 4x smaller than the cells to their right and above, which split too (+6).
  const SpacePtr s = square_with("[{point: [0.125, 0.125], times: 2}]");
  EXPECT_EQ(s->num_elements(), 16 + 3 + 12 + 6);
  expect_valid(s, 1);
}

TEST(RefineNear, BoxesRefineTheCellsTheyOverlap) {
  // Touching the corner cell's sides does not count: one cell, then the 2 x 2 block.
  EXPECT_EQ(square_with("[{box: [[0, 0], [0.25, 0.25]]}]")->num_elements(), 19);
  EXPECT_EQ(square_with("[{box: [[0, 0], [0.3, 0.3]]}]")->num_elements(), 28);
  // Entries apply in order: the box, then a point at the box's inner corner (4 cells of size 1/8).
  const SpacePtr s = square_with("[{box: [[0, 0], [0.5, 0.5]], times: 1}, {point: [0.25, 0.25], times: 1}]", 2, 0);
  EXPECT_EQ(s->num_elements(), 16 + 12 + 12);
  expect_valid(s, 0);
}

TEST(RefineNear, CurveRefinesTheCellsItCrosses) {
  // Circle of radius 0.3 about the centre: it crosses the 4 inner and the 8 side cells of the 4 x 4
  // grid and misses the 4 corner cells (their nearest point is 0.354 from the centre).
  const SpacePtr s = square_with(
      "[{curve: {x: \"0.5 + 0.3*cos(t)\", y: \"0.5 + 0.3*sin(t)\", t: [0, 6.283185307179586]}, times: 1}]");
  EXPECT_EQ(s->num_elements(), 16 + 3 * 12);
  expect_valid(s, 1);
  // Twice, with the trigonometric C1 space too.
  const SpacePtr twice = square_with(
      "[{curve: {x: \"0.5 + 0.3*cos(t)\", y: \"0.5 + 0.3*sin(t)\", t: [0, 6.283185307179586], samples: 2000}, times: 2}]");
  EXPECT_GT(twice->num_elements(), s->num_elements());
  expect_valid(twice, 1);
}

TEST(RefineNear, BadEntriesNameTheirPlace) {
  auto expect_error = [](const std::string& refine_near, const std::string& part) {
    const std::string msg = error_of(refine_near);
    EXPECT_NE(msg.find("test.yaml:"), std::string::npos) << msg;
    EXPECT_NE(msg.find(part), std::string::npos) << "expected '" << part << "' in: " << msg;
  };
  expect_error("[{point: [2, 2]}]", "no cell of the T-mesh meets");
  expect_error("[{point: [0.5, 0.5], times: 0}]", "times must be between 1 and 20");
  expect_error("[{pont: [0.5, 0.5]}]", "did you mean 'point'");
  expect_error("[{times: 2}]", "exactly one of point, box or curve");
  expect_error("[{point: [0.5, 0.5], box: [[0, 0], [1, 1]]}]", "exactly one of point, box or curve");
  expect_error("[{box: [[0.5, 0.5], [0, 0]]}]", "x0 < x1");
  expect_error("[{curve: {x: \"cos(s)\", y: \"t\", t: [0, 1]}}]", "as an expression in t");
  expect_error("[{curve: {x: \"t\", y: \"t\", t: [1, 0]}}]", "t0 < t1");
  expect_error("[{curve: {x: \"sqrt(t - 0.5)\", y: \"t\", t: [0, 1]}}]", "not finite");
  expect_error("{point: [0.5, 0.5]}", "expected a list");
  // The lattice allows 24 dyadic splits of a base cell.
  expect_error("[{point: [0.5, 0.5], times: 13}, {point: [0.5, 0.5], times: 13}]", "cannot refine 13 times");
}
