// The 4-split G1 space through the Space interface and the generic solver: config handling and its
// refusals, C1 basis functions after the isoparametric map, reproduction of x and y, the certified
// geometry check, nested levels keeping the coarse map, and optimal plate rates on the 2x2 grid.
#include <gtest/gtest.h>

#include <Eigen/SparseQR>
#include <cmath>

#include "config/errors.hpp"
#include "solver/solve_problem.hpp"
#include "spaces/g1_4split/face_function.hpp"
#include "spaces/g1_4split/g1_4split_meshes.hpp"
#include "spaces/g1_4split/g1_4split_space.hpp"
#include "tests/support/input_error.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {

std::string yaml(const std::string& problem, const std::string& domain, const std::string& space) {
  return "problem: " + problem + "\ndomain: {type: multipatch, name: " + domain + "}\nspace: {type: g1_4split, " + space +
         "}\n";
}

std::string error_of(const std::string& text, int level) {
  return test::input_error([&] { test::space_from_yaml(text, level); });
}

}  // namespace

TEST(G14Space, ConfigBuildsAndRefusesWithReasons) {
  const SpacePtr s = test::space_from_yaml(yaml("{pde: poisson}", "fan5", "degree: 5, blending: q1"), 1);
  EXPECT_EQ(s->type(), "g1_4split");
  EXPECT_EQ(s->num_elements(), 20);
  EXPECT_EQ(s->dimension(), 1408);  // notes §11, pentagon level 1 (q1)
  EXPECT_EQ(s->continuity(), 1);
  // The default (lines) is linear on every sub-edge: degree 4 stays separable where q1 is not.
  EXPECT_EQ(test::space_from_yaml(yaml("{pde: poisson}", "fan3", "degree: 4"), 1)->type(), "g1_4split");
  const std::string below = error_of(yaml("{pde: poisson}", "fan3", "degree: 4, blending: q1"), 1);
  EXPECT_NE(below.find("space.degree"), std::string::npos) << below;
  EXPECT_NE(below.find("smallest degree that works is 5"), std::string::npos) << below;
  const std::string q0 = error_of(yaml("{pde: poisson}", "fan3", "degree: 4, blending: q0"), 0);
  EXPECT_NE(q0.find("space.blending"), std::string::npos) << q0;
  EXPECT_NE(q0.find("singular"), std::string::npos) << q0;
  const std::string tri = error_of(yaml("{pde: poisson}", "2q2t_square", "degree: 5"), 0);
  EXPECT_NE(tri.find("triangle"), std::string::npos) << tri;
  EXPECT_NE(tri.find("g1 space"), std::string::npos) << tri;
}

TEST(G14Space, BasisFunctionsAreC1AfterTheMap) {
  struct Case {
    const char* domain;
    int k, level;
  };
  for (const Case c : {Case{"fan3", 4, 0}, Case{"fan6", 4, 0}, Case{"halffan3", 4, 0}, Case{"fan5", 5, 1}}) {
    G14Options o;
    o.degree = c.k;
    o.level = c.level;
    const G14Space s(g14_domain(c.domain), o);
    double worst = 0.0;
    const int stride = c.level == 0 ? 1 : 11;  // every function on the coarse meshes, a sample on the fine one
    for (int i = 0; i < s.dimension(); i += stride) {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(s.dimension());
      e(i) = 1.0;
      worst = std::max(worst, *s.max_gradient_jump(e));
    }
    EXPECT_LT(worst, 1e-10) << c.domain;
  }
}

