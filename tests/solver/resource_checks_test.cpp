/// The limits applied to a study: requests refused before the coarsest space is built, levels
/// estimated from the request (B-splines) or from level 0 before the study, with messages naming
/// the key to raise.
#include "solver/resource_checks.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <sstream>

#include "solver/study.hpp"
#include "spaces/space_factory.hpp"
#include "tests/support/scratch_files.hpp"

namespace iga {
namespace {

const char* kBase = R"yaml(problem: {pde: poisson, exact: "x*y", boundary: {all: dirichlet}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
)yaml";

std::string study_error(const std::string& rest, int levels_override = 0) {
  try {
    parse_study(ConfigNode::load_string(std::string(kBase) + rest, "run.yaml"), "run.yaml", levels_override, "");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ResourceChecks, DegreeAndElementsAreRefusedBeforeTheSpaceIsBuilt) {
  EXPECT_EQ(study_error("space: {type: bspline, degree: 100, elements: [2, 2]}\n"),
            "run.yaml:3:32: space.degree: degree 100 exceeds limits.max_degree = 12 (raise limits.max_degree in the "
            "config if this is intended, e.g. limits: {max_degree: ...})");
  // A billion elements: refused at once, not by bad_alloc after seconds.
  EXPECT_NE(study_error("space: {type: bspline, degree: 2, elements: [40000, 40000]}\n")
                .find("run.yaml:3:45: space.elements: about 1.6e+09 elements exceed limits.max_elements"),
            std::string::npos);
  EXPECT_EQ(study_error("space: {type: bspline, degree: 14, elements: [2, 2]}\nlimits: {max_degree: 14}\n"), "");
  // A space whose degree has another key (a T-mesh's section dimension n) is checked once built.
  EXPECT_EQ(study_error("space: {type: tmesh, section: poly, n: 13, regularity: 1, elements: [2, 2]}\n"),
            "run.yaml:3:8: space: the tmesh space has degree 13, more than limits.max_degree = 12 (raise "
            "limits.max_degree in the config if this is intended, e.g. limits: {max_degree: ...})");
}

TEST(ResourceChecks, LevelsAreEstimatedFromLevelZero) {
  // 2 x 2 elements: level l has 4^(l+1) elements; level 10 has 4.2e6 > 4e6.
  const std::string base = "space: {type: bspline, degree: 2, elements: [2, 2]}\n";
  EXPECT_EQ(study_error(base + "refinement: {levels: 10}\n"), "");
  const std::string m = study_error(base + "refinement: {levels: 11}\n");
  // A B-spline space's levels follow from its request: checked before level 0 is built.
  EXPECT_EQ(m.rfind("run.yaml:4:22: refinement.levels: level 10 of refinement.levels 11 (from space.elements and "
                    "space.degree) has ", 0), 0u) << m;
  EXPECT_NE(m.find("limits.max_elements"), std::string::npos) << m;
  EXPECT_EQ(study_error(base + "refinement: {levels: 11}\nlimits: {max_elements: 1e7, max_dofs: 2e7, max_memory_gb: 1e3}\n"), "");
  // Degrees of freedom and memory have their own keys.
  EXPECT_NE(study_error(base + "refinement: {levels: 4}\nlimits: {max_dofs: 1000}\n").find("more than limits.max_dofs = 1000"),
            std::string::npos);
  EXPECT_NE(study_error(base + "refinement: {levels: 4}\nlimits: {max_memory_gb: 1e-6}\n").find("limits.max_memory_gb"),
            std::string::npos);
  // The command line's --levels is blamed on the space (no config key holds it), and named.
  EXPECT_EQ(study_error(base, 11).rfind("run.yaml:3:8: space: level 10 of --levels 11", 0), 0u) << study_error(base, 11);
  // Other spaces: estimated from the built level 0.
  const std::string t = study_error("space: {type: tmesh, section: poly, n: 3, regularity: 1, elements: [2, 2]}\n"
                                    "refinement: {levels: 11}\n");
  EXPECT_EQ(t.rfind("run.yaml:4:22: refinement.levels: level ", 0), 0u) << t;
  EXPECT_NE(t.find(" (estimated from level 0) has "), std::string::npos) << t;
}

TEST(ResourceChecks, RequestedBsplineSizesAreTheBuiltOnes) {
  // The closed form against the built spaces, levels 0 to 2, with and without reduced regularity.
  for (const char* space : {"space: {type: bspline, degree: 2, elements: [3, 2]}\n",
                            "space: {type: bspline, degree: 3, regularity: 1, elements: [2, 5]}\n",
                            "space: {type: bspline, degree: 1}\n"}) {
    const ConfigNode root = ConfigNode::load_string(std::string(kBase) + space);
    for (int level = 0; level <= 2; ++level) {
      const SpaceSize built = measure(*make_space(root["domain"], root["space"], level));
      const auto sizes = requested_space_sizes(root["domain"], root["space"], level + 1);
      ASSERT_EQ(sizes.size(), static_cast<std::size_t>(level + 1)) << space;
      const SpaceRequestSize& requested = sizes[level];
      EXPECT_EQ(requested.elements, built.elements) << space << level;
      EXPECT_EQ(requested.dofs, built.dofs) << space << level;
      EXPECT_EQ(requested.element_entries, built.element_entries) << space << level;
    }
  }
  const ConfigNode other = ConfigNode::load_string(std::string(kBase) + "space: {type: ws4}\n");
  EXPECT_TRUE(requested_space_sizes(other["domain"], other["space"], 1).empty());
}

TEST(ResourceChecks, IterativePetscSolvesAreEstimatedWithoutAFactor) {
  // Cubic B-splines on 1000 x 1000 elements: 1 006 009 DOFs, 16 functions per element.
  const SpaceSize s{1e6, 1006009, 256e6};
  EXPECT_NEAR(estimated_memory_bytes(s) / 1e9, 8.5 * 256e6 * std::log2(1006009.0) / 1e9, 1e-9);  // 43.4 GB
  EXPECT_NEAR(estimated_memory_bytes(s, {false, 1}) / 1e9, (400 * 1006009.0 + 7 * 256e6) / 1e9, 1e-9);  // 2.19 GB
  // Over two ranks the matrix divides, the replicated space does not; a factor divides.
  EXPECT_NEAR(estimated_memory_bytes(s, {false, 2}) / 1e9, (400 * 1006009.0 + 3.5 * 256e6) / 1e9, 1e-9);
  EXPECT_NEAR(estimated_memory_bytes(s, {true, 2}), estimated_memory_bytes(s) / 2, 1.0);

  EXPECT_TRUE(memory_model(SolverKind::cholmod, {}).factorization);
  PetscSettings petsc;
  for (const char* pc : {"gamg", "hypre", "ilu"}) {
    petsc.pc = pc;
    EXPECT_FALSE(memory_model(SolverKind::petsc, petsc).factorization) << pc;
  }
  for (const char* pc : {"mumps", "cholesky"}) {
    petsc.pc = pc;
    EXPECT_TRUE(memory_model(SolverKind::petsc, petsc).factorization) << pc;
  }
  if (!petsc_available()) return;
  // Level 5 of 8 x 8 cubic elements: a factor of about 2.3 GB, CG + GAMG about 0.17 GB.
  const std::string base = "space: {type: bspline, degree: 3, elements: [8, 8]}\nrefinement: {levels: 6}\n"
                           "limits: {max_memory_gb: 1}\n";
  EXPECT_NE(study_error(base + "solver: {type: cholmod}\n").find("GB (matrix and factor), more than limits.max_memory_gb"),
            std::string::npos);
  EXPECT_EQ(study_error(base + "solver: {type: petsc}\n"), "");
  EXPECT_NE(study_error(base + "solver: {type: petsc, ksp: preonly, pc: mumps}\n").find("limits.max_memory_gb"),
            std::string::npos);
}

TEST(ResourceChecks, MeasureCountsElementEntries) {
  const ConfigNode root = ConfigNode::load_string(std::string(kBase) + "space: {type: bspline, degree: 2, elements: [3, 2]}\n");
  const SpaceSize s = measure(*make_space(root["domain"], root["space"], 0));
  EXPECT_EQ(s.elements, 6.0);
  EXPECT_EQ(s.dofs, 5.0 * 4.0);            // (3 + 2) x (2 + 2) quadratic C1 B-splines
  EXPECT_EQ(s.element_entries, 6.0 * 81);  // 9 active functions per element
  const SpaceSize l2 = uniform_estimate(s, 2);
  EXPECT_EQ(l2.elements, 96.0);
  EXPECT_GE(l2.dofs, 14.0 * 10.0);  // the estimate bounds the true level-2 dimension from above
}

/// An n x n grid of quads on a slightly curved sheet, as an .obj file in the scratch folder.
std::string quad_grid_obj(int n) {
  std::ostringstream obj;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) obj << "v " << double(i) / n << " " << double(j) / n << " " << 0.1 * i * i / (n * n) << "\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i + 1;
      obj << "f " << a << " " << a + 1 << " " << a + n + 2 << " " << a + n + 1 << "\n";
    }
  return test::scratch_file("grid" + std::to_string(n) + ".obj", obj.str());
}

