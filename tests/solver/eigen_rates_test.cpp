// Orders of eigenvalue errors on uniform refinement, through the study (run_study, the path of
// iga-run): twice the energy-norm order for smooth eigenfunctions, 2p for the Laplacian and
// 2(p − 1) for plates (Babuška–Osborn, "Eigenvalue problems", Handbook of Numerical Analysis II,
// 1991: |λ_h − λ| ≈ ‖u − u_h‖²_energy), and the clamped plate's λ₁ against its literature value.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "solver/eigen_table.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

/// The eigen rows of a study of `yaml` (its own refinement.levels).
std::vector<EigenRow> study_rows(const std::string& yaml) {
  const StudySettings settings = parse_study(ConfigNode::load_string(yaml, "test.yaml"), "test.yaml", 0, "");
  const StudyResult result = run_study(settings, [](const std::string&) {});
  const std::vector<EigenRow> rows = eigen_rows(result.eigen, settings.problem.eigen->exact);
  for (const EigenRow& r : rows)
    std::printf("level %d dofs %6d index %d  λ %.15e  error %.3e  rate %.2f\n", r.level, r.dofs, r.index, r.eigenvalue,
                r.relative_error.value_or(0), r.rate.value_or(0));
  return rows;
}

/// The rate in h of eigenvalue `index` at the last level.
double last_rate(const std::vector<EigenRow>& rows, int index) {
  for (auto r = rows.rbegin(); r != rows.rend(); ++r)
    if (r->index == index) return r->rate.value();
  throw std::logic_error("no such index");
}

TEST(EigenRates, LaplacianOnCubicBSplinesConvergesLikeHToThe6) {
  const std::vector<EigenRow> rows = study_rows(R"yaml(
problem: {pde: poisson, boundary: {all: dirichlet}, eigen: {count: 6, exact_eigenvalues: "pi^2*(m^2 + n^2)"}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 3, elements: [4, 4]}
refinement: {levels: 4}
)yaml");
  // From 16 x 16 to 32 x 32 elements, measured 6.02 (λ₁), 6.08 (λ₂, λ₄), 6.17 (λ₅): the rates of
  // the higher eigenvalues approach 2p from above (6.53, 6.17, 6.05 for λ₅ on 8, 16, 32 elements).
  for (int index : {1, 2, 4}) EXPECT_NEAR(last_rate(rows, index), 6.0, 0.1) << "index " << index;
  EXPECT_NEAR(last_rate(rows, 5), 6.0, 0.25);
  EXPECT_LT(rows[rows.size() - 6].relative_error.value(), 4e-11);  // λ₁ on 32 x 32: 2.97e-11
  // λ₂ = λ₃ (m, n = 1, 2 and 2, 1) to round-off: the square's symmetry is kept by the space.
  EXPECT_NEAR(rows[1].eigenvalue, rows[2].eigenvalue, 1e-12 * rows[1].eigenvalue);
}

TEST(EigenRates, LaplacianOnWs4ConvergesLikeHToThe8) {
  const std::vector<EigenRow> rows = study_rows(R"yaml(
problem: {pde: poisson, boundary: {all: dirichlet}, eigen: {count: 6, exact_eigenvalues: "pi^2*(m^2 + n^2)"}}
domain: {type: unit_square}
space: {type: ws4, elements: 2}
refinement: {levels: 3}
)yaml");
  // WS4 is quartic (and C3): 2p = 8. From 4 to 8 elements a side, measured 8.07 for λ₁; the higher
  // ones still approach 8 from above (8.35, 8.58, 8.09, 8.26 for λ₂, λ₄, λ₅, λ₆; λ₄ was 8.91 a
  // level before, and on 16 elements λ₆'s is 8.17).
  EXPECT_NEAR(last_rate(rows, 1), 8.0, 0.15);
  for (int index : {2, 4, 5, 6}) {
    EXPECT_GT(last_rate(rows, index), 7.9) << "index " << index;
    EXPECT_LT(last_rate(rows, index), 8.7) << "index " << index;
  }
}

TEST(EigenRates, SimplySupportedPlateConvergesLikeHToThe4) {
  const std::vector<EigenRow> rows = study_rows(R"yaml(
problem: {pde: biharmonic, boundary: {all: simply_supported}, eigen: {count: 6, exact_eigenvalues: "pi^4*(m^2 + n^2)^2"}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 3, elements: [4, 4]}
refinement: {levels: 4}
)yaml");
  // 2(p − 1) = 4 (measured 4.01 for λ₁ from 16 x 16 to 32 x 32 elements).
  for (int index : {1, 2, 4}) EXPECT_NEAR(last_rate(rows, index), 4.0, 0.1) << "index " << index;
}

TEST(EigenRates, ClampedPlateMatchesTheLiteratureValue) {
  // Bjørstad and Tjøstheim (Computing 63, 1999), spectral Legendre–Galerkin: λ₁ = 1294.9339795917.
  // Degree 6 on 16 x 16 elements: 5.6e-10 above it (a conforming space bounds λ₁ from above);
  // degree 6 on 64 x 64 elements comes within 3.1e-12 (docs/eigen.md), so the value holds to
  // about twelve digits.
  const std::vector<EigenRow> rows = study_rows(R"yaml(
problem: {pde: biharmonic, boundary: {all: clamped}, eigen: {count: 1, exact_eigenvalues: [1294.9339795917]}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 6, elements: [4, 4]}
refinement: {levels: 3}
)yaml");
  const EigenRow& finest = rows.back();
  EXPECT_LT(finest.relative_error.value(), 1e-9);
  EXPECT_GT(finest.eigenvalue, 1294.9339795917);
}

}  // namespace
}  // namespace iga
