#include "spaces/g1/bernstein_face.hpp"

#include <cmath>

#include "spaces/bspline/bspline_basis_1d.hpp"

namespace iga {

namespace {

/// Triangle index from the exponents of (λ_0, λ_1, λ_2) = (w, u, v).
int triangle_index_barycentric(int k, const int (&e)[3]) { return bernstein_triangle_index(k, e[1], e[2]); }

/// d-th derivative of x^n.
double power_derivative(double x, int n, int d) {
  if (d > n) return 0.0;
  double f = 1.0;
  for (int s = 0; s < d; ++s) f *= n - s;
  return f * std::pow(x, n - d);
}

double factorial(int n) {
  double f = 1.0;
  for (int s = 2; s <= n; ++s) f *= s;
  return f;
}

/// Value and derivatives up to order 2 of all triangle Bernstein polynomials at uv; out[d] is
/// (value, u, v, uu, uv, vv)[d] for every function.
void triangle_jet(int k, const Point2& uv, Eigen::Ref<Eigen::MatrixXd> out) {
  const double u = uv.x(), v = uv.y(), w = 1.0 - u - v;
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i + j <= k; ++i) {
      const int l = k - i - j;
      const double c = factorial(k) / (factorial(i) * factorial(j) * factorial(l));
      double U[3], V[3], W[3];
      for (int d = 0; d < 3; ++d) {
        U[d] = power_derivative(u, i, d);
        V[d] = power_derivative(v, j, d);
        W[d] = power_derivative(w, l, d);
      }
      // w = 1 - u - v: every derivative of W picks up a factor -1.
      const int id = bernstein_triangle_index(k, i, j);
      out(0, id) = c * U[0] * V[0] * W[0];
      out(1, id) = c * (U[1] * V[0] * W[0] - U[0] * V[0] * W[1]);
      out(2, id) = c * (U[0] * V[1] * W[0] - U[0] * V[0] * W[1]);
      out(3, id) = c * (U[2] * V[0] * W[0] - 2 * U[1] * V[0] * W[1] + U[0] * V[0] * W[2]);
      out(4, id) = c * (U[1] * V[1] * W[0] - U[1] * V[0] * W[1] - U[0] * V[1] * W[1] + U[0] * V[0] * W[2]);
      out(5, id) = c * (U[0] * V[2] * W[0] - 2 * U[0] * V[1] * W[1] + U[0] * V[0] * W[2]);
    }
}

void square_jet(int k, const Point2& uv, int order, Eigen::Ref<Eigen::MatrixXd> out) {
  const Eigen::MatrixXd bu = bernstein_derivatives(k, uv.x(), order), bv = bernstein_derivatives(k, uv.y(), order);
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i) {
      const int id = i + j * (k + 1);
      out(0, id) = bu(0, i) * bv(0, j);
      out(1, id) = bu(1, i) * bv(0, j);
      out(2, id) = bu(0, i) * bv(1, j);
      if (order < 2) continue;
      out(3, id) = bu(2, i) * bv(0, j);
      out(4, id) = bu(1, i) * bv(1, j);
      out(5, id) = bu(0, i) * bv(2, j);
    }
}

}  // namespace

int bernstein_count(CellShape shape, int k) {
  return shape == CellShape::quadrilateral ? (k + 1) * (k + 1) : (k + 1) * (k + 2) / 2;
}

int edge_row_last(CellShape shape, int k, int r) { return shape == CellShape::quadrilateral ? k : k - r; }

int edge_coefficient(CellShape shape, int k, int edge, int m, int r) {
  if (shape == CellShape::triangle) {
    // Edge e runs from corner e to corner e+1; r is the exponent of the opposite corner's λ.
    const int e = ((edge % 3) + 3) % 3;
    int exponents[3];
    exponents[e] = k - m - r;
    exponents[(e + 1) % 3] = m;
    exponents[(e + 2) % 3] = r;
    return triangle_index_barycentric(k, exponents);
  }
  int i = 0, j = 0;
  switch (((edge % 4) + 4) % 4) {
    case 0: i = m, j = r; break;
    case 1: i = k - r, j = m; break;
    case 2: i = k - m, j = k - r; break;
    default: i = r, j = k - m; break;
  }
  return i + j * (k + 1);
}

std::vector<int> corner_coefficients(CellShape shape, int k, int corner) {
  return {edge_coefficient(shape, k, corner, 0, 0), edge_coefficient(shape, k, corner, 1, 0),
          edge_coefficient(shape, k, corner, 0, 1), edge_coefficient(shape, k, corner, 1, 1)};
}

std::vector<int> interior_coefficients(CellShape shape, int k) {
  std::vector<int> out;
  for (int j = 2; j <= k - 2; ++j)
    for (int i = 2; i <= k - 2; ++i) {
      if (shape == CellShape::quadrilateral) out.push_back(i + j * (k + 1));
      else if (k - i - j >= 2) out.push_back(bernstein_triangle_index(k, i, j));
    }
  return out;
}

Eigen::MatrixXd bernstein_jet(CellShape shape, int k, const Point2& uv) {
  Eigen::MatrixXd out(6, bernstein_count(shape, k));
  if (shape == CellShape::quadrilateral) square_jet(k, uv, 1, out);
  else triangle_jet(k, uv, out);
  return out.topRows(3);
}

void bernstein_tables(CellShape shape, int k, const std::vector<Point2>& points, Eigen::MatrixXd (&tables)[6]) {
  const int n = bernstein_count(shape, k), q = static_cast<int>(points.size());
  for (auto& t : tables) t.resize(n, q);
  Eigen::MatrixXd jet(6, n);
  for (int p = 0; p < q; ++p) {
    if (shape == CellShape::quadrilateral) square_jet(k, points[p], 2, jet);
    else triangle_jet(k, points[p], jet);
    for (int d = 0; d < 6; ++d) tables[d].col(p) = jet.row(d).transpose();
  }
}

}  // namespace iga
