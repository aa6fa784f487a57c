#pragma once
// Helpers shared by the G1 space tests (quads, triangles, mixed meshes): the brute-force null
// space of all C0 + G1 rows, the global extraction, Bernstein coefficients of a function of (x, y)
// on every face, and the largest value / gradient jump of any basis function across interfaces.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "spaces/g1/bernstein_face.hpp"
#include "spaces/g1/g1_space.hpp"

namespace iga::test {

/// Row offset of each face's Bernstein coefficients in the stacked vector of all faces (size F+1).
inline std::vector<int> face_offsets(const PatchMesh& m, int k) {
  std::vector<int> off{0};
  for (int f = 0; f < m.num_faces(); ++f) off.push_back(off.back() + bernstein_count(m.shape(f), k));
  return off;
}

/// Global extraction: all face Bernstein coefficients (stacked by face_offsets) x global functions.
inline Eigen::MatrixXd global_extraction(const G1Space& s) {
  const std::vector<int> off = face_offsets(s.mesh(), s.degree());
  Eigen::MatrixXd e = Eigen::MatrixXd::Zero(off.back(), s.dimension());
  for (int f = 0; f < s.num_elements(); ++f) {
    const Eigen::MatrixXd c = s.basis().extraction[f];
    for (int j = 0; j < c.cols(); ++j) e.block(off[f], s.basis().face_dofs[f][j], c.rows(), 1) = c.col(j);
  }
  return e;
}

/// Bernstein coefficients on every face of a function of (x, y) (interpolation at the domain
/// points of each face, exact for polynomials of the face's degree), stacked like global_extraction.
inline Eigen::VectorXd face_coefficients(const G1Space& s, const std::function<double(Point2)>& fn) {
  const int k = s.degree();
  const std::vector<int> off = face_offsets(s.mesh(), k);
  Eigen::VectorXd out(off.back());
  for (CellShape shape : {CellShape::quadrilateral, CellShape::triangle}) {
    std::vector<Point2> pts;
    for (int j = 0; j <= k; ++j)
      for (int i = 0; i <= k; ++i)
        if (shape == CellShape::quadrilateral || i + j <= k) pts.push_back(Point2(double(i) / k, double(j) / k));
    const int nb = bernstein_count(shape, k);
    Eigen::MatrixXd b(nb, nb);
    for (int p = 0; p < nb; ++p) b.row(p) = bernstein_jet(shape, k, pts[p]).row(0);
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(b);
    for (int f = 0; f < s.num_elements(); ++f) {
      if (s.mesh().shape(f) != shape) continue;
      Eigen::VectorXd v(nb);
      for (int p = 0; p < nb; ++p) v[p] = fn(s.mesh().map(f, pts[p]).x);
      out.segment(off[f], nb) = lu.solve(v);
    }
  }
  return out;
}

/// Largest jump of value and of physical gradient of any basis function across interior edges
/// (7 points per edge, ends included), and the largest gradient seen.
inline void max_jumps(const G1Space& s, double& value_jump, double& gradient_jump, double& gradient_max) {
  value_jump = gradient_jump = gradient_max = 0.0;
  auto ev = s.make_evaluator();
  const std::vector<double> ts{0.0, 0.13, 0.31, 0.5, 0.77, 0.94, 1.0};
  for (int e = 0; e < s.mesh().num_edges(); ++e) {
    if (s.mesh().edge(e).boundary()) continue;
    const EdgeFrame fr = edge_frame(s.mesh(), e);
    QuadratureRule r1, r2;
    for (double t : ts) {
      r1.points.push_back(fr.start1 + t * fr.tangent1);
      r2.points.push_back(fr.start2 + t * fr.tangent2);
      r1.weights.push_back(1.0);
      r2.weights.push_back(1.0);
    }
    PointValues v1, v2;
    ev->evaluate(fr.face1, r1, update_values | update_gradients, v1);
    ev->evaluate(fr.face2, r2, update_values | update_gradients, v2);
    EXPECT_LT((v1.x - v2.x).cwiseAbs().maxCoeff(), 1e-14);
    std::map<int, std::pair<int, int>> rows;
    for (int i = 0; i < v1.num_functions(); ++i) rows[v1.dofs[i]].first = i + 1;
    for (int i = 0; i < v2.num_functions(); ++i) rows[v2.dofs[i]].second = i + 1;
    for (const auto& [g, r] : rows)
      for (int q = 0; q < static_cast<int>(ts.size()); ++q) {
        auto get = [&](const PointValues& v, int row, double& val, Eigen::Vector2d& grad) {
          val = row ? v.value(row - 1, q) : 0.0;
          grad = row ? Eigen::Vector2d(v.dx(row - 1, q), v.dy(row - 1, q)) : Eigen::Vector2d::Zero();
        };
        double a, b;
        Eigen::Vector2d ga, gb;
        get(v1, r.first, a, ga);
        get(v2, r.second, b, gb);
        value_jump = std::max(value_jump, std::abs(a - b));
        gradient_jump = std::max(gradient_jump, (ga - gb).norm());
        gradient_max = std::max(gradient_max, ga.norm());
      }
  }
}

/// Largest C0 + G1 row (edge_constraint_rows) applied to any basis function, relative to that
/// function's largest Bernstein coefficient: exactly 0 in exact arithmetic (notes §9.5.1).
inline double max_g1_residual(const G1Space& s) {
  const Eigen::MatrixXd e = global_extraction(s);
  const std::vector<int> off = face_offsets(s.mesh(), s.degree());
  const Eigen::ArrayXd scale = e.cwiseAbs().colwise().maxCoeff().transpose().array();
  double residual = 0.0;
  for (int id = 0; id < s.mesh().num_edges(); ++id) {
    if (s.mesh().edge(id).boundary()) continue;
    for (const auto& row : edge_constraint_rows(s.mesh(), s.gluing()[id], s.degree())) {
      Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(e.rows());
      for (const FaceCoefficient& fc : row) r[off[fc.face] + fc.index] += fc.value;
      residual = std::max(residual, ((r * e).transpose().array().abs() / scale).maxCoeff());
    }
  }
  return residual;
}

/// Property checks of a G1 space (notes §9.5), failures reported with `name`:
/// G1 residual <= 1e-12 and physical C1 continuity of every basis function (value jumps < 1e-12,
/// gradient jumps < 1e-11, with real gradients seen).
inline void expect_c1(const G1Space& s, const std::string& name) {
  EXPECT_LT(max_g1_residual(s), 1e-12) << name;
  double vj, gj, gmax;
  max_jumps(s, vj, gj, gmax);
  EXPECT_LT(vj, 1e-12) << name;
  EXPECT_LT(gj, 1e-11) << name << " (largest gradient " << gmax << ")";
  EXPECT_GT(gmax, 1.0) << name;  // the check saw real gradients
}

/// Full rank of the extraction (smallest singular value > 1e-6 x largest).
inline void expect_linearly_independent(const G1Space& s, const std::string& name) {
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(global_extraction(s));
  const Eigen::VectorXd& sv = svd.singularValues();
  EXPECT_GT(sv[sv.size() - 1], 1e-6 * sv[0]) << name;
}

/// 1 = Σ (vertex value functions): coordinate 1 on every value function (one per vertex), 0 on the
/// other vertex functions.
inline void expect_partition_of_unity(const G1Space& s, const std::string& name) {
  const Eigen::MatrixXd e = global_extraction(s);
  const Eigen::VectorXd one = face_coefficients(s, [](Point2) { return 1.0; });
  const Eigen::VectorXd x = e.colPivHouseholderQr().solve(one);
  EXPECT_LT((e * x - one).cwiseAbs().maxCoeff(), 1e-11) << name;
  int values = 0;
  for (int g = 0; g < s.dimension(); ++g) {
    const G1FunctionInfo& i = s.basis().info[g];
    if (i.entity != G1Entity::vertex) continue;
    EXPECT_NEAR(x[g], i.value_function ? 1.0 : 0.0, 1e-10) << name << " function " << g;
    values += i.value_function ? 1 : 0;
  }
  EXPECT_EQ(values, s.mesh().num_vertices()) << name;
}

/// Every polynomial (x − 0.3)^i (y + 0.2)^j with i + j <= k lies in the space (least-squares
/// residual of its Bernstein coefficients <= 1e-10 relative). Degree k+1 is not reproduced on
/// non-affine meshes, so this can fail.
inline void expect_reproduces_degree_k(const G1Space& s, const std::string& name) {
  const Eigen::MatrixXd e = global_extraction(s);
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(e);
  for (int d = 0; d <= s.degree(); ++d)
    for (int i = 0; i <= d; ++i) {
      const Eigen::VectorXd b =
          face_coefficients(s, [&](Point2 p) { return std::pow(p.x() - 0.3, i) * std::pow(p.y() + 0.2, d - i); });
      EXPECT_LT((e * qr.solve(b) - b).cwiseAbs().maxCoeff(), 1e-10 * std::max(1.0, b.cwiseAbs().maxCoeff()))
          << name << " x^" << i << " y^" << d - i;
    }
}

/// Numbers of basis functions vanishing on the boundary (row 0 of every boundary edge: the
/// Dirichlet subspace) and vanishing to first order there (rows 0 and 1: the clamped subspace).
inline std::pair<int, int> boundary_subspace_counts(const G1Space& s) {
  const int k = s.degree();
  std::vector<double> row0(s.dimension(), 0.0), row1(s.dimension(), 0.0);
  for (const BoundaryEdge& b : s.boundary_edges("all")) {
    const Eigen::MatrixXd ex = s.basis().extraction[b.element];
    const std::vector<int>& dofs = s.basis().face_dofs[b.element];
    const CellShape shape = s.mesh().shape(b.element);
    for (int j = 0; j < ex.cols(); ++j)
      for (int r = 0; r <= 1; ++r)
        for (int m = 0; m <= edge_row_last(shape, k, r); ++m) {
          double& row = r == 0 ? row0[dofs[j]] : row1[dofs[j]];
          row = std::max(row, std::abs(ex(edge_coefficient(shape, k, b.local_edge, m, r), j)));
        }
  }
  int dirichlet = 0, clamped = 0;
  for (int g = 0; g < s.dimension(); ++g) {
    dirichlet += row0[g] < 1e-12 ? 1 : 0;
    clamped += (row0[g] < 1e-12 && row1[g] < 1e-12) ? 1 : 0;
  }
  return {dirichlet, clamped};
}

/// Nullity of all C0 + G1 rows on all Bernstein coefficients (dense SVD): dim S¹_k by brute force;
/// with rows_zero = 1 (Dirichlet) or 2 (clamped), of the subspace whose Bernstein rows
/// 0 .. rows_zero-1 along every boundary edge vanish.
inline int brute_force_dimension(const PatchMesh& m, int k, int rows_zero = 0) {
  const std::vector<EdgeGluing> g = gluing_from_geometry(m);
  const std::vector<int> off = face_offsets(m, k);
  std::vector<std::vector<FaceCoefficient>> rows;
  for (int e = 0; e < m.num_edges(); ++e) {
    const MeshEdge& me = m.edge(e);
    if (!me.boundary()) {
      auto r = edge_constraint_rows(m, g[e], k);
      rows.insert(rows.end(), r.begin(), r.end());
      continue;
    }
    const CellShape shape = m.shape(me.first.face);
    for (int r = 0; r < rows_zero; ++r)
      for (int i = 0; i <= edge_row_last(shape, k, r); ++i)
        rows.push_back({{me.first.face, edge_coefficient(shape, k, me.first.local_edge, i, r), 1.0}});
  }
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()), off.back());
  for (size_t r = 0; r < rows.size(); ++r)
    for (const FaceCoefficient& c : rows[r]) a(static_cast<Eigen::Index>(r), off[c.face] + c.index) += c.value;
  if (a.rows() == 0) return static_cast<int>(a.cols());
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a);
  int rank = 0;
  for (int i = 0; i < svd.singularValues().size(); ++i)
    if (svd.singularValues()[i] > 1e-10 * svd.singularValues()[0]) ++rank;
  return static_cast<int>(a.cols()) - rank;
}

}  // namespace iga::test