TEST(G14Space, GeometryIsInTheSpaceRegularAndKeptByNestedRefinement) {
  for (const char* d : {"fan3", "fan5", "fan6", "halffan3", "grid2x2"}) {
    G14Options o;
    o.degree = 5;
    const G14Space s(g14_domain(d), o);
    const G14Basis& b = s.basis();
    // x and y are combinations of basis functions (least squares residual at round-off).
    Eigen::SparseQR<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> qr(b.functions);
    for (int comp = 0; comp < 2; ++comp) {
      Eigen::VectorXd g(b.functions.rows());
      const int fs = b.bspline.face_size();
      for (int f = 0; f < s.num_elements(); ++f) g.segment(f * fs, fs) = comp ? s.geometry().y[f] : s.geometry().x[f];
      const Eigen::VectorXd c = qr.solve(g);
      EXPECT_LT((b.functions * c - g).norm(), 1e-11 * g.norm()) << d;
    }
    for (int f = 0; f < s.num_elements(); ++f)
      EXPECT_GT(certified_jacobian_bound(b.bspline, s.geometry().x[f], s.geometry().y[f]), 1e-2) << d << f;
  }
  // Nested: the level-1 map is the level-0 map (child c of face f covers the quarter at corner c).
  G14Options o;
  o.degree = 5;
  const G14Space coarse(g14_domain("fan5"), o);
  o.level = 1;
  const G14Space fine(g14_domain("fan5"), o);
  const SplitBSpline& b = coarse.basis().bspline;
  double worst = 0.0;
  for (int f = 0; f < coarse.num_elements(); ++f)
    for (double u : {0.1, 0.3, 0.45})
      for (double v : {0.05, 0.25, 0.4}) {
        const Point2 uv(u, v);  // child 0 covers [0, 1/2]^2
        worst = std::max(worst, std::abs(face_jet(b, coarse.geometry().x[f], uv)(0) -
                                         face_jet(b, fine.geometry().x[4 * f], 2 * uv)(0)));
        worst = std::max(worst, std::abs(face_jet(b, coarse.geometry().y[f], uv)(0) -
                                         face_jet(b, fine.geometry().y[4 * f], 2 * uv)(0)));
      }
  EXPECT_LT(worst, 1e-13);
}

TEST(G14Space, PaperBlendingQ0GivesASingularGeometry) {
  G14Options o;
  o.degree = 4;
  o.blending = Blending::q0;
  EXPECT_THROW(G14Space(g14_domain("fan3"), o), InputError);
}

TEST(G14Space, LinearFunctionsAreReproducedIsoparametrically) {
  const SpacePtr s = test::space_from_yaml(yaml("{pde: poisson}", "fan5", "degree: 5"), 1);
  const LevelResult r = solve_problem(*s,
                                      test::problem_from_yaml(yaml("{pde: poisson, exact: \"1 + 2*x - 3*y\", boundary: "
                                                                   "{all: dirichlet}}",
                                                                   "fan5", "degree: 5")),
                                      SolverKind::cholmod)
                            .result;
  EXPECT_LT(*r.l2, 1e-11);
  EXPECT_LT(*r.h1, 1e-10);
  ASSERT_TRUE(r.g1_jump.has_value());
  EXPECT_LT(*r.g1_jump, 1e-10);
}

TEST(G14Space, ClampedPlateOptimalRatesOnTheRegularGrid) {
  const test::Rates r = test::last_rates(
      yaml("{pde: biharmonic, exact: \"sin(2*x+0.3)*cos(3*y)\", boundary: {all: clamped}}", "grid2x2", "degree: 4"), 3);
  EXPECT_GT(r.l2, 4.8);
  EXPECT_GT(r.h1, 3.8);
  EXPECT_GT(r.h2, 2.9);
}

TEST(G14Space, NestedQuinticPlateOnTheValence5Pentagon) {
  // Notes §11/§12.14: L2 about h^5, H2 about h^3.6 (optimal 6 / 4): along the coarse edges whose
  // q1 gluing is quadratic the traces lose one degree, in a layer of width h.
  const test::Rates r = test::last_rates(
      yaml("{pde: biharmonic, exact: \"sin(2*x+0.3)*cos(3*y)\", boundary: {all: clamped}}", "fan5", "degree: 5"), 3);
  EXPECT_GT(r.l2, 5.0);
  EXPECT_GT(r.h1, 4.2);
  EXPECT_GT(r.h2, 3.4);
}
