// The paper's worked example (notes §9.1, §12.3–12.5): three quads around a valence-3 vertex with
// the paper's own face order σ1 = [0,3,4,1], σ2 = [0,1,5,2], σ3 = [0,2,6,3], biquartic, C1 across
// the split lines, q0 gluing. The printed basis functions satisfy every C0 and G1 row; the two
// printed combinations that the notes found defective do not; the space has dimension 141 with
// the local counts 6 (centre), 4 per other vertex, 5 per interior edge, 8 per boundary edge.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <map>
#include <utility>

#include "spaces/g1_4split/g1_4split_basis.hpp"

namespace iga {
namespace {

/// A function on the three faces as B-spline coefficients: {(face, i, j) -> value}, N_ij = N_i(u) N_j(v).
using Coefficients = std::map<std::tuple<int, int, int>, double>;

QuadTopology paper_mesh() { return QuadTopology(7, {{0, 3, 4, 1}, {0, 1, 5, 2}, {0, 2, 6, 3}}, "round corner"); }

/// Largest scaled residual of the C0 + G1 rows on the function.
double residual(const Coefficients& f) {
  const QuadTopology t = paper_mesh();
  const SplitBSpline b(4, 1);  // m = 7: 8 x 8 coefficients per face
  const Eigen::MatrixXd C(global_constraints(t, symmetric_gluing(t, Blending::q0), b));
  Eigen::VectorXd x = Eigen::VectorXd::Zero(C.cols());
  for (const auto& [key, value] : f) {
    const auto [face, i, j] = key;
    x(face * b.face_size() + i + j * b.size()) += value;
  }
  double worst = 0.0;
  for (int r = 0; r < C.rows(); ++r) worst = std::max(worst, std::abs(C.row(r).dot(x)) / C.row(r).cwiseAbs().sum());
  return worst / x.cwiseAbs().maxCoeff();
}

/// c·(a on face) added to f.
void add(Coefficients& f, int face, const Coefficients& a, double c = 1.0) {
  for (const auto& [key, value] : a) f[{face, std::get<1>(key), std::get<2>(key)}] += c * value;
}

Coefficients on(std::initializer_list<std::tuple<int, int, double>> terms) {
  Coefficients f;
  for (const auto& [i, j, v] : terms) f[{0, i, j}] += v;
  return f;
}

}  // namespace

TEST(G14PaperExample, PrintedBasisFunctionsAreG1) {
  // Derivative function at the centre: [A, B, −A − B].
  const Coefficients A = on({{1, 0, 1}, {2, 0, 10. / 3}, {3, 0, 16. / 3}, {4, 0, 16. / 3}});
  const Coefficients B = on({{0, 1, -1}, {0, 2, -10. / 3}, {0, 3, -16. / 3}, {0, 4, -16. / 3},
                             {1, 2, -14. / 3}, {1, 3, -32. / 3}, {1, 4, -32. / 3}});
  Coefficients derivative;
  add(derivative, 0, A);
  add(derivative, 1, B);
  add(derivative, 2, A, -1);
  add(derivative, 2, B, -1);
  EXPECT_LT(residual(derivative), 1e-13);

  // Twist functions [Xa, Xb, Xa + N11 + Xb] and its cyclic shifts.
  const Coefficients Xa = on({{2, 0, -4. / 3}, {3, 0, -8. / 3}, {4, 0, -8. / 3}});
  const Coefficients Xb = on({{0, 2, -4. / 3}, {0, 3, -8. / 3}, {0, 4, -8. / 3},
                              {1, 2, -4. / 3}, {1, 3, -16. / 3}, {1, 4, -16. / 3}});
  for (int shift = 0; shift < 3; ++shift) {
    Coefficients twist;
    add(twist, shift, Xa);
    add(twist, (shift + 1) % 3, Xb);
    add(twist, (shift + 2) % 3, Xa);
    add(twist, (shift + 2) % 3, Xb);
    add(twist, (shift + 2) % 3, on({{1, 1, 1}}));
    EXPECT_LT(residual(twist), 1e-13) << shift;
  }

  // At the boundary vertex γ1 (shared by σ1 and σ2) and along the edge τ1 = γγ1.
  const std::vector<std::pair<Coefficients, Coefficients>> edge_and_vertex = {
      {on({{0, 6, 1}}), on({{6, 0, 1}, {6, 1, 2}})},
      {on({{1, 7, 1}}), on({{7, 1, -1}})},
      {on({{1, 6, 1}}), on({{6, 1, -1}})},
      {on({{0, 7, 1}, {1, 7, 1}}), on({{7, 0, 1}, {7, 1, 1}})},
      {on({{1, 2, -1}}), on({{2, 1, 1}})},
      {on({{1, 3, -1}}), on({{3, 1, 1}})},
      {on({{1, 4, -1}}), on({{4, 1, 1}})},
      {on({{1, 5, -1}}), on({{5, 1, 1}})},
      {on({{0, 5, 1}, {1, 5, 2}}), on({{5, 0, 1}})}};
  for (std::size_t n = 0; n < edge_and_vertex.size(); ++n) {
    Coefficients f;
    add(f, 0, edge_and_vertex[n].first);
    add(f, 1, edge_and_vertex[n].second);
    EXPECT_LT(residual(f), 1e-13) << n;
  }

  // Not G1: [Xa, 0, Xb] (a term lost in the printed text) and [N07, N70, 0] (cross derivatives −8 N7
  // on both sides).
  Coefficients lost;
  add(lost, 0, Xa);
  add(lost, 2, Xb);
  EXPECT_GT(residual(lost), 1e-3);
  Coefficients plain;
  add(plain, 0, on({{0, 7, 1}}));
  add(plain, 1, on({{7, 0, 1}}));
  EXPECT_GT(residual(plain), 1e-3);
}

TEST(G14PaperExample, DimensionAndLocalCounts) {
  const QuadTopology t = paper_mesh();
  const G14Basis basis = build_g14_basis(t, symmetric_gluing(t, Blending::q0), 4, 1);
  EXPECT_EQ(basis.dimension(), 141);
  // Vertices: 6 at the centre, 4 at each of the 6 boundary vertices; edges: 5 per interior edge,
  // 8 per boundary edge; faces: 16 each (notes §12.5).
  const G14Numbering& n = basis.numbering;
  EXPECT_EQ(n.vertex_first.back(), 6 + 6 * 4);
  EXPECT_EQ(n.edge_first.back() - n.vertex_first.back(), 3 * 5 + 6 * 8);
  EXPECT_EQ(t.num_faces() * n.per_face, 3 * 16);
}

}  // namespace iga
