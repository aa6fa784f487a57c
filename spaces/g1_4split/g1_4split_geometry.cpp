#include "spaces/g1_4split/g1_4split_geometry.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <limits>

#include "config/errors.hpp"
#include "quadrature/quadrature_rule.hpp"
#include "spaces/bspline/bspline_basis_1d.hpp"
#include "spaces/g1_4split/face_function.hpp"

namespace iga {

FaceGeometry bilinear_geometry(const PatchMesh& mesh, const SplitBSpline& b) {
  const int n = b.size();
  const Eigen::VectorXd g = b.greville();
  FaceGeometry out;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    std::vector<double> xs(n * n), ys(n * n);
    for (int q = 0; q < n; ++q)
      for (int p = 0; p < n; ++p) {
        const Point2 x = mesh.map(f, Point2(g(p), g(q))).x;
        xs[p + q * n] = x.x();
        ys[p + q * n] = x.y();
      }
    out.x.push_back(interpolate_face(b, xs));
    out.y.push_back(interpolate_face(b, ys));
  }
  return out;
}

namespace {

/// Mass matrix of the univariate basis on [0,1] (exact Gauss rule per half).
Eigen::MatrixXd mass_1d(const SplitBSpline& b) {
  const QuadratureRule g = gauss_legendre(b.degree() + 1);
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(b.size(), b.size());
  for (int h = 0; h < 2; ++h)
    for (int q = 0; q < g.size(); ++q) {
      const Eigen::RowVectorXd N = b.derivatives(0.5 * (h + g.points[q].x()), 0, h).row(0);
      M += 0.5 * g.weights[q] * N.transpose() * N;
    }
  return M;
}

}  // namespace

Eigen::MatrixXd face_tensor_product(const Eigen::MatrixXd& Gu, const Eigen::MatrixXd& Gv) {
  const int s = static_cast<int>(Gu.rows());
  Eigen::MatrixXd E(s * s, s * s);
  for (int j = 0; j < s; ++j)
    for (int i = 0; i < s; ++i)
      for (int l = 0; l < s; ++l)
        for (int k = 0; k < s; ++k) E(i + j * s, k + l * s) = Gu(i, k) * Gv(j, l);
  return E;
}

Eigen::SparseMatrix<double> block_diagonal(const Eigen::MatrixXd& face_matrix, int faces) {
  const int fs = static_cast<int>(face_matrix.rows());
  std::vector<Eigen::Triplet<double>> trip;
  for (int f = 0; f < faces; ++f)
    for (int r = 0; r < fs; ++r)
      for (int c = 0; c < fs; ++c)
        if (face_matrix(r, c) != 0.0) trip.emplace_back(f * fs + r, f * fs + c, face_matrix(r, c));
  Eigen::SparseMatrix<double> M(faces * fs, faces * fs);
  M.setFromTriplets(trip.begin(), trip.end());
  return M;
}

FaceGeometry project_geometry(const G14Basis& basis, const FaceGeometry& broken) {
  const SplitBSpline& b = basis.bspline;
  const int fs = b.face_size(), F = static_cast<int>(broken.x.size());
  const Eigen::MatrixXd M1 = mass_1d(b);
  const Eigen::SparseMatrix<double> M = block_diagonal(face_tensor_product(M1, M1), F);
  const Eigen::SparseMatrix<double>& B = basis.functions;
  const Eigen::SparseMatrix<double> MB = M * B;
  const Eigen::SparseMatrix<double> A = Eigen::SparseMatrix<double>(B.transpose()) * MB;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success) throw NumericalError("g1_4split: geometry projection failed (singular Gram matrix)");
  FaceGeometry out;
  for (int comp = 0; comp < 2; ++comp) {
    Eigen::VectorXd g(F * fs);
    for (int f = 0; f < F; ++f) g.segment(f * fs, fs) = comp == 0 ? broken.x[f] : broken.y[f];
    const Eigen::VectorXd c = solver.solve(Eigen::VectorXd(MB.transpose() * g));
    const Eigen::VectorXd h = B * c;
    for (int f = 0; f < F; ++f) (comp == 0 ? out.x : out.y).push_back(h.segment(f * fs, fs));
  }
  return out;
}

Eigen::VectorXd subdivided_face(const SplitBSpline& b, const Eigen::VectorXd& coarse, int c) {
  const int n = b.size();
  const Eigen::VectorXd g = b.greville();
  static const Point2 corner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  // Child c: corner c of the parent, halves of its edges c (child u) and c-1 (child v).
  const Point2 p0 = corner[c], e1 = 0.5 * (corner[(c + 1) % 4] - p0), e2 = 0.5 * (corner[(c + 3) % 4] - p0);
  std::vector<double> values(n * n);
  for (int q = 0; q < n; ++q)
    for (int p = 0; p < n; ++p) {
      const Point2 uv = p0 + g(p) * e1 + g(q) * e2;
      values[p + q * n] = face_jet(b, coarse, uv)(0);
    }
  return interpolate_face(b, values);
}

FaceGeometry subdivide_geometry(const SplitBSpline& b, const FaceGeometry& coarse) {
  FaceGeometry out;
  for (std::size_t f = 0; f < coarse.x.size(); ++f)
    for (int c = 0; c < 4; ++c) {
      out.x.push_back(subdivided_face(b, coarse.x[f], c));
      out.y.push_back(subdivided_face(b, coarse.y[f], c));
    }
  return out;
}

