// B-splines on exact NURBS patches in 3D (spaces/surface_patch/): dimensions from the knot
// counting formula, the exact geometry (points on the surface and the curvature of the map's
// second-order jets against the closed forms of torus, sphere and cylinder), C1 normals and
// functions across the periodic seams, the G+Smo XML roof equal to the built-in sector, and the
// rates of the surface biharmonic on a closed torus and on a clamped cylinder sector.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "config/errors.hpp"
#include "spaces/lifted_space.hpp"
#include "tests/support/check_space.hpp"
#include "tests/support/scratch_files.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

/// Functions of one direction: `joints` breakpoints of the map (C1 arcs: multiplicity p − min(r, 1))
/// among `elements` (the others p − r); periodic: one per knot of a period; open: p + 1 more.
int functions(int p, int r, int elements, int joints, bool periodic) {
  const int knots = joints * (p - std::min(r, 1)) + (elements - joints) * (p - r);
  return periodic ? knots : knots - (p - r) + p + 1;
}

TEST(SurfacePatch, DimensionsFollowTheKnotCount) {
  // Torus: 4 quarter arcs in each direction, both periodic (the seam is a joint too).
  for (int p : {2, 3, 4})
    for (int level : {0, 1}) {
      const SpacePtr s = test::space_from_yaml(
          "domain: {type: surface_patch, shape: torus}\nspace: {type: bspline, degree: " + std::to_string(p) +
              ", elements: [8, 4]}\n",
          level);
      const int nu = functions(p, p - 1, 8 << level, 4, true), nv = functions(p, p - 1, 4 << level, 4, true);
      EXPECT_EQ(s->dimension(), nu * nv) << "p " << p << " level " << level;
      EXPECT_EQ(s->num_elements(), (8 << level) * (4 << level));
      EXPECT_EQ(s->continuity(), 1);  // C1 at the arcs' joints
      EXPECT_TRUE(s->boundary_edges("all").empty());
    }
  // Scordelis–Lo sector: one arc (no joint), open in both directions: (p + n) per direction.
  const SpacePtr sector = test::space_from_yaml(
      "domain: {type: surface_patch, shape: cylinder, radius: 25, length: 50, half_angle: 40}\n"
      "space: {type: bspline, degree: 4, regularity: 2, elements: [3, 2]}\n");
  EXPECT_EQ(sector->dimension(), functions(4, 2, 3, 0, false) * functions(4, 2, 2, 0, false));
  EXPECT_EQ(sector->dimension(), (5 + 2 * 2) * (5 + 1 * 2));
  EXPECT_EQ(sector->continuity(), 2);
  EXPECT_EQ(sector->boundary_edges("all").size(), 2u * (3 + 2));
  EXPECT_NE(dynamic_cast<const LiftedSpace*>(sector.get()), nullptr);
}

/// Largest deviation of the points from the implicit surface and of |H| from the exact mean
/// curvature, at the Gauss points of every element.
template <class Implicit, class Curvature>
void expect_exact_geometry(const std::string& domain, Implicit implicit, Curvature curvature, double scale) {
  SCOPED_TRACE(domain);
  const SpacePtr s = test::space_from_yaml("domain: " + domain + "\nspace: {type: bspline, degree: 3}\n", 1);
  auto ev = s->make_evaluator();
  PointValues pv;
  double worst_x = 0, worst_h = 0;
  for (int e = 0; e < s->num_elements(); ++e) {
    const RulePtr rule = s->quadrature(e, 6);
    ev->evaluate(e, *rule, update_values | update_surface_curvature, pv);
    for (int q = 0; q < rule->size(); ++q) {
      const Eigen::Vector3d x = pv.x3.col(q);
      worst_x = std::max(worst_x, std::abs(implicit(x)));
      worst_h = std::max(worst_h, std::abs(std::abs(pv.mean_curvature(q)) - std::abs(curvature(x))) * scale);
    }
  }
  std::printf("%s: |implicit| %.1e, |H - H_exact| R %.1e\n", domain.c_str(), worst_x, worst_h);
  EXPECT_LT(worst_x, 1e-13 * scale);
  EXPECT_LT(worst_h, 1e-12);  // second derivatives by the quotient rule, no differences
}

TEST(SurfacePatch, GeometryIsExactToSecondOrder) {
  const double R = 2.0, r = 0.5;
  expect_exact_geometry(
      "{type: surface_patch, shape: torus, major_radius: 2, minor_radius: 0.5}",
      [&](const Eigen::Vector3d& x) { return std::hypot(std::hypot(x.x(), x.y()) - R, x.z()) - r; },
      [&](const Eigen::Vector3d& x) {
        const double rho = std::hypot(x.x(), x.y());
        return 1.0 / r + (rho - R) / r / rho;  // κ1 = 1/r, κ2 = cos φ / ρ
      },
      R);
  expect_exact_geometry(
      "{type: surface_patch, shape: sphere, radius: 3, hole: 18}",
      [](const Eigen::Vector3d& x) { return x.norm() - 3.0; }, [](const Eigen::Vector3d&) { return 2.0 / 3.0; }, 3.0);
  expect_exact_geometry(
      "{type: surface_patch, shape: cylinder, radius: 25, length: 50, half_angle: 40}",
      [](const Eigen::Vector3d& x) { return std::hypot(x.y(), x.z()) - 25.0; },
      [](const Eigen::Vector3d&) { return 1.0 / 25.0; }, 25.0);
  expect_exact_geometry(
      "{type: surface_patch, shape: cylinder, radius: 1, length: 3}",
      [](const Eigen::Vector3d& x) { return std::hypot(x.y(), x.z()) - 1.0; },
      [](const Eigen::Vector3d&) { return 1.0; }, 1.0);
}

