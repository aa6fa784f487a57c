// The linear RSD interpolant of one triangle (note §2.5, §3.1–3.2, tests §9.1–9.4): shape
// functions, partition of unity, linear precision (Π1 yes, Π0 no, with the note's residuals),
// and the RSD identities (24)/(25) that make the per-edge correction local.
#include <gtest/gtest.h>

#include <random>

#include "geometry/rsd/edge_curves.hpp"
#include "geometry/rsd/rsd_patch.hpp"

namespace iga::rsd {
namespace {

const std::vector<double> samples = {0.0, 0.1, 0.25, 0.3, 0.5, 0.7, 0.75, 0.9, 1.0};

TEST(RsdShapeFunctions, Identities) {
  const Poly<double> Phi = phi<double>(), Theta = theta<double>();
  for (double t : samples) {
    const double s = t * t * (1 - t) * (1 - t);
    EXPECT_NEAR(Phi(t) + Phi(1 - t), 1.0, 1e-15);
    EXPECT_NEAR(Phi.derivative()(t), 30 * s, 1e-14);
    EXPECT_NEAR(Theta.derivative()(t) * (1 - t), 12 * s, 1e-14);
    EXPECT_NEAR(Theta(t) + Theta(1 - t), 1 - 6 * s, 1e-15);
  }
  EXPECT_EQ(Theta(0.5) + Theta(0.5), 5.0 / 8.0);
  // The conditions (21) of an RSD tuple: Ψ(0) = Ψ'(0) = 0, Ψ(1) = 1, Ψ0'(1) = 0.
  for (const Poly<double>& psi : {Phi, Theta}) {
    EXPECT_EQ(psi(0), 0.0);
    EXPECT_EQ(psi.derivative()(0), 0.0);
    EXPECT_EQ(psi(1), 1.0);
  }
  EXPECT_EQ(Phi.derivative()(1), 0.0);
}

/// Scalar data (in the x component) of the function `u` with gradient `grad` at the vertices of
/// the unit triangle (0,0), (1,0), (0,1): f_a = u(p_a), g_ab = directional derivative towards p_b.
template <class U, class Grad>
TriangleData scalar_data(U u, Grad grad) {
  const std::array<Eigen::Vector2d, 3> p = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)};
  TriangleData d;
  for (int a = 0; a < 3; ++a) {
    d.f[a] = Eigen::Vector3d(u(p[a]), 0, 0);
    for (int b = 0; b < 3; ++b) d.g[a][b] = Eigen::Vector3d(grad(p[a]).dot(p[b] - p[a]), 0, 0);
  }
  return d;
}

double patch_x(RsdTuple tuple, const TriangleData& d, const Eigen::Vector3d& t) {
  return rsd_patch(tuple, d, {}, rsd_degree(tuple)).value(t)[0];
}

TEST(RsdInterpolant, PartitionOfUnity) {
  TriangleData d;
  for (int a = 0; a < 3; ++a) {
    d.f[a] = Eigen::Vector3d(0.3, -1.7, 2.5);
    for (int b = 0; b < 3; ++b) d.g[a][b].setZero();
  }
  for (RsdTuple tuple : {RsdTuple::pi0, RsdTuple::pi1}) {
    const BezierTriangle f = rsd_patch(tuple, d, {}, rsd_degree(tuple));
    for (const auto& b : f.control) EXPECT_NEAR((b - d.f[0]).norm(), 0, 1e-15);
  }
}

TEST(RsdInterpolant, LinearPrecisionHoldsForPi1AndFailsForPi0WithTheNotesResiduals) {
  const auto x = [](const Eigen::Vector2d& p) { return p[0]; };
  const auto grad_x = [](const Eigen::Vector2d&) { return Eigen::Vector2d(1, 0); };
  const TriangleData d = scalar_data(x, grad_x);
  // x = t2 on the unit triangle.
  for (const Eigen::Vector3d t : {Eigen::Vector3d(0.5, 0.25, 0.25), Eigen::Vector3d(0.2, 0.6, 0.2),
                                  Eigen::Vector3d(0.1, 0.3, 0.6)})
    EXPECT_NEAR(patch_x(RsdTuple::pi1, d, t), t[1], 1e-15);
  // Π0: the residual −3 t1 t2 (t1+t2−1)(2t1² + 2t1t2 − 2t1 − t2² + t2) (note §9.3).
  EXPECT_NEAR(patch_x(RsdTuple::pi0, d, {0.5, 0.25, 0.25}) - 0.25, -3.0 / 512, 1e-15);
  EXPECT_NEAR(patch_x(RsdTuple::pi0, d, {0.2, 0.6, 0.2}) - 0.6, 36.0 / 3125, 1e-15);
}

