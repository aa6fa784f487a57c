// The geometry study as a config states it: the icosphere surfaces level by level against the
// sphere (the note's table §5.6 for L = 0..2, with rates), and input errors for what does not fit
// (a level of its own, another mesh, PDE sections, a bad reference).
#include "geometry/geometry_study.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/input_error.hpp"

namespace iga {
namespace {

GeometryStudySettings settings_of(const std::string& yaml, int levels = 0) {
  return parse_geometry_study(ConfigNode::load_string(yaml, "g.yaml"), "g.yaml", levels, "");
}

const char* kStudy = R"(
study: {type: geometry, levels: 3, reference: {type: sphere, center: [0, 0, 0], radius: 1}}
domain: {type: surface, mesh: icosphere, normals: exact}
)";

TEST(GeometryStudy, IcosphereLevelsReproduceTheNotesTable) {
  const auto rows = run_geometry_study(settings_of(kStudy), [](const std::string&) {});
  ASSERT_EQ(rows.size(), 3u);
  // Note §5.6 (three digits): radial, normal (degrees), relative area and volume errors.
  const double note[3][4] = {{3.06e-2, 7.68, 1.69e-2, 3.13e-2}, {7.82e-3, 3.22, 8.47e-3, 1.19e-2},
                             {2.99e-3, 1.67, 3.33e-3, 4.76e-3}};
  for (int l = 0; l < 3; ++l) {
    EXPECT_EQ(rows[l].triangles, 20 << (2 * l));
    EXPECT_NEAR(rows[l].radial, note[l][0], 0.015 * note[l][0]);
    EXPECT_NEAR(rows[l].normal_degrees, note[l][1], 0.015 * note[l][1]);
    EXPECT_NEAR(rows[l].area_error, note[l][2], 0.015 * note[l][2]);
    EXPECT_NEAR(rows[l].volume_error, note[l][3], 0.015 * note[l][3]);
    EXPECT_TRUE(rows[l].patches.patches.empty());  // rows keep the report, not the patches
    ASSERT_FALSE(rows[l].patches.measures.empty());
    EXPECT_EQ(rows[l].patches.measures[0].first, "patch_degree");
    EXPECT_EQ(rows[l].patches.measures[0].second, 8.0);
  }
}

TEST(GeometryStudy, ACentreAndRadiusScaleTheErrors) {
  // The icosphere has unit radius: against the sphere of radius 2 about (1, 0, 0) the relative
  // area error is |A/(16π) − 1| with A ≈ 4π.
  const auto rows = run_geometry_study(settings_of(R"(
study: {type: geometry, levels: 1, reference: {type: sphere, center: [1, 0, 0], radius: 2}}
domain: {type: surface, mesh: icosphere}
)"),
                                       [](const std::string&) {});
  EXPECT_NEAR(rows[0].area_error, 0.75, 0.01);
  EXPECT_GT(rows[0].radial, 1.0);
}

TEST(GeometryStudy, WhatDoesNotFitIsAnInputErrorAtItsKey) {
  const auto error = [](const std::string& yaml) { return test::input_error([&] { settings_of(yaml); }); };
  EXPECT_NE(error(R"(
study: {type: geometry, reference: {type: sphere}}
domain: {type: surface, mesh: icosphere, level: 2}
)").find("g.yaml:3"),
            std::string::npos);
  EXPECT_NE(error(R"(
study: {type: geometry, reference: {type: sphere}}
domain: {type: surface, mesh: octahedron}
)").find("icosphere"),
            std::string::npos);
  EXPECT_NE(error(R"(
study: {type: geometry, reference: {type: sphere}}
domain: {type: surface, mesh: icosphere}
space: {type: surface, degree: 2}
)").find("space"),
            std::string::npos);
  EXPECT_NE(error(R"(
study: {type: geometry, reference: {type: sphere, radius: -1}}
domain: {type: surface, mesh: icosphere}
)").find("radius"),
            std::string::npos);
  EXPECT_NE(error(R"(
study: {type: geometry, levels: 9, reference: {type: sphere}}
domain: {type: surface, mesh: icosphere}
)").find("levels"),
            std::string::npos);
  EXPECT_NE(error(R"(
study: {type: geometry}
domain: {type: surface, mesh: icosphere}
)").find("reference"),
            std::string::npos);
  EXPECT_EQ(settings_of(kStudy, 2).levels, 2);  // --levels
}

}  // namespace
}  // namespace iga