ConfigNode surface_config(int n, const std::string& rest = "") {
  quad_grid_obj(n);
  return ConfigNode::load_string("problem: {pde: laplace_beltrami, exact: \"x*y\", boundary: {all: dirichlet}}\n"
                                 "domain: {type: surface, file: grid" + std::to_string(n) + ".obj}\n"
                                 "space: {type: g1_4split, degree: 5}\n" + rest,
                                 (test::scratch_folder() / "surface.yaml").string());
}

TEST(ResourceChecks, SurfaceFilesAreEstimatedFromTheirFaces) {
  // Against the built space: as many elements, at least as many DOFs and entries, not far more
  // (6 x 6 faces: 2644 DOFs estimated, 2500 built).
  const ConfigNode root = surface_config(6);
  const auto sizes = requested_space_sizes(root["domain"], root["space"], 2);
  ASSERT_EQ(sizes.size(), 2u);
  for (int level = 0; level < 2; ++level) {
    const SpaceSize built = measure(*make_space(root["domain"], root["space"], level));
    EXPECT_EQ(sizes[level].elements, built.elements) << level;
    EXPECT_GE(sizes[level].dofs, built.dofs) << level;
    EXPECT_LE(sizes[level].dofs, 1.2 * built.dofs) << level;
    EXPECT_GE(sizes[level].element_entries, built.element_entries) << level;
    EXPECT_LE(sizes[level].element_entries, 1.2 * built.element_entries) << level;
    // (2k - r + 1)^4 = 10^4: 64 N² bytes per face to build level 0, 8 N² per face of a nested level
    // on top of level 0's.
    const double level0 = 64.0 * 1e4 * sizes[0].elements;
    EXPECT_EQ(sizes[level].build_bytes, level == 0 ? level0 : level0 + 8.0 * 1e4 * built.elements) << level;
  }
  // Other domains and spaces: no estimate.
  const ConfigNode cube = ConfigNode::load_string("domain: {type: surface, mesh: cube}\nspace: {type: g1_4split, degree: 5}\n");
  EXPECT_TRUE(requested_space_sizes(cube["domain"], cube["space"], 2).empty());
}

