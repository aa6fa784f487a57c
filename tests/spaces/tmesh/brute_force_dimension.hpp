#pragma once
/// @file
/// Test oracle (notes §3.6): the dimension of the C^(r1,r2) generalized spline space on a T-mesh
/// as the null space of the smoothness constraints on per-cell Bernstein coefficients. Slow
/// (dense SVD); meant for small meshes in tests, never for building spaces.

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "spaces/tmesh/tmesh.hpp"

namespace iga {

/// Jumps of D_t^beta (beta <= r2) across horizontal and D_s^alpha (alpha <= r1) across vertical
/// shared side pieces at 3(n+1) Chebyshev points each; dimension = unknowns - numerical rank with
/// relative tolerance `tol` on the singular values.
inline int brute_force_dimension(const TMesh& mesh, int r1, int r2, double tol = 1e-12) {
  const auto& cells = mesh.cells();
  const int nc = mesh.num_cells();
  const int n1 = mesh.sections()[cells[0].section_s].n, n2 = mesh.sections()[cells[0].section_t].n;
  const int nloc = (n1 + 1) * (n2 + 1);
  std::vector<Eigen::RowVectorXd> rows;
  const int npts = 3 * (std::max(n1, n2) + 1);
  // Cell c's derivative of order `order` across the line (direction `normal_s` = s) at the point
  // with parameters (ts, tt) in [0,1]^2, as a row over its coefficients, scaled by h^order.
  auto row_of = [&](int c, bool normal_s, int order, double ts, double tt, double h, Eigen::RowVectorXd& row, double sign) {
    const SectionBernstein bs(mesh.sections()[cells[c].section_s], mesh.width(c));
    const SectionBernstein bt(mesh.sections()[cells[c].section_t], mesh.height(c));
    const Eigen::MatrixXd Ds = bs.derivatives(ts, normal_s ? order : 0);
    const Eigen::MatrixXd Dt = bt.derivatives(tt, normal_s ? 0 : order);
    const double scale = std::pow(h / (normal_s ? mesh.width(c) : mesh.height(c)), order);
    for (int j = 0; j <= n2; ++j)
      for (int i = 0; i <= n1; ++i)
        row(c * nloc + i + j * (n1 + 1)) += sign * scale * (normal_s ? Ds(order, i) * Dt(0, j) : Ds(0, i) * Dt(order, j));
  };
  for (int a = 0; a < nc; ++a)
    for (int b = 0; b < nc; ++b) {
      const TCell &A = cells[a], &B = cells[b];
      // B above A (horizontal interface) or B right of A (vertical interface).
      for (int dir = 0; dir < 2; ++dir) {
        const bool horizontal = dir == 0;
        if (horizontal ? A.y1 != B.y0 : A.x1 != B.x0) continue;
        const std::int64_t lo = horizontal ? std::max(A.x0, B.x0) : std::max(A.y0, B.y0);
        const std::int64_t hi = horizontal ? std::min(A.x1, B.x1) : std::min(A.y1, B.y1);
        if (lo >= hi) continue;
        const int rmax = horizontal ? r2 : r1;
        const double h = horizontal ? std::min(mesh.height(a), mesh.height(b)) : std::min(mesh.width(a), mesh.width(b));
        for (int k = 0; k < npts; ++k) {
          const double u = 0.5 - 0.5 * std::cos(std::numbers::pi * (k + 0.5) / npts);
          const double z = lo + u * double(hi - lo);
          for (int order = 0; order <= rmax; ++order) {
            Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(nc * nloc);
            if (horizontal) {
              row_of(a, false, order, (z - A.x0) / double(A.x1 - A.x0), 1.0, h, row, 1.0);
              row_of(b, false, order, (z - B.x0) / double(B.x1 - B.x0), 0.0, h, row, -1.0);
            } else {
              row_of(a, true, order, 1.0, (z - A.y0) / double(A.y1 - A.y0), h, row, 1.0);
              row_of(b, true, order, 0.0, (z - B.y0) / double(B.y1 - B.y0), h, row, -1.0);
            }
            rows.push_back(row);
          }
        }
      }
    }
  if (rows.empty()) return nc * nloc;
  Eigen::MatrixXd M(rows.size(), nc * nloc);
  for (size_t k = 0; k < rows.size(); ++k) M.row(k) = rows[k];
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(M);
  const Eigen::VectorXd s = svd.singularValues();
  int rank = 0;
  for (int k = 0; k < s.size(); ++k) rank += s(k) > tol * s(0) ? 1 : 0;
  return nc * nloc - rank;
}

}  // namespace iga
