// G1 surfaces from a `domain: {type: surface}` config: built-ins, files, normals, options, and
// input errors at their keys.
#include <gtest/gtest.h>

#include "config/errors.hpp"
#include "geometry/surface_from_config.hpp"
#include "geometry/surface_patches.hpp"
#include "tests/support/scratch_files.hpp"

namespace iga {
namespace {

ConfigNode domain_of(const std::string& yaml, const std::string& name = "test.yaml") {
  return ConfigNode::load_string(yaml, name)["domain"];
}

std::string error_of(const std::string& yaml, const std::string& name = "test.yaml") {
  try {
    surface_from_config(domain_of(yaml, name));
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

TEST(SurfaceFromConfig, BuiltinIcosphereWithOptions) {
  const rsd::RsdSurface s =
      surface_from_config(domain_of("domain: {type: surface, mesh: icosphere, level: 1, tuple: pi1}"));
  EXPECT_EQ(s.mesh.num_triangles(), 80);
  EXPECT_EQ(s.report.patch_degree, 9);
  EXPECT_LT(s.report.max_g1_residual, 1e-12);
  const SurfacePatches patches = surface_patches_of(s);
  EXPECT_EQ(patches.labels[1], (std::pair<std::string, std::string>{"tuple", "pi1"}));
  EXPECT_EQ(patches.measures[0], (std::pair<std::string, double>{"patch_degree", 9.0}));
  EXPECT_EQ(patches.patches.size(), 80u);
  EXPECT_EQ(surface_from_config(domain_of("domain: {type: surface, mesh: octahedron, method: none}")).report.patch_degree,
            5);
}

TEST(SurfaceFromConfig, FileRelativeToTheConfigWithEstimatedNormals) {
  test::scratch_file("tet.off", "OFF\n4 4 6\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
  const std::string config = test::scratch_file("surface.yaml", "domain: {type: surface, file: tet.off}\n");
  const rsd::RsdSurface s = surface_from_config(ConfigNode::load_file(config)["domain"]);
  EXPECT_EQ(s.report.patch_degree, 8);
  EXPECT_NEAR(s.report.max_fold_alpha, -1.0, 1e-12);
}

TEST(SurfaceFromConfig, ErrorsNameTheKey) {
  EXPECT_NE(error_of("domain: {type: surface, mesh: icosphere}").find("level"), std::string::npos);
  EXPECT_NE(error_of("domain: {type: surface, mesh: octahedron, level: 2}").find("'level' applies to mesh: icosphere"),
            std::string::npos);
  EXPECT_NE(error_of("domain: {type: surface, mesh: icosphere, level: 1, tuple: pi2}").find("tuple"), std::string::npos);
  EXPECT_NE(error_of("domain: {type: surface, mesh: cube}").find("mesh"), std::string::npos);
  EXPECT_NE(error_of("domain: {type: surface, mesh: octahedron, file: a.obj}").find("not both"), std::string::npos);
  EXPECT_NE(error_of("domain: {type: surface, mesh: octahedron, normal: fan}").find("unknown key 'normal'"),
            std::string::npos);
  const std::string missing = error_of("domain: {type: surface, file: missing.obj}", "cfg.yaml");
  EXPECT_NE(missing.find("cfg.yaml:1:"), std::string::npos) << missing;
  EXPECT_NE(missing.find("cannot open"), std::string::npos) << missing;
}

}  // namespace
}  // namespace iga