TEST(RsdInterpolant, NeitherTupleReproducesQuadratics) {
  const auto x2 = [](const Eigen::Vector2d& p) { return p[0] * p[0]; };
  const auto grad = [](const Eigen::Vector2d& p) { return Eigen::Vector2d(2 * p[0], 0); };
  const TriangleData d = scalar_data(x2, grad);
  for (RsdTuple tuple : {RsdTuple::pi0, RsdTuple::pi1})
    EXPECT_GT(std::abs(patch_x(tuple, d, {0.2, 0.6, 0.2}) - 0.36), 1e-3);
}

TEST(RsdInterpolant, EdgeCurveAndCrossDerivativeMatchTheClosedFormsAndIgnoreTheThirdVertex) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> U(-1, 1);
  auto vec = [&] { return Eigen::Vector3d(U(random), U(random), U(random)); };
  auto arr = [](const Eigen::Vector3d& x) { return Vec3<double>{x[0], x[1], x[2]}; };
  TriangleData d;
  for (int a = 0; a < 3; ++a) {
    d.f[a] = vec();
    for (int b = 0; b < 3; ++b) d.g[a][b] = vec();
  }
  for (RsdTuple tuple : {RsdTuple::pi0, RsdTuple::pi1})
    for (const auto& [a, b] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}}) {
      const int c = 3 - a - b;
      // The closed forms of note §3.2 with i = a, j = b, k = c (t = t_a); v̄ is not needed here.
      const EdgeEndData<double> e{arr(d.f[a]),    arr(d.f[b]),    arr(d.g[a][b]), arr(d.g[b][a]),
                                  arr(d.g[a][c]), arr(d.g[b][c]), arr(d.g[a][c]), arr(d.g[b][c])};
      const EdgeCurves<double> closed = edge_curves(tuple, e);
      TriangleData other = d;  // different data at the third vertex
      other.f[c] += vec();
      other.g[c][a] += vec();
      other.g[c][b] += vec();
      for (const TriangleData& data : {d, other}) {
        const BezierTriangle f = rsd_patch(tuple, data, {}, rsd_degree(tuple));
        for (double t : samples) {
          Eigen::Vector3d point = Eigen::Vector3d::Zero(), cross = Eigen::Vector3d::Zero();
          point[a] = t;
          point[b] = 1 - t;
          cross[c] = 1;
          cross[a] = cross[b] = -0.5;
          const Eigen::Vector3d value = f.value(point), derivative = f.derivative(point, cross);
          for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(value[k], closed.c[k](t), 1e-13);
            EXPECT_NEAR(derivative[k], closed.v[k](t), 1e-13);
          }
          // u = c' is the derivative towards p_i (t increases towards p_a).
          Eigen::Vector3d along = Eigen::Vector3d::Zero();
          along[a] = 1;
          along[b] = -1;
          const Eigen::Vector3d u = f.derivative(point, along);
          for (int k = 0; k < 3; ++k) EXPECT_NEAR(u[k], closed.u[k](t), 1e-12);
        }
      }
    }
}

TEST(RsdInterpolant, DegreesBeforeCorrection) {
  EXPECT_EQ(rsd_degree(RsdTuple::pi0), 5);
  EXPECT_EQ(rsd_degree(RsdTuple::pi1), 6);
  EXPECT_EQ(degree(edge_curves<double>(RsdTuple::pi0, {{1, 0, 0}, {0, 1, 0}, {0, 1, 0}, {1, 0, 0},
                                                      {0, 0, 1}, {0, 0, 1}, {0, 0, -1}, {0, 0, -1}}).v), 4);
}

}  // namespace
}  // namespace iga::rsd
