/// @file
/// TensorBSplineSpace, PatchGeometry and make_bspline_space: dimension, partition of unity,
/// polynomial reproduction, nestedness, physical derivatives on the curved quarter annulus,
/// boundary edges and config errors (BSplineSpace* tests).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <random>
#include <thread>

#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "spaces/closed_forms.hpp"
#include "spaces/bspline/bspline_from_config.hpp"
#include "spaces/bspline/tensor_bspline_space.hpp"
#include "spaces/element_values.hpp"

namespace iga {
namespace {

const double pi = std::numbers::pi;

std::shared_ptr<const TensorBSplineSpace> build(const std::string& domain, const std::string& space, int level = 0) {
  const ConfigNode root = ConfigNode::load_string("domain: " + domain + "\nspace: " + space + "\n", "test.yaml");
  const SpacePtr s = make_bspline_space(root["domain"], root["space"], level);
  auto t = std::dynamic_pointer_cast<const TensorBSplineSpace>(s);
  EXPECT_TRUE(t != nullptr);
  return t;
}

const char* kAnnulus = "{type: quarter_annulus, inner: 1, outer: 2}";
const char* kRectangle = "{type: rectangle, min: [-1, 0.5], max: [2, 1.5]}";

std::string space_yaml(int p, int r, int nx, int ny) {
  return "{type: bspline, degree: " + std::to_string(p) + ", regularity: " + std::to_string(r) + ", elements: [" +
         std::to_string(nx) + ", " + std::to_string(ny) + "]}";
}

/// A single-point rule (weights unused by evaluators).
QuadratureRule points_rule(const std::vector<Point2>& pts) {
  QuadratureRule r;
  r.points = pts;
  r.weights.assign(pts.size(), 1.0);
  return r;
}

/// Message of the InputError thrown by f (empty when none).
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(BSplineSpace, DimensionFormula) {
  for (int p = 1; p <= 4; ++p)
    for (int r = 0; r < p; ++r)
      for (int level = 0; level <= 1; ++level) {
        const int nx = 3, ny = 2;
        const auto s = build(kRectangle, space_yaml(p, r, nx, ny), level);
        const int ex = nx << level, ey = ny << level;
        EXPECT_EQ(s->num_elements(), ex * ey);
        EXPECT_EQ(s->dimension(), (ex * (p - r) + r + 1) * (ey * (p - r) + r + 1)) << p << " " << r << " " << level;
        EXPECT_EQ(s->degree(), p);
        EXPECT_EQ(s->regularity(), r);
      }
  // Defaults: regularity p-1, elements [2, 2].
  const auto d = build(kAnnulus, "{type: bspline, degree: 3}");
  EXPECT_EQ(d->dimension(), 5 * 5);
  EXPECT_EQ(d->type(), "bspline");
  const auto params = d->parameters();
  ASSERT_EQ(params.size(), 4u);
  EXPECT_EQ(params[0], (std::pair<std::string, std::string>("degree", "3")));
  EXPECT_EQ(params[1], (std::pair<std::string, std::string>("regularity", "2")));
  EXPECT_EQ(params[2], (std::pair<std::string, std::string>("elements", "2x2")));
  EXPECT_EQ(params[3].first, "domain");
}

TEST(BSplineSpace, ElementDofsMatchEvaluatorAndCoverSpace) {
  const auto s = build(kAnnulus, space_yaml(3, 1, 3, 2));
  auto ev = s->make_evaluator();
  PointValues pv;
  std::vector<int> count(s->dimension(), 0), dofs;
  for (int e = 0; e < s->num_elements(); ++e) {
    ev->evaluate(e, *s->quadrature(e, 2), update_values, pv);
    s->element_dofs(e, dofs);
    EXPECT_EQ(dofs, pv.dofs);
    EXPECT_EQ(pv.num_functions(), 16);
    for (int i : dofs) ++count[i];
  }
  for (int c : count) EXPECT_GE(c, 1);
}

TEST(BSplineSpace, PartitionOfUnityOnCurvedPatch) {
  const auto s = build(kAnnulus, space_yaml(3, 1, 3, 2), 1);
  ElementValues fe(*s, update_values | update_gradients | update_hessians);
  double worst = 0.0;
  for (int e = 0; e < s->num_elements(); ++e) {
    fe.reinit(e, *s->quadrature(e, 5));
    const PointValues& v = fe.values();
    const Eigen::RowVectorXd one = Eigen::RowVectorXd::Ones(v.num_functions());
    worst = std::max(worst, ((one * v.value).array() - 1.0).abs().maxCoeff());
    for (const Eigen::MatrixXd* d : {&v.dx, &v.dy, &v.dxx, &v.dxy, &v.dyy})
      worst = std::max(worst, (one * *d).cwiseAbs().maxCoeff() / (1.0 + d->cwiseAbs().maxCoeff()));
  }
  EXPECT_LT(worst, 1e-12);
  std::printf("[ measured ] partition of unity (values; derivatives relative) %.2e\n", worst);
}

/// Least-squares residual of fitting f(x, y) by the space from its values at quadrature points.
double fit_residual(const Space& s, const std::function<double(double, double)>& f, int degree) {
  ElementValues fe(s, update_values);
  std::vector<Eigen::RowVectorXd> rows;
  std::vector<double> rhs;
  for (int e = 0; e < s.num_elements(); ++e) {
    fe.reinit(e, *s.quadrature(e, degree));
    const PointValues& v = fe.values();
    for (int q = 0; q < v.num_points(); ++q) {
      Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(s.dimension());
      for (int i = 0; i < v.num_functions(); ++i) row(v.dofs[i]) = v.value(i, q);
      rows.push_back(row);
      rhs.push_back(f(v.x(0, q), v.x(1, q)));
    }
  }
  Eigen::MatrixXd A(rows.size(), s.dimension());
  Eigen::VectorXd b(rows.size());
  for (size_t k = 0; k < rows.size(); ++k) {
    A.row(k) = rows[k];
    b(k) = rhs[k];
  }
  const Eigen::VectorXd c = A.colPivHouseholderQr().solve(b);
  return (A * c - b).cwiseAbs().maxCoeff();
}

TEST(BSplineSpace, ReproducesPolynomialsOnRectangle) {
  double worst = 0.0;
  for (int p = 1; p <= 4; ++p)
    for (int r = 0; r < p; ++r) {
      const auto s = build(kRectangle, space_yaml(p, r, 3, 2));
      EXPECT_TRUE(s->affine_elements());
      for (int a = 0; a <= p; ++a)
        for (int b = 0; b <= p; ++b) {
          // p+2 points per element and direction: more samples than functions.
          const double res =
              fit_residual(*s, [&](double x, double y) { return std::pow(x, a) * std::pow(y, b); }, 2 * p + 3);
          worst = std::max(worst, res);
        }
      // Degree p+1 in x is not in the space.
      EXPECT_GT(fit_residual(*s, [&](double x, double) { return std::pow(x, p + 1); }, 2 * p + 3), 1e-4);
    }
  EXPECT_LT(worst, 1e-12);
  std::printf("[ measured ] x^a y^b (a, b <= p) least-squares residual %.2e\n", worst);
}

TEST(BSplineSpace, RefinedSpaceContainsCoarseFunctions) {
  // Nestedness on the curved patch: a random coarse function evaluated at the fine quadrature
  // points is fitted exactly by the level-1 space of the same degree and regularity.
  for (int p = 2; p <= 3; ++p) {
    const int r = p - 2;
    const auto coarse = build(kAnnulus, space_yaml(p, r, 2, 3), 0);
    const auto fine = build(kAnnulus, space_yaml(p, r, 2, 3), 1);
    const Eigen::VectorXd c = Eigen::VectorXd::Random(coarse->dimension());
    auto cev = coarse->make_evaluator();
    ElementValues fe(*fine, update_values);
    std::vector<Eigen::RowVectorXd> rows;
    std::vector<double> rhs;
    double xdiff = 0.0;
    for (int e = 0; e < fine->num_elements(); ++e) {
      const QuadratureRule& rule = *fine->quadrature(e, 2 * p + 3);  // p+2 points per direction
      fe.reinit(e, rule);
      // The coarse element containing this fine element, and the fine points in its reference cell.
      Point2 lo, hi, clo, chi;
      fine->element_box(e, lo, hi);
      const Point2 mid = 0.5 * (lo + hi);
      int cex = 0, cey = 0;
      for (int k = 0; k < coarse->num_elements_u(); ++k)
        if (coarse->knots_u()[coarse->knots_u().spans()[k]] <= mid.x()) cex = k;
      for (int k = 0; k < coarse->num_elements_v(); ++k)
        if (coarse->knots_v()[coarse->knots_v().spans()[k]] <= mid.y()) cey = k;
      const int celem = cex + cey * coarse->num_elements_u();
      coarse->element_box(celem, clo, chi);
      std::vector<Point2> pts;
      for (const Point2& xi : rule.points) pts.push_back((lo + (hi - lo).cwiseProduct(xi) - clo).cwiseQuotient(chi - clo));
      const QuadratureRule cr = points_rule(pts);
      PointValues cv;
      cev->evaluate(celem, cr, update_values, cv);
      xdiff = std::max(xdiff, (cv.x - fe.values().x).cwiseAbs().maxCoeff());
      for (int q = 0; q < rule.size(); ++q) {
        Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(fine->dimension());
        for (int i = 0; i < fe.num_functions(); ++i) row(fe.dofs()[i]) = fe.values().value(i, q);
        rows.push_back(row);
        double f = 0.0;
        for (int i = 0; i < cv.num_functions(); ++i) f += c(cv.dofs[i]) * cv.value(i, q);
        rhs.push_back(f);
      }
    }
    EXPECT_LT(xdiff, 1e-14);
    Eigen::MatrixXd A(rows.size(), fine->dimension());
    Eigen::VectorXd b(rows.size());
    for (size_t k = 0; k < rows.size(); ++k) {
      A.row(k) = rows[k];
      b(k) = rhs[k];
    }
    const Eigen::VectorXd d = A.colPivHouseholderQr().solve(b);
    const double res = (A * d - b).cwiseAbs().maxCoeff();
    EXPECT_LT(res, 1e-12) << "p " << p;
    std::printf("[ measured ] p %d: coarse function in refined space, residual %.2e\n", p, res);
  }
}

TEST(BSplineSpace, GeometryJetMatchesFiniteDifferences) {
  const PatchGeometry g = PatchGeometry::quarter_annulus(1.0, 2.0);
  const double h = 1e-5;
  double worst_j = 0.0, worst_h = 0.0;
  for (double u : {0.1, 0.5, 0.83})
    for (double v : {0.2, 0.5, 0.91}) {
      const GeometryJet j = g.evaluate({u, v});
      for (int k = 0; k < 2; ++k) {
        const Point2 e = Point2::Unit(k) * h;
        const GeometryJet jp = g.evaluate(Point2(u, v) + e), jm = g.evaluate(Point2(u, v) - e);
        worst_j = std::max(worst_j, ((jp.x - jm.x) / (2 * h) - j.jacobian.col(k)).norm());
        // Column k of the Hessians = d(J)/d xi_k rows.
        const Eigen::Matrix2d dJ = (jp.jacobian - jm.jacobian) / (2 * h);
        worst_h = std::max(worst_h, std::abs(dJ(0, 0) - j.hessian_x(0, k)) + std::abs(dJ(0, 1) - j.hessian_x(1, k)) +
                                        std::abs(dJ(1, 0) - j.hessian_y(0, k)) + std::abs(dJ(1, 1) - j.hessian_y(1, k)));
      }
    }
  EXPECT_LT(worst_j, 1e-8);
  EXPECT_LT(worst_h, 1e-7);
}

TEST(BSplineSpace, RectangleMapIsItsBilinearPatch) {
  // The rectangle is evaluated as F = min + diag(max - min) uv, not by the spline sums of its
  // bilinear patch: the same map to round-off, with the Jacobian's zeros and the Hessians exact
  // (the sums leave 2e-16 in ∂x/∂v).
  const Point2 lo(-1.0, 0.5), hi(2.0, 1.75);
  const PatchGeometry fast = PatchGeometry::rectangle(lo, hi);
  const KnotVector linear(1, {0.0, 0.0, 1.0, 1.0});
  const PatchGeometry sums(linear, linear, {lo, Point2(hi.x(), lo.y()), Point2(lo.x(), hi.y()), hi});
  ASSERT_TRUE(fast.is_affine());
  ASSERT_FALSE(sums.is_affine());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const Point2 uv(k == 0 ? 0.0 : k == 1 ? 1.0 : unit(rng), k == 0 ? 0.0 : k == 1 ? 1.0 : unit(rng));
    const GeometryJet a = fast.evaluate(uv), b = sums.evaluate(uv);
    EXPECT_LT((a.x - b.x).norm(), 4 * std::numeric_limits<double>::epsilon() * hi.norm()) << uv.transpose();
    const double round_off = 4 * std::numeric_limits<double>::epsilon() * (hi - lo).norm();
    EXPECT_LT((a.jacobian - b.jacobian).norm(), round_off) << uv.transpose();
    EXPECT_LT(b.hessian_x.norm() + b.hessian_y.norm(), round_off) << uv.transpose();
    EXPECT_EQ(a.jacobian, Eigen::Matrix2d((hi - lo).asDiagonal()));
    EXPECT_EQ(a.hessian_x, Eigen::Matrix2d::Zero());
    EXPECT_EQ(a.hessian_y, Eigen::Matrix2d::Zero());
  }
  EXPECT_EQ(fast.evaluate(Point2(0.0, 0.0)).x, lo);
  EXPECT_EQ(fast.evaluate(Point2(1.0, 1.0)).x, hi);
}

TEST(BSplineSpace, PhysicalDerivativesOnAnnulusMatchFiniteDifferences) {
  // grad N(xi+d) - grad N(xi-d) ~ H (x(xi+d) - x(xi-d)) and N(xi+d) - N(xi-d) ~ grad N . (same),
  // with errors O(|d|^3): checks the chain rule including the NURBS second derivatives.
  const auto s = build(kAnnulus, space_yaml(3, 1, 2, 3), 1);
  auto ev = s->make_evaluator();
  const double d = 1e-4;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unif(0.1, 0.9), angle(0.0, 2 * pi);
  double worst_grad = 0.0, worst_hess = 0.0;
  for (int e = 0; e < s->num_elements(); e += 3)
    for (int t = 0; t < 4; ++t) {
      const Point2 xi(unif(rng), unif(rng));
      const double a = angle(rng);
      const Point2 step = d * Point2(std::cos(a), std::sin(a));
      PointValues pv;
      ev->evaluate(e, points_rule({xi, xi + step, xi - step}), update_values | update_gradients | update_hessians, pv);
      const Point2 dx = pv.x.col(1) - pv.x.col(2);
      for (int i = 0; i < pv.num_functions(); ++i) {
        const Point2 g(pv.dx(i, 0), pv.dy(i, 0));
        Eigen::Matrix2d H;
        H << pv.dxx(i, 0), pv.dxy(i, 0), pv.dxy(i, 0), pv.dyy(i, 0);
        const double dv = pv.value(i, 1) - pv.value(i, 2);
        const Point2 dg(pv.dx(i, 1) - pv.dx(i, 2), pv.dy(i, 1) - pv.dy(i, 2));
        worst_grad = std::max(worst_grad, std::abs(dv - g.dot(dx)) / (g.norm() * dx.norm() + 1e-3 * dx.norm()));
        worst_hess = std::max(worst_hess, (dg - H * dx).norm() / (H.norm() * dx.norm() + 1e-3 * dx.norm()));
      }
    }
  EXPECT_LT(worst_grad, 1e-6);
  EXPECT_LT(worst_hess, 1e-6);
  EXPECT_GT(worst_hess, 0.0);
  std::printf("[ measured ] FD relative errors: gradient %.2e, Hessian %.2e\n", worst_grad, worst_hess);
}

TEST(BSplineSpace, AnnulusBoundaryIsExactlyCircular) {
  const PatchGeometry g = PatchGeometry::quarter_annulus(1.0, 2.0);
  double worst = 0.0;
  for (int k = 0; k <= 50; ++k) {
    const double v = k / 50.0;
    worst = std::max(worst, std::abs(g.point({0.0, v}).norm() - 1.0));
    worst = std::max(worst, std::abs(g.point({1.0, v}).norm() - 2.0));
  }
  EXPECT_LT(worst, 1e-14);
  std::printf("[ measured ] max ||x| - r| on the arcs %.2e\n", worst);
  EXPECT_LT((g.point({0.0, 0.0}) - Point2(1, 0)).norm(), 1e-15);
  EXPECT_LT((g.point({1.0, 1.0}) - Point2(0, 2)).norm(), 1e-15);
  EXPECT_NEAR(g.point({0.0, 0.5}).x(), std::sqrt(0.5), 1e-15);  // symmetric parametrization
  EXPECT_TRUE(g.is_rational());
  EXPECT_FALSE(g.is_affine());
}

TEST(BSplineSpace, EdgeLengthsNormalsAndArea) {
  const double r0 = 1.0, r1 = 2.0;
  const auto s = build(kAnnulus, space_yaml(2, 1, 2, 3), 1);
  EXPECT_FALSE(s->affine_elements());
  ElementValues fe(*s, update_values);
  double area = 0.0;
  for (int e = 0; e < s->num_elements(); ++e) {
    fe.reinit(e, *s->quadrature(e, 16));
    area += fe.jxw().sum();
  }
  EXPECT_NEAR(area, pi * (r1 * r1 - r0 * r0) / 4, 1e-13);
  std::printf("[ measured ] area error %.2e\n", std::abs(area - pi * (r1 * r1 - r0 * r0) / 4));

  const std::map<std::string, double> length = {
      {"left", pi * r0 / 2}, {"right", pi * r1 / 2}, {"bottom", r1 - r0}, {"top", r1 - r0}};
  double worst_normal = 0.0, worst_length = 0.0;
  for (const auto& [name, expected] : length) {
    double sum = 0.0;
    for (const BoundaryEdge& b : s->boundary_edges(name)) {
      fe.reinit_edge(b.element, b.local_edge, *s->edge_quadrature(b.element, b.local_edge, 20));
      sum += fe.jxw().sum();
      for (int q = 0; q < fe.num_points(); ++q) {
        const Point2 x = fe.values().x.col(q);
        Point2 n;
        if (name == "left") n = -x.normalized();
        if (name == "right") n = x.normalized();
        if (name == "bottom") n = Point2(0, -1);
        if (name == "top") n = Point2(-1, 0);
        worst_normal = std::max(worst_normal, (fe.normal().col(q) - n).norm());
      }
    }
    worst_length = std::max(worst_length, std::abs(sum - expected));
    std::printf("[ measured ] %-6s length %.16f (exact %.16f)\n", name.c_str(), sum, expected);
  }
  EXPECT_LT(worst_length, 1e-12);
  EXPECT_LT(worst_normal, 1e-14);
}

TEST(BSplineSpace, BoundaryEdgesAndMeshSize) {
  const auto s = build("{type: rectangle, min: [0, 0], max: [2, 1]}", space_yaml(2, 1, 4, 2));
  EXPECT_EQ(s->boundary_names(), (std::vector<std::string>{"left", "right", "bottom", "top"}));
  EXPECT_EQ(s->boundary_edges("all").size(), 12u);
  const auto left = s->boundary_edges("left");
  ASSERT_EQ(left.size(), 2u);
  EXPECT_EQ(left[1].element, 4);
  EXPECT_EQ(left[1].local_edge, 3);
  const auto top = s->boundary_edges("top");
  ASSERT_EQ(top.size(), 4u);
  EXPECT_EQ(top[0].element, 4);
  EXPECT_EQ(top[0].local_edge, 2);
  EXPECT_EQ(s->boundary_edges("right")[0].local_edge, 1);
  EXPECT_EQ(s->boundary_edges("bottom")[3].element, 3);
  EXPECT_THROW(s->boundary_edges("inner"), InputError);
  // Elements are 0.5 x 0.5.
  EXPECT_NEAR(s->mesh_size(), std::sqrt(0.5), 1e-15);

  // Curved: the largest element touches the outer arc; h halves under refinement.
  const double h0 = build(kAnnulus, space_yaml(2, 1, 2, 2))->mesh_size();
  const double h1 = build(kAnnulus, space_yaml(2, 1, 2, 2), 1)->mesh_size();
  EXPECT_GT(h0, std::hypot(0.5, 2 * std::sin(pi / 8)) * 0.99);
  EXPECT_GT(h0 / h1, 1.8);  // curvature makes the coarse ratio a little below 2
  EXPECT_LT(h0 / h1, 2.0);
}

TEST(BSplineSpace, QuadratureRulesAreSharedAndExact) {
  const auto s = build(kRectangle, space_yaml(3, 2, 2, 2));
  const RulePtr a = s->quadrature(0, 6), b = s->quadrature(3, 6);
  EXPECT_EQ(a.get(), b.get());
  EXPECT_GE(a->degree, 6);
  EXPECT_NEAR(std::accumulate(a->weights.begin(), a->weights.end(), 0.0), 1.0, 1e-14);
  const RulePtr e1 = s->edge_quadrature(0, 1, 5), e2 = s->edge_quadrature(2, 1, 5);
  EXPECT_EQ(e1.get(), e2.get());
  for (const Point2& p : e1->points) EXPECT_EQ(p.x(), 1.0);
  // Integral of x^6 y^6 over the unit square.
  double v = 0.0;
  for (int k = 0; k < a->size(); ++k) v += a->weights[k] * std::pow(a->points[k].x() * a->points[k].y(), 6);
  EXPECT_NEAR(v, 1.0 / 49, 1e-15);
}

TEST(BSplineSpace, ThreadsShareRulesAndEvaluateIdentically) {
  // One space, one evaluator per thread, rules requested concurrently (mutex-protected cache).
  const auto s = build(kAnnulus, space_yaml(3, 2, 4, 4), 1);
  const int nthreads = 4;
  std::vector<double> sums(nthreads, 0.0);
  std::vector<const QuadratureRule*> rules(nthreads, nullptr);
  std::vector<std::thread> threads;
  for (int t = 0; t < nthreads; ++t)
    threads.emplace_back([&, t] {
      ElementValues fe(*s, update_values | update_hessians);
      for (int e = 0; e < s->num_elements(); ++e) {
        const RulePtr rule = s->quadrature(e, 7 + e % 3);
        if (e == 0) rules[t] = rule.get();
        fe.reinit(e, *rule);
        sums[t] += (fe.values().dxx * fe.jxw()).sum();
      }
    });
  for (std::thread& th : threads) th.join();
  for (int t = 1; t < nthreads; ++t) {
    EXPECT_EQ(sums[t], sums[0]);
    EXPECT_EQ(rules[t], rules[0]);
  }
}

TEST(BSplineSpace, PatchDomainFromData) {
  // The quarter annulus written as a general NURBS patch, with knots on [0,2] (rescaled).
  const std::string patch =
      "{type: patch, degree: [1, 2], knots_u: [0, 0, 2, 2], knots_v: [0, 0, 0, 2, 2, 2],"
      " control_points: [[1, 0], [2, 0], [1, 1], [2, 2], [0, 1], [0, 2]],"
      " weights: [1, 1, 0.7071067811865476, 0.7071067811865476, 1, 1]}";
  const auto s = build(patch, space_yaml(3, 2, 2, 2));
  const auto a = build(kAnnulus, space_yaml(3, 2, 2, 2));
  for (double u : {0.0, 0.3, 1.0})
    for (double v : {0.0, 0.6, 1.0})
      EXPECT_LT((s->geometry().point({u, v}) - a->geometry().point({u, v})).norm(), 1e-15);

  // A polynomial patch with an interior geometry knot: the space keeps that breakpoint.
  const std::string two_spans =
      "{type: patch, degree: [2, 1], knots_u: [0, 0, 0, 0.25, 1, 1, 1], knots_v: [0, 0, 1, 1],"
      " control_points: [[0, 0], [0.5, 0.1], [2, 0], [3, 0.2], [0, 1], [0.5, 1.1], [2, 1], [3, 1.3]]}";
  const auto p2 = build(two_spans, space_yaml(2, 1, 4, 1), 1);
  EXPECT_EQ(p2->num_elements_u(), 8);
  EXPECT_EQ(p2->knots_u().multiplicity(0.25), 1);
  EXPECT_EQ(p2->knots_u().multiplicity(0.125), 1);
  EXPECT_EQ(p2->knots_u().multiplicity(0.8125), 1);
  EXPECT_EQ(p2->dimension(), (8 + 2) * (2 + 2));
  EXPECT_FALSE(p2->affine_elements());
}

TEST(BSplineSpace, ClosedFormMatricesMatchQuadratureAndKeepTheirKernel) {
  // On rectangles (the affine patches) the double-double closed form equals the Gauss matrix to
  // round-off, is exactly symmetric and maps constants to zero (linears too, for the second-order
  // forms) to double-double round-off.
  for (int p : {2, 3, 5}) {
    const auto s = build(kRectangle, space_yaml(p, p - 1, 5, 3));
    ASSERT_TRUE(s->geometry().is_affine());
    ElementValues fe(*s, update_values | update_gradients | update_hessians);
    for (int e : {0, 7, 14}) {
      fe.reinit(e, *s->quadrature(e, 2 * p));
      const PointValues& v = fe.values();
      const Eigen::VectorXd& w = fe.jxw();
      const Eigen::MatrixXd lap = v.dxx + v.dyy;
      const std::map<BilinearForm, Eigen::MatrixXd> gauss = {
          {BilinearForm::mass, v.value * w.asDiagonal() * v.value.transpose()},
          {BilinearForm::laplace, v.dx * w.asDiagonal() * v.dx.transpose() + v.dy * w.asDiagonal() * v.dy.transpose()},
          {BilinearForm::bilaplace, lap * w.asDiagonal() * lap.transpose()},
          {BilinearForm::hessian, v.dxx * w.asDiagonal() * v.dxx.transpose() +
                                      2 * v.dxy * w.asDiagonal() * v.dxy.transpose() +
                                      v.dyy * w.asDiagonal() * v.dyy.transpose()}};
      for (const auto& [form, expected] : gauss) {
        DoubleDoubleMatrix exact;
        ASSERT_TRUE(s->closed_forms()->element_matrix(e, form, exact));
        const double scale = expected.cwiseAbs().maxCoeff();
        EXPECT_LT((exact.hi - expected).cwiseAbs().maxCoeff(), 1e-12 * scale) << "element " << e;
        EXPECT_EQ(exact.hi, exact.hi.transpose());
        EXPECT_EQ(exact.lo, exact.lo.transpose());
        if (form == BilinearForm::mass) continue;
        // Constants, and for the second-order forms x and y (the functions' coefficients of x, y
        // from the element's own Gauss points by least squares), lie in the kernel.
        std::vector<Eigen::VectorXd> kernel = {Eigen::VectorXd::Ones(exact.rows())};
        if (form != BilinearForm::laplace)
          for (int d = 0; d < 2; ++d)
            kernel.push_back(v.value.transpose().colPivHouseholderQr().solve(v.x.row(d).transpose()));
        // Constants are exact in double: their image is zero to double-double round-off; the
        // least-squares linears carry double round-off.
        for (std::size_t k = 0; k < kernel.size(); ++k) {
          const double bound = (k == 0 ? 1e-24 : 1e-12) * scale * kernel[k].cwiseAbs().maxCoeff();
          for (Eigen::Index i = 0; i < exact.rows(); ++i) {
            DoubleDouble row(0.0);
            for (Eigen::Index j = 0; j < exact.cols(); ++j) row += exact(i, j) * DoubleDouble(kernel[k](j));
            EXPECT_LT(std::abs(row.hi), bound) << "element " << e;
          }
        }
      }
    }
  }
}

TEST(BSplineSpace, ConfigErrorsNameThePlace) {
  auto err = [](const std::string& domain, const std::string& space) {
    return error_of([&] { build(domain, space); });
  };
  const std::string deg0 = err(kRectangle, "{type: bspline, degree: 0}");
  EXPECT_NE(deg0.find("space.degree"), std::string::npos) << deg0;
  EXPECT_NE(deg0.find("B-splines need degree >= 1 (got 0)"), std::string::npos) << deg0;

  const std::string reg = err(kRectangle, "{type: bspline, degree: 3, regularity: 3}");
  EXPECT_NE(reg.find("space.regularity"), std::string::npos) << reg;
  EXPECT_NE(reg.find("regularity must be between 0 and degree-1 = 2 (got 3)"), std::string::npos) << reg;
  EXPECT_NE(err(kRectangle, "{type: bspline, degree: 2, regularity: -1}").find("(got -1)"), std::string::npos);

  const std::string el = err(kRectangle, "{type: bspline, degree: 2, elements: [0, 2]}");
  EXPECT_NE(el.find("space.elements"), std::string::npos) << el;
  EXPECT_NE(el.find("element counts must be >= 1"), std::string::npos) << el;

  const std::string key = err(kRectangle, "{type: bspline, degre: 2}");
  EXPECT_NE(key.find("degre"), std::string::npos) << key;

  const std::string rect = err("{type: rectangle, min: [0, 1], max: [1, 1]}", "{type: bspline, degree: 2}");
  EXPECT_NE(rect.find("domain.max"), std::string::npos) << rect;
  EXPECT_NE(rect.find("max must be greater than min"), std::string::npos) << rect;

  const std::string ann = err("{type: quarter_annulus, inner: 2, outer: 2}", "{type: bspline, degree: 2}");
  EXPECT_NE(ann.find("domain.outer"), std::string::npos) << ann;
  EXPECT_NE(ann.find("outer radius must be greater than the inner one (got inner = 2, outer = 2)"),
            std::string::npos)
      << ann;
  EXPECT_NE(err("{type: quarter_annulus, inner: 0, outer: 2}", "{type: bspline, degree: 2}").find("domain.inner"),
            std::string::npos);

  const std::string count =
      err("{type: patch, degree: [1, 1], knots_u: [0, 0, 1, 1], knots_v: [0, 0, 1, 1],"
          " control_points: [[0, 0], [1, 0], [0, 1]]}",
          "{type: bspline, degree: 2}");
  EXPECT_NE(count.find("domain.control_points"), std::string::npos) << count;
  EXPECT_NE(count.find("need 2 x 2 = 4 control points"), std::string::npos) << count;

  const std::string knots = err("{type: patch, degree: [2, 1], knots_u: [0, 0, 1, 1], knots_v: [0, 0, 1, 1],"
                                " control_points: [[0, 0], [1, 0], [0, 1], [1, 1]]}",
                                "{type: bspline, degree: 2}");
  EXPECT_NE(knots.find("domain.knots_u"), std::string::npos) << knots;

  // Clockwise control points: det J < 0 everywhere.
  const std::string flip = err("{type: patch, degree: [1, 1], knots_u: [0, 0, 1, 1], knots_v: [0, 0, 1, 1],"
                               " control_points: [[0, 0], [0, 1], [1, 0], [1, 1]]}",
                               "{type: bspline, degree: 2}");
  EXPECT_NE(flip.find("domain"), std::string::npos) << flip;
  EXPECT_NE(flip.find("reverses orientation"), std::string::npos) << flip;

  const std::string weights = err("{type: patch, degree: [1, 1], knots_u: [0, 0, 1, 1], knots_v: [0, 0, 1, 1],"
                                  " control_points: [[0, 0], [1, 0], [0, 1], [1, 1]], weights: [1, 1, 0, 1]}",
                                  "{type: bspline, degree: 2}");
  EXPECT_NE(weights.find("weights must be positive"), std::string::npos) << weights;

  const std::string split = err("{type: patch, degree: [2, 1], knots_u: [0, 0, 0, 0.5, 1, 1, 1], knots_v: [0, 0, 1, 1],"
                                " control_points: [[0, 0], [1, 0], [2, 0], [3, 0], [0, 1], [1, 1], [2, 1], [3, 1]]}",
                                "{type: bspline, degree: 2, elements: [3, 2]}");
  EXPECT_NE(split.find("use a multiple of 2"), std::string::npos) << split;
}

}  // namespace
}  // namespace iga