/// Across every shared edge (periodic seams and arc joints included): points, normals and the
/// surface gradient of a random function agree from both sides at round-off.
TEST(SurfacePatch, NormalsAndFunctionsAreContinuousAcrossSeams) {
  for (const std::string domain : {"{type: surface_patch, shape: torus}", "{type: surface_patch, shape: cylinder}",
                                   "{type: surface_patch, shape: sphere, hole: 30}"}) {
    SCOPED_TRACE(domain);
    const SpacePtr s = test::space_from_yaml("domain: " + domain + "\nspace: {type: bspline, degree: 3}\n", 1);
    const Eigen::VectorXd c = test::random_vector(s->dimension(), 7);
    auto ev = s->make_evaluator();
    PointValues ga, gb;
    FunctionValues fa, fb;
    double dx = 0, dn = 0, du = 0, dg = 0;
    int seams = 0;
    const unsigned flags = update_values | update_gradients | update_surface_curvature;
    for (const InteriorEdge& edge : s->interior_edges()) {
      QuadratureRule ra, rb;
      for (double t : {0.1, 0.5, 0.87}) {
        ra.points.push_back(reference_edge_point(CellShape::quadrilateral, edge.edge_a, edge.a0 + t * (edge.a1 - edge.a0)));
        rb.points.push_back(reference_edge_point(CellShape::quadrilateral, edge.edge_b, edge.b0 + t * (edge.b1 - edge.b0)));
        ra.weights.push_back(1.0);
        rb.weights.push_back(1.0);
      }
      ev->evaluate_function(edge.element_a, ra, c, flags, ga, fa);
      ev->evaluate_function(edge.element_b, rb, c, flags, gb, fb);
      ev->evaluate(edge.element_a, ra, update_surface_curvature, ga);
      ev->evaluate(edge.element_b, rb, update_surface_curvature, gb);
      const bool seam = std::abs(edge.element_a - edge.element_b) > 1 && edge.edge_a == 1;
      seams += seam || (edge.edge_a == 2 && edge.element_b < edge.element_a);
      dx = std::max(dx, (ga.x3 - gb.x3).cwiseAbs().maxCoeff());
      dn = std::max(dn, (ga.normal3 - gb.normal3).cwiseAbs().maxCoeff());
      du = std::max(du, (fa.value - fb.value).cwiseAbs().maxCoeff());
      dg = std::max({dg, (fa.dx - fb.dx).cwiseAbs().maxCoeff(), (fa.dy - fb.dy).cwiseAbs().maxCoeff(),
                     (fa.dz - fb.dz).cwiseAbs().maxCoeff()});
    }
    std::printf("%s: %d seam edges, jumps x %.1e n %.1e u %.1e grad u %.1e\n", domain.c_str(), seams, dx, dn, du, dg);
    EXPECT_GT(seams, 0);
    EXPECT_LT(dx, 1e-13);
    EXPECT_LT(dn, 1e-13);
    EXPECT_LT(du, 1e-13);
    EXPECT_LT(dg, 1e-11);  // coefficients of size 1 over elements of size ~0.3
  }
}

TEST(SurfacePatch, XmlRoofIsTheBuiltInSector) {
  const std::string file = std::string(IGA_SOURCE_DIR) + "/configs/domains/scordelis-lo-roof.xml";
  const SpacePtr a = test::space_from_yaml(
      "domain: {type: surface_patch, file: \"" + file + "\"}\nspace: {type: bspline, degree: 3, elements: [4, 2]}\n");
  const SpacePtr b = test::space_from_yaml(
      "domain: {type: surface_patch, shape: cylinder, radius: 25, length: 50, half_angle: 40}\n"
      "space: {type: bspline, degree: 3, elements: [4, 2]}\n");
  ASSERT_EQ(a->dimension(), b->dimension());
  auto ea = a->make_evaluator(), eb = b->make_evaluator();
  PointValues pa, pb;
  double worst = 0;
  for (int e = 0; e < a->num_elements(); ++e) {
    const RulePtr rule = a->quadrature(e, 4);
    ea->evaluate(e, *rule, update_hessians | update_surface_curvature, pa);
    eb->evaluate(e, *rule, update_hessians | update_surface_curvature, pb);
    worst = std::max({worst, (pa.x3 - pb.x3).cwiseAbs().maxCoeff() / 25.0, (pa.dxx - pb.dxx).cwiseAbs().maxCoeff(),
                      (pa.mean_curvature - pb.mean_curvature).cwiseAbs().maxCoeff()});
  }
  EXPECT_LT(worst, 1e-14);  // the file's 17 digits
}