namespace {

/// Bernstein coefficients of the product of two tensor Bernstein polynomials.
Eigen::MatrixXd bernstein_product(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  const int a1 = static_cast<int>(A.rows()) - 1, b1 = static_cast<int>(A.cols()) - 1;
  const int a2 = static_cast<int>(B.rows()) - 1, b2 = static_cast<int>(B.cols()) - 1;
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(a1 + a2 + 1, b1 + b2 + 1);
  for (int i1 = 0; i1 <= a1; ++i1)
    for (int i2 = 0; i2 <= a2; ++i2) {
      const double wu = binomial(a1, i1) * binomial(a2, i2) / binomial(a1 + a2, i1 + i2);
      for (int j1 = 0; j1 <= b1; ++j1)
        for (int j2 = 0; j2 <= b2; ++j2)
          P(i1 + i2, j1 + j2) += wu * binomial(b1, j1) * binomial(b2, j2) / binomial(b1 + b2, j1 + j2) * A(i1, j1) * B(i2, j2);
    }
  return P;
}

/// de Casteljau split of each column (direction of rows) at 1/2: the two halves.
std::pair<Eigen::MatrixXd, Eigen::MatrixXd> split_rows(const Eigen::MatrixXd& C) {
  const int p = static_cast<int>(C.rows()) - 1;
  Eigen::MatrixXd left(C.rows(), C.cols()), right(C.rows(), C.cols()), w = C;
  for (int r = 0; r <= p; ++r) {
    left.row(r) = w.row(0);
    right.row(p - r) = w.row(p - r);
    for (int i = 0; i < p - r; ++i) w.row(i) = 0.5 * (w.row(i) + w.row(i + 1));
  }
  return {left, right};
}

/// Certified lower bound of a tensor Bernstein polynomial's minimum when positive, else <= 0.
double certified_min(const Eigen::MatrixXd& C, int depth) {
  const double lo = C.minCoeff();
  if (lo > 0.0) return lo;
  const int p = static_cast<int>(C.rows()) - 1, q = static_cast<int>(C.cols()) - 1;
  if (std::min({C(0, 0), C(p, 0), C(0, q), C(p, q)}) <= 0.0 || depth == 0) return std::min(lo, 0.0);
  const auto [a, b] = split_rows(C);
  double m = 1e300;
  for (const Eigen::MatrixXd& h : {a, b}) {
    const auto [c, d] = split_rows(h.transpose());
    m = std::min({m, certified_min(c.transpose(), depth - 1), certified_min(d.transpose(), depth - 1)});
    if (m <= 0.0) return m;
  }
  return m;
}

}  // namespace

double certified_jacobian_bound(const SplitBSpline& b, const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
  const int k = b.degree();
  double diameter2 = 0.0;
  for (int i = 0; i < x.size(); ++i)
    for (int j = 0; j < i; ++j) diameter2 = std::max(diameter2, std::pow(x(i) - x(j), 2) + std::pow(y(i) - y(j), 2));
  double bound = 1e300;
  for (int hv = 0; hv < 2; ++hv)
    for (int hu = 0; hu < 2; ++hu) {
      const Eigen::MatrixXd X = piece_bernstein(b, x, hu, hv), Y = piece_bernstein(b, y, hu, hv);
      // Derivatives on the sub-square (local coordinates; the factor 4 of the halving is dropped).
      const Eigen::MatrixXd Xu = k * (X.bottomRows(k) - X.topRows(k)), Yu = k * (Y.bottomRows(k) - Y.topRows(k));
      const Eigen::MatrixXd Xv = k * (X.rightCols(k) - X.leftCols(k)), Yv = k * (Y.rightCols(k) - Y.leftCols(k));
      const Eigen::MatrixXd det = bernstein_product(Xu, Yv) - bernstein_product(Yu, Xv);
      bound = std::min(bound, 4.0 * certified_min(det, 6) / std::max(diameter2, 1e-300));
      if (bound <= 0.0) return bound;
    }
  return bound;
}

double largest_jacobian_ratio(const SplitBSpline& b, const FaceGeometry& g) {
  constexpr int kSamples = 24;  // intervals per direction; the split lines (1/2) are sampled
  std::vector<Point2> points;
  for (int i = 0; i <= kSamples; ++i)
    for (int j = 0; j <= kSamples; ++j) points.emplace_back(double(i) / kSamples, double(j) / kSamples);
  Eigen::MatrixXd t[6];
  tensor_tables(b, points, t);
  double worst = 1.0;
  for (std::size_t f = 0; f < g.x.size(); ++f) {
    const Eigen::RowVectorXd xu = g.x[f].transpose() * t[1], xv = g.x[f].transpose() * t[2];
    const Eigen::RowVectorXd yu = g.y[f].transpose() * t[1], yv = g.y[f].transpose() * t[2];
    const Eigen::RowVectorXd det = xu.cwiseProduct(yv) - xv.cwiseProduct(yu);
    if (det.minCoeff() <= 0.0) return std::numeric_limits<double>::infinity();
    worst = std::max(worst, det.maxCoeff() / det.minCoeff());
  }
  return worst;
}

void check_face_geometry(const SplitBSpline& b, const Eigen::VectorXd& x, const Eigen::VectorXd& y, int f,
                         const std::string& mesh_name, bool fair) {
  // A margin: det J vanishing at a point (q0 blending) leaves Bernstein coefficients at round-off.
  if (certified_jacobian_bound(b, x, y) <= 1e-8)
    throw InputError("g1_4split geometry of '" + mesh_name + "': det J of the " + (fair ? "fair" : "least-squares") +
                     " map is not certified positive on face " + std::to_string(f) +
                     (fair ? " (the map is not injective; try space.geometry_fit: least_squares)"
                           : " (the mesh does not fit the symmetric gluing there: an extraordinary vertex needs its "
                             "edges spread like a regular fan, a valence-4 vertex straight mesh lines)"));
}

}  // namespace iga
