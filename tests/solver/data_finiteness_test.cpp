/// check_data_finite: data that are not finite on a mesh line (where no interior quadrature point
/// lies) are an InputError naming the config key; finite data pass.
#include "solver/data_finiteness.hpp"

#include <gtest/gtest.h>

#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "spaces/space_factory.hpp"

namespace iga {
namespace {

std::string error_of(const std::string& problem_yaml) {
  const ConfigNode root = ConfigNode::load_string(
      problem_yaml + "domain: {type: rectangle, min: [0, 0], max: [1, 1]}\n"
                     "space: {type: bspline, degree: 2, elements: [2, 2]}\n",
      "run.yaml");
  const ProblemSpec problem = parse_problem(root["problem"]);
  const SpacePtr space = make_space(root["domain"], root["space"], 0);
  try {
    check_data_finite(*space, problem);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(DataFiniteness, PoleOnAMeshLineIsFoundAtAVertex) {
  // x = 0.5 is a mesh line of the 2 x 2 grid: no Gauss point of the interior lies on it.
  const std::string m = error_of("problem: {pde: poisson, exact: \"1/(x-0.5)\", boundary: {all: dirichlet}}\n");
  EXPECT_EQ(m.rfind("run.yaml:1:32: problem.exact: the exact solution is not finite at (0.5, 0), a vertex", 0), 0u) << m;
}

TEST(DataFiniteness, InfiniteDerivativeOnAMeshLine) {
  const std::string m = error_of("problem: {pde: poisson, exact: \"sqrt(abs(x-0.5))\", boundary: {all: dirichlet}}\n");
  EXPECT_NE(m.find("problem.exact: the x-derivative of the exact solution is not finite"), std::string::npos) << m;
}

TEST(DataFiniteness, IntegrablePointSingularityAtAVertexIsAccepted) {
  // The re-entrant corner solution r^(2/3) sin(2θ/3) of an L-shape: ∇u is infinite at the corner
  // vertex (0, 0) only, which no integral sees. Here (0, 0) is a corner of the square.
  EXPECT_EQ(error_of("problem: {pde: poisson, exact: \"(x^2+y^2)^(1/3)*sin(2/3*atan2(y, x))\", "
                     "boundary: {all: dirichlet}}\n"),
            "");
}

TEST(DataFiniteness, SourceAndBoundaryDataNameTheirKeys) {
  std::string m = error_of("problem: {pde: poisson, source: \"log(y-0.5)\", boundary: {all: dirichlet}}\n");
  EXPECT_NE(m.find("problem.source: the source term is not finite"), std::string::npos) << m;
  // Boundary data are checked on the boundary only: 1/(x-0.5) is not finite at (0.5, 0).
  m = error_of("problem: {pde: poisson, source: \"1\", boundary: {all: dirichlet}, data: {u: \"1/(x-0.5)\"}}\n");
  EXPECT_NE(m.find("problem.data: the boundary value u is not finite at (0.5, "), std::string::npos) << m;
  // Not finite only inside the domain, away from the boundary: fine for boundary data.
  EXPECT_EQ(error_of("problem: {pde: poisson, source: \"1\", boundary: {all: dirichlet}, "
                     "data: {u: \"1/((x-0.5)^2+(y-0.5)^2)\"}}\n"),
            "");
  EXPECT_EQ(error_of("problem: {pde: poisson, exact: \"x*y + sin(x)\", boundary: {all: dirichlet}}\n"), "");
}

}  // namespace
}  // namespace iga
