#include "spaces/g1/bernstein_quad.hpp"

#include "spaces/bspline/bspline_basis_1d.hpp"

namespace iga {

int edge_coefficient(int k, int edge, int m, int r) {
  int i = 0, j = 0;
  switch (((edge % 4) + 4) % 4) {
    case 0: i = m, j = r; break;
    case 1: i = k - r, j = m; break;
    case 2: i = k - m, j = k - r; break;
    default: i = r, j = k - m; break;
  }
  return i + j * (k + 1);
}

std::vector<int> corner_coefficients(int k, int corner) {
  return {edge_coefficient(k, corner, 0, 0), edge_coefficient(k, corner, 1, 0), edge_coefficient(k, corner, 0, 1),
          edge_coefficient(k, corner, 1, 1)};
}

Eigen::MatrixXd bernstein_tensor_jet(int k, const Point2& uv) {
  const Eigen::MatrixXd bu = bernstein_derivatives(k, uv.x(), 1), bv = bernstein_derivatives(k, uv.y(), 1);
  Eigen::MatrixXd out(3, (k + 1) * (k + 1));
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i) {
      const int id = i + j * (k + 1);
      out(0, id) = bu(0, i) * bv(0, j);
      out(1, id) = bu(1, i) * bv(0, j);
      out(2, id) = bu(0, i) * bv(1, j);
    }
  return out;
}

}  // namespace iga
