// The exact reference edge of the note (§5.1: regular octahedron, edge (0, 2), k = 4, k̄ = 5) for
// Π0 and Π1, the paper's GCD-cofactor Algorithm 2 on the note's unit cases (§3.6), and the
// paper method's known failures (folds on the tetrahedron, blow-up on the icosphere).
#include <gtest/gtest.h>

#include <functional>
#include <sstream>

#include "geometry/builtin_surface_meshes.hpp"
#include "geometry/rsd/hermite_edge_solver.hpp"
#include "geometry/rsd/paper_edge_solver.hpp"
#include "geometry/rsd/rsd_surface.hpp"

namespace iga::rsd {
namespace {

using Q = GiNaC::numeric;
using Curve = std::function<Eigen::Vector3d(double)>;

/// Octahedron edge (0, 2): g_ij = p_j (projected chords), note §5.1.
template <class T>
EdgeEndData<T> reference_edge() {
  return {{T(1), T(0), T(0)},  {T(0), T(1), T(0)},  {T(0), T(1), T(0)},  {T(1), T(0), T(0)},
          {T(0), T(0), T(1)},  {T(0), T(0), T(1)},  {T(0), T(0), T(-1)}, {T(0), T(0), T(-1)}};
}

Eigen::Vector3d at(const VecPoly<double>& p, double t) { return {p[0](t), p[1](t), p[2](t)}; }

/// Polynomials of degree ≤ 12 agree when they agree at 21 points.
void expect_curve(const VecPoly<double>& p, const Curve& expected, double tolerance, const char* what) {
  for (int q = 0; q <= 20; ++q) {
    const double t = q / 20.0;
    EXPECT_NEAR((at(p, t) - expected(t)).norm(), 0, tolerance) << what << " at t = " << t;
  }
}

void expect_scalar(const Poly<double>& p, const std::function<double(double)>& expected, double tolerance,
                   const char* what) {
  for (int q = 0; q <= 20; ++q) {
    const double t = q / 20.0;
    EXPECT_NEAR(p(t), expected(t), tolerance) << what << " at t = " << t;
  }
}

TEST(RsdReferenceEdge, Pi0MatchesTheNote) {
  const EdgeCurves<double> e = edge_curves(RsdTuple::pi0, reference_edge<double>());
  const auto c3 = [](double t) { return (t - 1) * (t - 1) * (t - 1); };
  expect_curve(e.v, [&](double t) {
    return Eigen::Vector3d(c3(t) * (3 * t + 1) / 2, t * t * t * (3 * t - 4) / 2, -6 * t * t * t * t + 12 * t * t * t - 6 * t * t + 1);
  }, 1e-14, "v");
  expect_curve(e.vbar, [&](double t) {
    return Eigen::Vector3d(c3(t) * (3 * t + 1) / 2, t * t * t * (3 * t - 4) / 2, 6 * t * t * t * t - 12 * t * t * t + 6 * t * t - 1);
  }, 1e-14, "vbar");
  expect_curve(e.u, [](double t) {
    return Eigen::Vector3d((t - 1) * (t - 1) * (15 * t * t + 2 * t + 1), -t * t * (15 * t * t - 32 * t + 18), 0);
  }, 1e-13, "u");
  const auto r4 = [](double t) { return 6 * t * t * t * t - 12 * t * t * t + 6 * t * t - 1; };
  expect_curve(e.w(), [&](double t) {
    return Eigen::Vector3d(2 * t * t * (15 * t * t - 32 * t + 18) * r4(t),
                           2 * (t - 1) * (t - 1) * (15 * t * t + 2 * t + 1) * r4(t), 0);
  }, 1e-12, "w");
  const auto q4 = [](double t) { return 45 * t * t * t * t - 90 * t * t * t + 49 * t * t - 4 * t - 9; };
  expect_scalar(e.Delta(), [&](double t) { return 2 * t * t * (t - 1) * (t - 1) * r4(t) * q4(t); }, 1e-12, "Delta");
  const auto [delta, remainder] = divide(e.Delta(), edge_bubble<double>());
  expect_scalar(delta, [&](double t) { return 2 * r4(t) * q4(t); }, 1e-11, "delta");

  const HermiteEdgeSolution h = solve_edge_hermite(RsdTuple::pi0, reference_edge<double>());
  EXPECT_NEAR(h.X0, -0.5, 1e-15);
  EXPECT_NEAR(h.X1, 0.5, 1e-15);
  EXPECT_NEAR(h.Y0, -0.5, 1e-15);
  EXPECT_NEAR(h.Y1, -0.5, 1e-15);
  expect_scalar(h.X(), [](double t) { return -(2 * t - 1) * (2 * t * t - 2 * t - 1) / 2; }, 1e-15, "X");
  EXPECT_EQ(degree(h.z), 3);
  expect_curve(h.z, [](double t) {
    return Eigen::Vector3d(30 * t * t * t - 41 * t * t - 4 * t + 6, -30 * t * t * t + 49 * t * t - 4 * t - 9, 0);
  }, 1e-12, "z_herm");
}

TEST(RsdReferenceEdge, Pi1MatchesTheNote) {
  const EdgeCurves<double> e = edge_curves(RsdTuple::pi1, reference_edge<double>());
  const auto c3 = [](double t) { return (t - 1) * (t - 1) * (t - 1); };
  expect_curve(e.v, [&](double t) {
    return Eigen::Vector3d(c3(t) * (6 * t * t + 3 * t + 1) / 2, -t * t * t * (6 * t * t - 15 * t + 10) / 2, 1);
  }, 1e-14, "v");
  expect_curve(e.u, [&](double t) {
    return Eigen::Vector3d(-c3(t) * (36 * t * t + 3 * t + 1), -t * t * t * (36 * t * t - 75 * t + 40), 0);
  }, 1e-13, "u");
  expect_curve(e.w(), [&](double t) {
    return Eigen::Vector3d(-2 * t * t * t * (36 * t * t - 75 * t + 40), 2 * c3(t) * (36 * t * t + 3 * t + 1), 0);
  }, 1e-12, "w");
  EXPECT_EQ(degree(e.w()), 5);  // only 5 for Π1 at valence 4 with fan normals (note §3.7)
  const auto q4 = [](double t) { return 216 * t * t * t * t - 432 * t * t * t + 186 * t * t + 30 * t + 25; };
  expect_scalar(e.Delta(), [&](double t) { return -2 * t * t * t * c3(t) * q4(t); }, 1e-12, "Delta");
  const HermiteEdgeSolution h = solve_edge_hermite(RsdTuple::pi1, reference_edge<double>());
  EXPECT_NEAR(h.Y0, -0.5, 1e-15);
  EXPECT_NEAR(h.Y1, -0.5, 1e-15);
  EXPECT_EQ(degree(h.z), 4);
  expect_curve(h.z, [](double t) {
    return Eigen::Vector3d(-(t - 1) * (72 * t * t * t - 102 * t * t - 7 * t + 12),
                           -t * (72 * t * t * t - 114 * t * t + 5 * t + 25), 0);
  }, 1e-12, "z_herm");
}

/// Exact polynomial from integer coefficients (constant first) over a common denominator.
Poly<Q> qpoly(const std::vector<long>& coefficients, long denominator = 1) {
  std::vector<Q> c;
  for (long x : coefficients) c.push_back(Q(x) / Q(denominator));
  return Poly<Q>(c);
}

bool same(const Poly<Q>& a, const Poly<Q>& b) { return (a - b).is_zero(); }

std::string text(const Poly<Q>& p) {
  std::string s;
  for (const Q& x : p.c) {
    std::ostringstream o;
    o << x;
    s += o.str() + " ";
  }
  return s;
}

TEST(GcdCofactors, TheNotesUnitCases) {
  // s1 s2, s2 s3, s3 s1 with s1 = t² + 1, s2 = t² + t + 2, s3 = t² − 3t + 1 (Remark 7's family).
  auto r = gcd_cofactors({qpoly({2, 1, 3, 1, 1}), qpoly({2, -5, 0, -2, 1}), qpoly({1, -3, 2, -3, 1})});
  EXPECT_TRUE(same(r.gcd, qpoly({1}))) << text(r.gcd);
  EXPECT_EQ(r.steps, 14);
  EXPECT_TRUE(same(r.q[0], qpoly({35, -13}, 87))) << text(r.q[0]);
  EXPECT_TRUE(same(r.q[1], qpoly({-88, 29, -117}, 174))) << text(r.q[1]);
  EXPECT_TRUE(same(r.q[2], qpoly({70, 38, 39}, 58))) << text(r.q[2]);

  r = gcd_cofactors({qpoly({0, -1, 0, 1}), qpoly({0, 0, 1, 1}), qpoly({2, 3, 1})});
  EXPECT_TRUE(same(r.gcd, qpoly({1, 1})));
  EXPECT_EQ(r.steps, 5);
  EXPECT_TRUE(same(r.q[0], qpoly({1}, 2)) && same(r.q[1], qpoly({-1}, 2)) && same(r.q[2], qpoly({1}, 2)));

  r = gcd_cofactors({qpoly({0, 0, 1}), qpoly({-1, 0, 1}), qpoly({2, 1})});
  EXPECT_TRUE(same(r.gcd, qpoly({1})));
  EXPECT_EQ(r.steps, 6);
  EXPECT_TRUE(same(r.q[0], qpoly({1})) && same(r.q[1], qpoly({-1})) && r.q[2].is_zero());
}

TEST(GcdCofactors, ReferenceEdgeGcdAndCofactors) {
  const VecPoly<Q> w0 = edge_curves(RsdTuple::pi0, reference_edge<Q>()).w();
  const auto r0 = gcd_cofactors({w0[0], w0[1], w0[2]});
  // ρ = t⁴ − 2t³ + t² − 1/6: the common factor Θ(t) + Θ(1 − t) of valence 4 with fan normals.
  EXPECT_TRUE(same(r0.gcd, qpoly({-1, 0, 6, -12, 6}, 6))) << text(r0.gcd);
  EXPECT_EQ(r0.steps, 9);
  EXPECT_TRUE(same(r0.q[0], qpoly({-179, 240, 1230, -900}, 4692))) << text(r0.q[0]);
  EXPECT_TRUE(same(r0.q[1], qpoly({391, 0, -1470, 900}, 4692))) << text(r0.q[1]);
  EXPECT_TRUE(r0.q[2].is_zero());
  const VecPoly<Q> w1 = edge_curves(RsdTuple::pi1, reference_edge<Q>()).w();
  const auto r1 = gcd_cofactors({w1[0], w1[1], w1[2]});
  EXPECT_TRUE(same(r1.gcd, qpoly({1})));
  EXPECT_EQ(r1.steps, 11);
  // The paper's z solves the exact G1 equation s⟨z, w⟩ = Δ.
  for (RsdTuple tuple : {RsdTuple::pi0, RsdTuple::pi1}) {
    const EdgeCurves<Q> e = edge_curves(tuple, reference_edge<Q>());
    const VecPoly<Q> z = solve_edge_paper(tuple, reference_edge<Q>());
    EXPECT_TRUE(same(edge_bubble<Q>() * dot(z, e.w()), e.Delta()));
    EXPECT_EQ(degree(z), tuple == RsdTuple::pi0 ? 7 : 10);
  }
}

TEST(PaperMethod, DegreesOnValenceFourAndThree) {
  for (const auto& mesh : {regular_octahedron(), regular_tetrahedron()}) {
    EXPECT_EQ(build_rsd_surface(mesh, {RsdTuple::pi0, RsdMethod::paper}).report.patch_degree, 12) << mesh.source;
    EXPECT_EQ(build_rsd_surface(mesh, {RsdTuple::pi1, RsdMethod::paper}).report.patch_degree, 15) << mesh.source;
  }
}

TEST(PaperMethod, FoldsOnTheRegularTetrahedronWhereHermiteDoesNot) {
  // Note §5.2: max α = +18.4 (Π0) and +21.5 (Π1) with exact G1; Hermite gives α ≡ −1.
  const auto tet = regular_tetrahedron();
  const RsdReport p0 = build_rsd_surface(tet, {RsdTuple::pi0, RsdMethod::paper}).report;
  const RsdReport p1 = build_rsd_surface(tet, {RsdTuple::pi1, RsdMethod::paper}).report;
  EXPECT_NEAR(p0.max_fold_alpha, 18.4, 0.05);
  EXPECT_NEAR(p1.max_fold_alpha, 21.5, 0.05);
  EXPECT_LT(p0.max_g1_residual, 1e-12);
  EXPECT_LT(p1.max_g1_residual, 1e-12);
  EXPECT_NEAR(build_rsd_surface(tet, {RsdTuple::pi0, RsdMethod::hermite}).report.max_fold_alpha, -1, 1e-12);
}

TEST(PaperMethod, RegressionGuardBlowsUpOnTheLevelTwoIcosphere) {
  // Why the paper's cofactors are not used (note §5.6, §9.18): nearly reducible w on a
  // quasi-uniform mesh makes the Bézout cofactors of 1 enormous. The G1 determinant still
  // vanishes (to round-off amplified by |z|), so only |z| and α reveal it.
  const RsdReport r = build_rsd_surface(icosphere(2), {RsdTuple::pi0, RsdMethod::paper}).report;
  EXPECT_GT(r.max_z, 1e6);
  EXPECT_GT(r.max_fold_alpha, 0.0);
  EXPECT_LT(r.max_g1_residual, 1e-8);
  const RsdReport h = build_rsd_surface(icosphere(2), {RsdTuple::pi0, RsdMethod::hermite}).report;
  EXPECT_LT(h.max_z, 1.0);
  EXPECT_LT(h.max_fold_alpha, -0.99);
}

}  // namespace
}  // namespace iga::rsd
