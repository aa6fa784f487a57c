#pragma once
/// @file
/// Checks shared by the tests of spaces built on some of their elements (BuildsOnElements): a
/// skeleton answers everything but the per-element data, and a space built on some elements
/// evaluates them bit for bit as the whole space does and refuses the others.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "spaces/builds_on_elements.hpp"

namespace iga::test {

/// u_h = Σ c_i N_i of the element's active functions (`local`, element_dofs order) with first and
/// second derivatives at the element's rule of degree `degree`.
inline FunctionValues element_function(const Space& space, int element, const Eigen::VectorXd& local, int degree) {
  const std::unique_ptr<Space::Evaluator> ev = space.make_evaluator();
  PointValues geometry;
  FunctionValues out;
  ev->evaluate_element_function(element, *space.quadrature(element, degree), local,
                                update_values | update_gradients | update_hessians, geometry, out);
  return out;
}

/// `skeleton` built on no element: the whole space's active functions and geometry (what the
/// partition's element centres and the mesh outlines read) on every element; functions refused.
inline void expect_skeleton_of(const Space& skeleton, const Space& whole) {
  const auto& builds = dynamic_cast<const BuildsOnElements&>(skeleton);
  ASSERT_EQ(skeleton.num_elements(), whole.num_elements());
  EXPECT_EQ(skeleton.dimension(), whole.dimension());
  const std::unique_ptr<Space::Evaluator> a = skeleton.make_evaluator(), b = whole.make_evaluator();
  std::vector<int> dofs_a, dofs_b;
  for (int e = 0; e < skeleton.num_elements(); ++e) {
    EXPECT_FALSE(builds.built_on(e)) << e;
    skeleton.element_dofs(e, dofs_a);
    whole.element_dofs(e, dofs_b);
    EXPECT_EQ(dofs_a, dofs_b) << e;
    PointValues ga, gb;
    a->evaluate_geometry(e, *skeleton.quadrature(e, 1), ga);
    b->evaluate_geometry(e, *whole.quadrature(e, 1), gb);
    EXPECT_EQ(ga.x, gb.x) << e;
    EXPECT_EQ(ga.jacobian, gb.jacobian) << e;
  }
  PointValues values;
  EXPECT_THROW(a->evaluate(0, *skeleton.quadrature(0, 1), update_values, values), std::logic_error);
}

/// `built` (a space built on `elements`, increasing) evaluates u_h of fixed coefficients with its
/// derivatives bit for bit as `whole` on those elements, at the rule of degree `degree`, and
/// refuses every other element with std::logic_error.
inline void expect_built_as_whole(const Space& built, const Space& whole, const std::vector<int>& elements, int degree) {
  const auto& builds = dynamic_cast<const BuildsOnElements&>(built);
  ASSERT_EQ(built.num_elements(), whole.num_elements());
  EXPECT_EQ(built.dimension(), whole.dimension());
  std::vector<int> dofs;
  for (int e = 0; e < built.num_elements(); ++e) {
    const bool in = std::binary_search(elements.begin(), elements.end(), e);
    EXPECT_EQ(builds.built_on(e), in) << e;
    built.element_dofs(e, dofs);
    Eigen::VectorXd local(static_cast<Eigen::Index>(dofs.size()));
    for (Eigen::Index m = 0; m < local.size(); ++m) local(m) = std::cos(0.3 + static_cast<double>(m));
    if (!in) {
      EXPECT_THROW(element_function(built, e, local, degree), std::logic_error) << e;
      continue;
    }
    const FunctionValues u = element_function(built, e, local, degree), v = element_function(whole, e, local, degree);
    EXPECT_EQ(u.value, v.value) << e;
    EXPECT_EQ(u.dx, v.dx) << e;
    EXPECT_EQ(u.dy, v.dy) << e;
    EXPECT_EQ(u.dxx, v.dxx) << e;
    EXPECT_EQ(u.dxy, v.dxy) << e;
    EXPECT_EQ(u.dyy, v.dyy) << e;
  }
}

}  // namespace iga::test
