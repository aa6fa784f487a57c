#include "geometry/rsd/paper_edge_solver.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "config/errors.hpp"

namespace iga::rsd {

namespace {

using Q = GiNaC::numeric;
using QPoly = Poly<Q>;

QPoly shifted(const QPoly& p, int e) {  // t^e p(t)
  return QPoly::monomial(e) * p;
}

QPoly scaled(const QPoly& p, const Q& factor) { return factor * p; }

/// Rounds x to a multiple of 2^−30, as an exact rational.
Q rational(double x) {
  const double scale = std::ldexp(1.0, 30);
  return Q(static_cast<long>(std::llround(x * scale))) / Q(1L << 30);
}

Vec3<Q> rational(const Eigen::Vector3d& x) { return {rational(x[0]), rational(x[1]), rational(x[2])}; }

Eigen::Vector3d to_double(const Vec3<Q>& x) { return {x[0].to_double(), x[1].to_double(), x[2].to_double()}; }

Q dot3(const Vec3<Q>& a, const Vec3<Q>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

GcdCofactors<Q> gcd_cofactors(const std::vector<QPoly>& a) {
  const int K = static_cast<int>(a.size());
  std::vector<QPoly> p = a;
  // X is K×K with p = a·X (p_c = Σ_r a_r X[r][c]); columns move with the entries of p.
  std::vector<std::vector<QPoly>> X(K, std::vector<QPoly>(K));
  for (int r = 0; r < K; ++r) X[r][r] = QPoly::constant(Q(1));
  GcdCofactors<Q> result;
  for (;;) {
    // (N) normalise the nonzero entries to monic (zero entries untouched).
    for (int c = 0; c < K; ++c) {
      if (p[c].is_zero()) continue;
      const Q inverse = Q(1) / p[c].lead();
      p[c] = scaled(p[c], inverse);
      for (int r = 0; r < K; ++r) X[r][c] = scaled(X[r][c], inverse);
    }
    // (R) zeros first, then by non-increasing degree (stable).
    std::vector<int> order(K);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int x, int y) {
      const int dx = p[x].is_zero() ? 1 << 20 : p[x].degree(), dy = p[y].is_zero() ? 1 << 20 : p[y].degree();
      return dx > dy;
    });
    std::vector<QPoly> p2(K);
    std::vector<std::vector<QPoly>> X2(K, std::vector<QPoly>(K));
    for (int c = 0; c < K; ++c) {
      p2[c] = p[order[c]];
      for (int r = 0; r < K; ++r) X2[r][c] = X[r][order[c]];
    }
    p = std::move(p2);
    X = std::move(X2);
    bool done = true;
    for (int c = 0; c + 1 < K; ++c) done = done && p[c].is_zero();
    if (done) break;
    // (D) cancel the leading term of the first nonzero entry with the next one.
    int L = 0;
    while (p[L].is_zero()) ++L;
    const int e = p[L].degree() - p[L + 1].degree();
    p[L] = p[L] - shifted(p[L + 1], e);
    for (int r = 0; r < K; ++r) X[r][L] = X[r][L] - shifted(X[r][L + 1], e);
    ++result.steps;
  }
  result.gcd = p[K - 1];
  for (int r = 0; r < K; ++r) result.q.push_back(X[r][K - 1]);  // column K (the paper prints row K)
  return result;
}

VecPoly<Q> solve_edge_paper(RsdTuple tuple, const EdgeEndData<Q>& data) {
  const EdgeCurves<Q> curves = edge_curves(tuple, data);
  const VecPoly<Q> w = curves.w();
  const auto [delta, remainder] = divide(curves.Delta(), edge_bubble<Q>());
  if (!remainder.is_zero()) throw NumericalError("paper method: Δ is not divisible by t²(1−t)²");
  if (delta.is_zero()) return {};
  const auto cof = gcd_cofactors({w[0], w[1], w[2]});
  const auto [zeta, rest] = divide(delta, cof.gcd);
  if (!rest.is_zero()) throw NumericalError("paper method: δ is not divisible by gcd(w)");
  return {zeta * cof.q[0], zeta * cof.q[1], zeta * cof.q[2]};
}

std::vector<VecPoly<double>> paper_corrections(RsdTuple tuple, const TriangleSurfaceMesh& mesh,
                                               const std::vector<SurfaceEdge>& edges, FirstOrderData& data) {
  std::vector<Vec3<Q>> p, n;
  for (int v = 0; v < mesh.num_points(); ++v) {
    p.push_back(rational(mesh.points[v]));
    n.push_back(rational(mesh.normals[v]));
  }
  auto g = [&](int a, int b) {
    const Vec3<Q> chord{p[b][0] - p[a][0], p[b][1] - p[a][1], p[b][2] - p[a][2]};
    const Q factor = dot3(chord, n[a]) / dot3(n[a], n[a]);
    return Vec3<Q>{chord[0] - factor * n[a][0], chord[1] - factor * n[a][1], chord[2] - factor * n[a][2]};
  };
  data = FirstOrderData{};
  for (const auto& x : p) data.f.push_back(to_double(x));
  for (const auto& x : n) data.n.push_back(to_double(x).normalized());
  for (const auto& e : edges) {
    data.g_of(e.i, e.j) = to_double(g(e.i, e.j));
    data.g_of(e.j, e.i) = to_double(g(e.j, e.i));
  }
  std::vector<VecPoly<double>> z(edges.size());
  for (std::size_t m = 0; m < edges.size(); ++m) {
    const SurfaceEdge& e = edges[m];
    if (!e.interior()) continue;
    const EdgeEndData<Q> end{p[e.i], p[e.j], g(e.i, e.j), g(e.j, e.i), g(e.i, e.k), g(e.j, e.k), g(e.i, e.kbar),
                             g(e.j, e.kbar)};
    const VecPoly<Q> exact = solve_edge_paper(tuple, end);
    for (int c = 0; c < 3; ++c) {
      std::vector<double> coefficients;
      for (const Q& x : exact[c].c) coefficients.push_back(x.to_double());
      z[m][c] = Poly<double>(coefficients);
    }
  }
  return z;
}

}  // namespace iga::rsd