TEST(ResourceChecks, ALargeSurfaceFileIsRefusedBeforeLevelZero) {
  // 6400 faces at degree 5: about 4 GB to build level 0 (3.2 GB measured, after 70 s), and more to
  // factorize its matrix.
  const auto start = std::chrono::steady_clock::now();
  std::string m;
  try {
    parse_study(surface_config(80, "limits: {max_memory_gb: 2}\n"), "surface.yaml", 0, "");
  } catch (const InputError& e) {
    m = e.what();
  }
  EXPECT_NE(m.find("surface.yaml:2:31: domain.file: level 0 (from the 6400 faces of domain.file and space.degree) "
                   "needs about "),
            std::string::npos)
      << m;
  EXPECT_NE(m.find(" GB (the space, matrix and factor), more than limits.max_memory_gb = 2"), std::string::npos) << m;
  // Requested levels: blamed on --levels.
  try {
    parse_study(surface_config(80, "limits: {max_memory_gb: 1e3}\n"), "surface.yaml", 4, "");
    m.clear();
  } catch (const InputError& e) {
    m = e.what();
  }
  EXPECT_NE(m.find("surface.yaml:3:8: space: level 2 of --levels 4 (from the 6400 faces of domain.file and "
                   "space.degree) has "), std::string::npos)
      << m;
  EXPECT_NE(m.find("more than limits.max_dofs"), std::string::npos) << m;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

}  // namespace
}  // namespace iga