/// A closed unit cylinder about the z axis, 0 ≤ z ≤ 1, as a G+Smo file: the circle of four quarter
/// arcs (9 control points, the first repeated last, weights 1, 1/√2, …) in u, a segment in v.
std::string closed_cylinder_xml() {
  const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, cy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  std::string coefs, weights;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 9; ++i) {
      coefs += std::to_string(cx[i]) + " " + std::to_string(cy[i]) + " " + std::to_string(j) + "\n";
      weights += (i % 2 ? "0.70710678118654752 " : "1 ");
    }
  return "<xml><Geometry type=\"TensorNurbs2\" id=\"0\"><Basis type=\"TensorNurbsBasis2\">"
         "<Basis type=\"TensorBSplineBasis2\">"
         "<Basis type=\"BSplineBasis\" index=\"0\"><KnotVector degree=\"2\">0 0 0 1 1 2 2 3 3 4 4 4</KnotVector></Basis>"
         "<Basis type=\"BSplineBasis\" index=\"1\"><KnotVector degree=\"1\">0 0 1 1</KnotVector></Basis>"
         "</Basis><weights>" + weights + "</weights></Basis><coefs geoDim=\"3\">" + coefs + "</coefs></Geometry></xml>\n";
}

TEST(SurfacePatch, PeriodicFilePatchClosesC1) {
  const std::filesystem::path file = test::scratch_file("closed_cylinder.xml", closed_cylinder_xml());
  const std::string domain = "{type: surface_patch, file: \"" + file.string() + "\", periodic: u}";
  const SpacePtr s = test::space_from_yaml("domain: " + domain + "\nspace: {type: bspline, degree: 3, elements: [8, 2]}\n");
  // u: the seam and three more arc joints at C1 (2 knots each) and 4 simple knots; v open: p + 2.
  EXPECT_EQ(s->dimension(), (4 * 2 + 4) * (3 + 2));
  EXPECT_EQ(s->continuity(), 1);  // the file's double knots are C0 by multiplicity, C1 as measured
  EXPECT_EQ(s->boundary_edges("all").size(), 2u * 8);  // the two rims only
  const test::SpaceCheck r = test::check_space(*s, 1, 1e-3);
  EXPECT_EQ(r.edges_checked, 2 * 8 + 8);  // 8 per row along u (the seam included), 8 across v
  EXPECT_LT(r.partition_of_unity, 1e-14);
  EXPECT_LT(r.value_jump, 1e-12);
  EXPECT_LT(r.gradient_jump, 1e-12);
  // Declared periodic in v, where it does not close: refused.
  try {
    test::space_from_yaml("domain: {type: surface_patch, file: \"" + file.string() +
                          "\", periodic: both}\nspace: {type: bspline, degree: 3}\n");
    ADD_FAILURE() << "a patch that does not close in v was accepted as periodic";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("does not close"), std::string::npos) << e.what();
  }
}

// Expected p + 1 / p / p − 1 for the C1 cubic spaces (exact geometry: nothing geometric limits them).
TEST(SurfacePatch, BiharmonicRatesOnTheClosedTorus) {
  const test::Rates r = test::last_rates(
      "problem: {pde: surface_biharmonic, exact: \"x*y + sin(z) + x\", reaction: 1}\n"
      "domain: {type: surface_patch, shape: torus, major_radius: 2, minor_radius: 1}\n"
      "space: {type: bspline, degree: 3, elements: [8, 4]}\n",
      4);
  std::printf("torus rates L2 %.2f H1 %.2f H2 %.2f\n", r.l2, r.h1, r.h2);
  // Levels 2 → 3 are still coming down to 4 / 3 / 2 (4.54 / 3.46 / 2.18; level 4: 4.13 / 3.11 / 2.05).
  EXPECT_GT(r.l2, 3.7);
  EXPECT_GT(r.h1, 2.7);
  EXPECT_NEAR(r.h2, 2.0, 0.3);
}

TEST(SurfacePatch, BiharmonicRatesOnTheClampedCylinderSector) {
  const test::Rates r = test::last_rates(
      "problem: {pde: surface_biharmonic, exact: \"sin(x/4)*cos(y/5) + z*z/100\", reaction: 1}\n"
      "domain: {type: surface_patch, shape: cylinder, radius: 25, length: 50, half_angle: 40}\n"
      "space: {type: bspline, degree: 3, elements: [2, 2]}\n",
      5);
  std::printf("cylinder sector rates L2 %.2f H1 %.2f H2 %.2f\n", r.l2, r.h1, r.h2);
  test::expect_rates(r, 4.0, 3.0, 2.0);
}

}  // namespace
}  // namespace iga
