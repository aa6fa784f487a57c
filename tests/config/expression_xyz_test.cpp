// Expressions in x, y, z (functions on surfaces in 3D) next to the planar ones.
#include <gtest/gtest.h>

#include <cmath>

#include "config/errors.hpp"
#include "config/expression.hpp"

namespace iga {
namespace {

TEST(ExpressionXyz, EvaluatesAndDifferentiatesInThreeVariables) {
  const SymbolicFunction u = SymbolicFunction::parse_xyz("x*y + sin(z) + z^2*x", "test");
  const Eigen::Vector3d p(0.3, -0.7, 1.1);
  EXPECT_NEAR(u.at(p), 0.3 * -0.7 + std::sin(1.1) + 1.21 * 0.3, 1e-15);
  EXPECT_NEAR(u.diff_z().at(p), std::cos(1.1) + 2 * 1.1 * 0.3, 1e-15);
  EXPECT_NEAR(u.diff_x().at(p), -0.7 + 1.21, 1e-15);
  EXPECT_NEAR(u.diff_z().diff_z().at(p), -std::sin(1.1) + 2 * 0.3, 1e-15);
  // A planar function has no z: ∂z is zero, and at() ignores the third coordinate.
  const SymbolicFunction f = SymbolicFunction::parse("x*y", "test");
  EXPECT_TRUE(f.diff_z().is_zero());
  EXPECT_DOUBLE_EQ(f.at(p), 0.3 * -0.7);
}

TEST(ExpressionXyz, PlanarParsingStillRejectsZ) {
  EXPECT_THROW(SymbolicFunction::parse("x + z", "test"), InputError);
  try {
    SymbolicFunction::parse_xyz("x + w", "problem.exact");
    FAIL() << "w is not a variable";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("known: x, y, z, pi"), std::string::npos) << e.what();
  }
}

TEST(ExpressionXyz, PlanarEvaluationAfterAThreeDimensionalOneIsUnchanged) {
  // The evaluators are per thread and per function: a 3D evaluation leaves planar ones alone.
  const SymbolicFunction u = SymbolicFunction::parse_xyz("z", "test");
  const SymbolicFunction f = SymbolicFunction::parse("x - y", "test");
  EXPECT_DOUBLE_EQ(u.at(Eigen::Vector3d(0, 0, 5)), 5.0);
  EXPECT_DOUBLE_EQ(f(2.0, 0.5), 1.5);
}

}  // namespace
}  // namespace iga
