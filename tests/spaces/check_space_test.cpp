// check_space (tests/support/check_space.hpp) on every space and every built-in domain family,
// planar and surface: derivatives against central differences with steps h = 1e-3 and h/2, whose
// errors must shrink by the factor 4 of an O(h²) truncation (0.3 allowed) down to the round-off
// floor ε/h² ≈ 1e-10 (1e-9 allowed); a wrong derivative leaves an error that does not shrink.
// Jumps across interior edges up to the declared continuity at round-off (1e-9 relative: the
// extractions come from solves), partition of unity where the basis has it (Bernstein and
// B-spline bases), quadrature exact on monomials up to degree 2p, evaluate_function equal to the
// contraction of evaluate (values, gradients, Hessians; surfaces included) to round-off, and an
// evaluator specialisation (B-spline sum factorization) equal to the generic evaluator on the
// space's explicit core (tables → C_e → push-forward) to round-off: the same sums in another order.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "spaces/g1/multipatch_domains.hpp"
#include "spaces/g1_4split/g1_4split_meshes.hpp"
#include "tests/support/check_space.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

struct Case {
  std::string domain, space;
  int level = 0;
  bool partition_of_unity = false;
};

std::vector<Case> all_cases() {
  std::vector<Case> cases = {
      {"{type: rectangle, min: [0, 0], max: [2, 1]}", "{type: bspline, degree: 3, regularity: 2, elements: [3, 2]}", 0, true},
      {"{type: quarter_annulus, inner: 1, outer: 2}", "{type: bspline, degree: 4, elements: [2, 2]}", 0, true},
      {"{type: rectangle, min: [0, 0], max: [3, 2]}", "{type: tmesh, section: poly, n: 3}", 1},
      {"{type: l_shape, min: [-1, -1], max: [1, 1]}", "{type: tmesh, section: poly, n: 3}", 1},
      {"{type: rectangle, min: [0, 0], max: [2, 2]}", "{type: tmesh, section: trig, n: 3}", 1},
      {"{type: rectangle, min: [0, 0], max: [3, 2]}", "{type: tmesh, section: trig, n: 3, elements: [3, 2]}", 1},
      {"{type: rectangle, min: [0, 0], max: [3.141592653589793, 3.141592653589793]}",
       "{type: tmesh, section: trig, n: 3, regularity: 1, frequency: 1, elements: [2, 2], "
       "refine: [[0, 0, 0.5, 0.5], [0.25, 0.25, 0.5, 0.5]]}", 1},
      {"{type: rectangle, min: [0, 0], max: [2, 2]}", "{type: tmesh, section: hyperbolic, n: 3}", 1},
      {"{type: unit_square}", "{type: ws4, elements: 2}"},
      {"{type: unit_square, jitter: 0.15, seed: 3}", "{type: ws4, elements: 2}"},
      {"{type: l_shape}", "{type: ws4, elements: 2}"},
      {"{type: polygon, vertices: [[0, 0], [2, 0], [2.5, 1.2], [1, 2], [-0.3, 1]], mesh_size: 0.8}",
       "{type: ws4}"},
  };
  for (const std::string& name : multipatch_domain_names())
    cases.push_back({"{type: multipatch, name: " + name + "}", "{type: g1, degree: 5}", 0, false});
  for (const std::string& name : g14_domain_names())
    cases.push_back({"{type: multipatch, name: " + name + "}", "{type: g1_4split, degree: 5}", 0, false});
  for (const std::string& mesh : {"cube", "split_tetrahedron"})
    cases.push_back({std::string("{type: surface, mesh: ") + mesh + "}", "{type: g1_4split, degree: 5}", 0, false});
  // B-splines on exact NURBS patches in 3D: closed (periodic seams among the interior edges) and open.
  for (const std::string& patch : {"shape: torus", "shape: cylinder", "shape: cylinder, radius: 25, length: 50, half_angle: 40",
                                   "shape: sphere, hole: 18", "shape: sphere, hole: 30, sweep: 90"})
    cases.push_back({"{type: surface_patch, " + patch + "}", "{type: bspline, degree: 3}", 1, true});
  for (const std::string& mesh : {"icosphere, level: 0", "octahedron", "tetrahedron", "perturbed_octahedron", "height_field"})
    cases.push_back({"{type: surface, mesh: " + mesh + "}", "{type: surface, degree: 3}", 1, true});
  return cases;
}

TEST(CheckSpace, EverySpaceOnEveryBuiltInFamily) {
  for (const Case& c : all_cases()) {
    SCOPED_TRACE(c.space + " on " + c.domain);
    const SpacePtr space = test::space_from_yaml("domain: " + c.domain + "\nspace: " + c.space + "\n", c.level);
    const int stride = std::max(1, space->num_elements() / 24);
    const test::SpaceCheck r = test::check_space(*space, stride, 1e-3);
    std::printf("%-10s %-44.44s pou %.0e grad %.1e/%.1e hess %.1e/%.1e jumps %.0e %.0e (%d edges, C%d) quad %.0e fv %.0e ve %.0e\n",
                space->type().c_str(), c.domain.c_str(), r.partition_of_unity, r.gradient_fd, r.gradient_fd_half,
                r.hessian_fd, r.hessian_fd_half, r.value_jump, r.gradient_jump, r.edges_checked,
                space->continuity(), r.quadrature, r.function_values, r.evaluator_vs_extraction);
    if (c.partition_of_unity) EXPECT_LT(r.partition_of_unity, 1e-12);
    EXPECT_LT(r.gradient_fd_half, 0.3 * r.gradient_fd + 1e-9);
    EXPECT_LT(r.hessian_fd_half, 0.3 * r.hessian_fd + 1e-9);
    EXPECT_LT(r.hessian_fd, 1e-3);  // h² times third derivatives of size 1/h_e³ on the coarse elements
    EXPECT_LT(r.quadrature, 1e-13);
    EXPECT_LT(r.function_values, 1e-13);  // the same sums in another order
    // Planar spaces with a fast kernel: it was compared (bspline on a surface_patch is generic).
    for (const char* fast : {"bspline", "tmesh", "ws4"})
      if (space->type() == fast && space->ambient_dimension() == 2) EXPECT_GE(r.evaluator_vs_extraction, 0.0);
    EXPECT_LT(r.evaluator_vs_extraction, 1e-13);
    if (space->continuity() >= 0) EXPECT_LT(r.value_jump, 1e-9);
    if (space->continuity() >= 1) EXPECT_LT(r.gradient_jump, 1e-9);
  }
}

}  // namespace
}  // namespace iga

namespace iga {
namespace {

// Found by check_space: the sections' Bernstein bases were keyed by (section, lattice length),
// so on cells that are not square the x basis served the y side too. Trigonometric and hyperbolic
// sections depend on the physical length (polynomial ones do not), and their basis functions
// jumped by ~0.1 across interior edges of (3 × 2) / 2 elements (1.5 × 1 cells, refined once).
TEST(CheckSpace, TMeshNonPolynomialSectionsOnNonSquareCellsAreContinuous) {
  for (const std::string section : {"trig", "hyperbolic"}) {
    SCOPED_TRACE(section);
    const SpacePtr space = test::space_from_yaml("domain: {type: rectangle, min: [0, 0], max: [3, 2]}\n"
                                                 "space: {type: tmesh, section: " + section + ", n: 3}\n",
                                                 1);
    const test::SpaceCheck r = test::check_space(*space, 1, 1e-3);
    EXPECT_LT(r.value_jump, 1e-9);
    EXPECT_LT(r.gradient_jump, 1e-9);
  }
}

}  // namespace
}  // namespace iga
