#include "spaces/bspline/tensor_bernstein_tables.hpp"

#include "spaces/bspline/bspline_basis_1d.hpp"

namespace iga {

int tabulate_tensor_bernstein(int pu, int pv, const std::vector<Point2>& points, LocalTables& tables) {
  const int q = static_cast<int>(points.size());
  const int du[6] = {0, 1, 0, 2, 1, 0}, dv[6] = {0, 0, 1, 0, 1, 2};
  for (auto& table : tables) table.resize((pu + 1) * (pv + 1), q);
  for (int k = 0; k < q; ++k) {
    const Eigen::MatrixXd bu = bernstein_derivatives(pu, points[k].x(), 2);
    const Eigen::MatrixXd bv = bernstein_derivatives(pv, points[k].y(), 2);
    for (int d = 0; d < 6; ++d)
      for (int b = 0; b <= pv; ++b)
        for (int a = 0; a <= pu; ++a) tables[d](a + b * (pu + 1), k) = bu(du[d], a) * bv(dv[d], b);
  }
  return 2;
}

}  // namespace iga
