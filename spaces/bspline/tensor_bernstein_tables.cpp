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

Eigen::SparseMatrix<double> tensor_extraction(const Eigen::MatrixXd& cu, const Eigen::MatrixXd& cv) {
  const Eigen::Index nu = cu.rows(), lu = cu.cols();
  std::vector<Eigen::Triplet<double>> entries;  // (local, active)
  for (Eigen::Index b = 0; b < cv.rows(); ++b)
    for (Eigen::Index a = 0; a < nu; ++a)
      for (Eigen::Index m = 0; m < cv.cols(); ++m)
        for (Eigen::Index l = 0; l < lu; ++l)
          if (cu(a, l) * cv(b, m) != 0.0) entries.emplace_back(l + m * lu, a + b * nu, cu(a, l) * cv(b, m));
  Eigen::SparseMatrix<double> c(lu * cv.cols(), nu * cv.rows());
  c.setFromTriplets(entries.begin(), entries.end());
  c.makeCompressed();
  return c;
}

void add_grid_boundary(SpaceFacts& facts, int nex, int ney, bool open_u, bool open_v) {
  std::vector<BoundaryEdge> bottom, right, top, left;
  if (open_v)
    for (int ex = 0; ex < nex; ++ex) {
      bottom.push_back({ex, 0});
      top.push_back({ex + (ney - 1) * nex, 2});
    }
  if (open_u)
    for (int ey = 0; ey < ney; ++ey) {
      right.push_back({nex - 1 + ey * nex, 1});
      left.push_back({ey * nex, 3});
    }
  for (const auto* side : {&bottom, &right, &top, &left})
    facts.all_boundary_edges.insert(facts.all_boundary_edges.end(), side->begin(), side->end());
  if (open_u) {
    facts.boundary_parts.emplace_back("left", left);
    facts.boundary_parts.emplace_back("right", right);
  }
  if (open_v) {
    facts.boundary_parts.emplace_back("bottom", bottom);
    facts.boundary_parts.emplace_back("top", top);
  }
}

}  // namespace iga
