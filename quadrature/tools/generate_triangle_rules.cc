/// @file
/// Generator of the compact fully symmetric triangle rules in quadrature/triangle_rule_tables.cpp.
///
/// The extension is .cc on purpose: the library globs quadrature/**/*.cpp, and this program has
/// its own main(). Build and run (about 10-30 minutes on two cores):
///
///   g++ -std=c++20 -O2 -pthread -I/usr/include/eigen3 -o /tmp/generate_triangle_rules
///       quadrature/tools/generate_triangle_rules.cc
///   /tmp/generate_triangle_rules 20 2 > quadrature/triangle_rule_tables.cpp   # max degree, threads
///
/// Method. A rule symmetric under the six barycentric permutations is a union of orbits: the
/// centroid, 3-orbits (a, a, 1-2a) and 6-orbits (a, b, 1-a-b). Such a rule integrates every
/// polynomial of degree <= d exactly iff it integrates the S3-invariant ones exactly, so the
/// unknowns (one weight per orbit plus its parameters) must solve N(d) moment equations, one per
/// invariant basis function. The invariant basis is an orthonormal basis of the range of the
/// symmetrization projector acting on the orthonormal Dubiner basis, so the residual norm is the
/// norm of the quadrature error functional and the equations are well conditioned. Orbit
/// structures are tried in order of increasing point count; for each, seeded random starts are
/// polished by Levenberg-Marquardt in long double. A solution is accepted only with positive
/// weights, points strictly inside, distinct orbits and residual < 1e-15, and it is re-checked on
/// all monomials x^i y^j, i + j <= d. The random stream (mt19937_64, raw bits) and the iteration
/// caps are fixed, so the output does not depend on timing or on the thread count.

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <numbers>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

using Real = long double;
using Mat = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
using Vec = Eigen::Matrix<Real, Eigen::Dynamic, 1>;

/// Value with gradient in (x, y): forward-mode differentiation of the basis.
struct Dual {
  Real v = 0, dx = 0, dy = 0;
};
Dual operator+(Dual a, Dual b) { return {a.v + b.v, a.dx + b.dx, a.dy + b.dy}; }
Dual operator-(Dual a, Dual b) { return {a.v - b.v, a.dx - b.dx, a.dy - b.dy}; }
Dual operator*(Dual a, Dual b) { return {a.v * b.v, a.dx * b.v + a.v * b.dx, a.dy * b.v + a.v * b.dy}; }
Dual operator*(Real s, Dual a) { return {s * a.v, s * a.dx, s * a.dy}; }
Dual operator+(Dual a, Real s) { return {a.v + s, a.dx, a.dy}; }

/// Gauss-Legendre on [0,1] in long double (Newton on the Legendre recurrence).
void gauss01(int n, std::vector<Real>& x, std::vector<Real>& w) {
  x.assign(n, 0);
  w.assign(n, 0);
  for (int i = 0; i < n; ++i) {
    Real t = std::cos(std::numbers::pi_v<Real> * (i + 0.75L) / (n + 0.5L));
    Real p0 = 1, p1 = t, dp = 1;
    for (int it = 0; it < 100; ++it) {
      p0 = 1;
      p1 = t;
      for (int k = 2; k <= n; ++k) {
        const Real p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) p0 = 1;
      dp = n * (t * p1 - p0) / (t * t - 1);
      const Real step = p1 / dp;
      t -= step;
      if (std::fabs(step) < 1e-21L) break;
    }
    x[i] = (1 + t) / 2;
    w[i] = 1 / ((1 - t * t) * dp * dp);
  }
}

/// Collapsed (Duffy) Gauss product rule on the unit triangle, exact for total degree `deg`.
void reference_rule(int deg, std::vector<Real>& px, std::vector<Real>& py, std::vector<Real>& pw) {
  std::vector<Real> s, ws, t, wt;
  gauss01(deg / 2 + 2, s, ws);
  gauss01(deg / 2 + 1, t, wt);
  px.clear();
  py.clear();
  pw.clear();
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = 0; j < t.size(); ++j) {
      px.push_back(s[i]);
      py.push_back(t[j] * (1 - s[i]));
      pw.push_back(ws[i] * wt[j] * (1 - s[i]));
    }
}

/// Unnormalized Dubiner basis of total degree <= d at (x, y), with gradients. The collapsed
/// Legendre factor is written as v^p P_p(u / v) with u = 2x + y - 1, v = 1 - y, which is a
/// polynomial: no singularity at the top vertex, so iterates may leave the triangle safely.
void dubiner(int d, Dual x, Dual y, std::vector<Dual>& out) {
  out.clear();
  const Dual u = 2.0L * x + y + (-1.0L);
  const Dual v = Dual{1, 0, 0} - y;
  const Dual t = 2.0L * y + (-1.0L);
  std::vector<Dual> q(d + 1);
  q[0] = {1, 0, 0};
  if (d >= 1) q[1] = u;
  for (int p = 1; p < d; ++p) q[p + 1] = (Real(2 * p + 1) / (p + 1)) * (u * q[p]) - (Real(p) / (p + 1)) * (v * v * q[p - 1]);
  std::vector<Dual> jac(d + 1);
  for (int p = 0; p <= d; ++p) {
    const Real a = 2 * p + 1;  // Jacobi P^(a,0) in t
    jac[0] = {1, 0, 0};
    if (d - p >= 1) jac[1] = 0.5L * ((a + 2) * t + a);
    for (int n = 2; n <= d - p; ++n) {
      const Real a1 = 2.0L * n * (n + a) * (2 * n + a - 2);
      const Real a2 = (2 * n + a - 1) * a * a;
      const Real a3 = (2 * n + a - 2) * (2 * n + a - 1) * (2 * n + a);
      const Real a4 = 2.0L * (n + a - 1) * (n - 1) * (2 * n + a);
      jac[n] = (1 / a1) * ((a3 * t + a2) * jac[n - 1] - a4 * jac[n - 2]);
    }
    for (int n = 0; n <= d - p; ++n) out.push_back(q[p] * jac[n]);
  }
}

/// Orthonormal basis of the S3-invariant polynomials of degree <= d: psi = V^T (scale .* dubiner).
struct InvariantBasis {
  int degree = 0;
  std::vector<Real> scale;  ///< normalizes the Dubiner functions
  Mat Vt;                   ///< N x K
  Vec moments;              ///< integrals of psi over the unit triangle

  int size() const { return static_cast<int>(Vt.rows()); }

  /// psi_j and its gradient at (x, y).
  void eval(Real x, Real y, Vec& val, Vec& gx, Vec& gy) const {
    std::vector<Dual> phi;
    dubiner(degree, {x, 1, 0}, {y, 0, 1}, phi);
    const int k = static_cast<int>(phi.size());
    Vec pv(k), px(k), py(k);
    for (int i = 0; i < k; ++i) {
      pv(i) = scale[i] * phi[i].v;
      px(i) = scale[i] * phi[i].dx;
      py(i) = scale[i] * phi[i].dy;
    }
    val = Vt * pv;
    gx = Vt * px;
    gy = Vt * py;
  }
};

/// Number of invariant polynomials of degree <= d: monomials e2^i e3^j with 2i + 3j <= d.
int invariant_count(int d) {
  if (d < 0) return 0;
  int n = 0;
  for (int j = 0; 3 * j <= d; ++j) n += (d - 3 * j) / 2 + 1;
  return n;
}

InvariantBasis make_invariant_basis(int d) {
  InvariantBasis basis;
  basis.degree = d;
  std::vector<Real> px, py, pw;
  reference_rule(2 * d, px, py, pw);
  const int npts = static_cast<int>(px.size());
  std::vector<Dual> phi;
  dubiner(d, {0.3L, 0, 0}, {0.3L, 0, 0}, phi);
  const int k = static_cast<int>(phi.size());
  // Values at the reference points and at their six barycentric permutations.
  std::vector<Mat> values(6, Mat(npts, k));
  for (int i = 0; i < npts; ++i) {
    const Real l[3] = {1 - px[i] - py[i], px[i], py[i]};
    static constexpr int perm[6][2] = {{1, 2}, {2, 1}, {0, 1}, {1, 0}, {0, 2}, {2, 0}};
    for (int s = 0; s < 6; ++s) {
      dubiner(d, {l[perm[s][0]], 0, 0}, {l[perm[s][1]], 0, 0}, phi);
      for (int j = 0; j < k; ++j) values[s](i, j) = phi[j].v;
    }
  }
  const Vec w = Eigen::Map<const Vec>(pw.data(), npts);
  basis.scale.resize(k);
  for (int j = 0; j < k; ++j) basis.scale[j] = 1 / std::sqrt((values[0].col(j).array().square() * w.array()).sum());
  const Eigen::Map<const Vec> sc(basis.scale.data(), k);
  for (auto& m : values) m = m * sc.asDiagonal();
  const Mat gram = values[0].transpose() * w.asDiagonal() * values[0];
  const Real orth_err = (gram - Mat::Identity(k, k)).cwiseAbs().maxCoeff();
  if (orth_err > 1e-15L) {
    std::fprintf(stderr, "degree %d: Dubiner basis not orthonormal (%Lg)\n", d, orth_err);
    std::exit(1);
  }
  // Symmetrization projector in the orthonormal coordinates; its range is the invariant space.
  Mat proj = Mat::Zero(k, k);
  for (int s = 0; s < 6; ++s) proj += values[0].transpose() * w.asDiagonal() * values[s];
  proj /= 6;
  proj = (proj + proj.transpose()).eval() / 2;
  Eigen::SelfAdjointEigenSolver<Mat> eig(proj);
  std::vector<int> keep;
  for (int j = 0; j < k; ++j) {
    const Real e = eig.eigenvalues()(j);
    if (e > 0.5L) keep.push_back(j);
    if (std::fabs(e) > 1e-14L && std::fabs(e - 1) > 1e-14L) {
      std::fprintf(stderr, "degree %d: projector eigenvalue %Lg\n", d, e);
      std::exit(1);
    }
  }
  if (static_cast<int>(keep.size()) != invariant_count(d)) {
    std::fprintf(stderr, "degree %d: %zu invariants, expected %d\n", d, keep.size(), invariant_count(d));
    std::exit(1);
  }
  basis.Vt.resize(keep.size(), k);
  for (std::size_t j = 0; j < keep.size(); ++j) basis.Vt.row(j) = eig.eigenvectors().col(keep[j]).transpose();
  basis.moments = basis.Vt * (values[0].transpose() * w);
  return basis;
}

/// Orbit structure: centroid (0 or 1), number of 3-orbits and of 6-orbits.
struct Structure {
  int n0 = 0, n1 = 0, n2 = 0;
  int points() const { return n0 + 3 * n1 + 6 * n2; }
  int unknowns() const { return n0 + 2 * n1 + 3 * n2; }
};

/// Unknown vector layout: [w0] (centroid), then (w, a) per 3-orbit, then (w, a, b) per 6-orbit.
/// Generators: centroid (1/3, 1/3); 3-orbit (x, y) = (a, 1 - 2a); 6-orbit (x, y) = (a, b).
struct Orbit {
  int type;
  Real w, a, b, c;  ///< per-point weight and barycentric coordinates (a, b, c)
};

std::vector<Orbit> unpack(const Structure& st, const Vec& u) {
  std::vector<Orbit> orbits;
  int i = 0;
  if (st.n0) orbits.push_back({0, u(i++), 1.0L / 3, 1.0L / 3, 1.0L / 3});
  for (int k = 0; k < st.n1; ++k, i += 2) orbits.push_back({1, u(i), u(i + 1), u(i + 1), 1 - 2 * u(i + 1)});
  for (int k = 0; k < st.n2; ++k, i += 3) orbits.push_back({2, u(i), u(i + 1), u(i + 2), 1 - u(i + 1) - u(i + 2)});
  return orbits;
}

void residual(const InvariantBasis& basis, const Structure& st, const Vec& u, Vec& r, Mat* jac) {
  const int n = basis.size();
  r = -basis.moments;
  if (jac) jac->setZero(n, u.size());
  Vec val, gx, gy;
  int i = 0;
  auto add = [&](Real x, Real y, Real mult, int cols, Real dxa, Real dya) {
    basis.eval(x, y, val, gx, gy);
    const Real w = u(i);
    r += (mult * w) * val;
    if (!jac) return;
    jac->col(i) = mult * val;
    if (cols == 1) jac->col(i + 1) = (mult * w) * (dxa * gx + dya * gy);
    if (cols == 2) {
      jac->col(i + 1) = (mult * w) * gx;
      jac->col(i + 2) = (mult * w) * gy;
    }
  };
  if (st.n0) {
    add(1.0L / 3, 1.0L / 3, 1, 0, 0, 0);
    i += 1;
  }
  for (int k = 0; k < st.n1; ++k, i += 2) add(u(i + 1), 1 - 2 * u(i + 1), 3, 1, 1, -2);
  for (int k = 0; k < st.n2; ++k, i += 3) add(u(i + 1), u(i + 2), 6, 2, 0, 0);
}

/// Uniform double in [0,1) from raw mt19937_64 bits (portable, unlike std distributions).
Real uniform(std::mt19937_64& rng) { return static_cast<Real>(rng() >> 11) * 0x1.0p-53L; }

Vec random_start(const Structure& st, std::mt19937_64& rng) {
  Vec u(st.unknowns());
  const Real w0 = 0.5L / st.points();
  int i = 0;
  if (st.n0) u(i++) = w0;
  for (int k = 0; k < st.n1; ++k, i += 2) {
    u(i) = w0 * (0.5L + uniform(rng));
    u(i + 1) = 0.01L + 0.48L * uniform(rng);
  }
  for (int k = 0; k < st.n2; ++k, i += 3) {
    u(i) = w0 * (0.5L + uniform(rng));
    Real s = uniform(rng), t = uniform(rng);
    if (s > t) std::swap(s, t);
    u(i + 1) = 0.005L + 0.99L * s;
    u(i + 2) = 0.005L + 0.99L * (t - s);
  }
  return u;
}

bool far_outside(const std::vector<Orbit>& orbits) {
  for (const Orbit& o : orbits)
    if (std::min({o.a, o.b, o.c}) < -0.5L || std::max({o.a, o.b, o.c}) > 1.5L) return true;
  return false;
}

/// Damped Gauss-Newton (Levenberg-Marquardt) from u; returns the final residual norm.
Real levenberg_marquardt(const InvariantBasis& basis, const Structure& st, Vec& u) {
  Vec r, rt;
  Mat J;
  residual(basis, st, u, r, &J);
  Real norm = r.norm(), lambda = 1e-2L;
  for (int it = 0; it < 400 && norm > 1e-19L; ++it) {
    // Fail fast from starts that are not heading for a root.
    if ((it == 60 && norm > 1e-3L) || (it == 150 && norm > 1e-8L) || (it == 250 && norm > 1e-14L)) break;
    const int m = static_cast<int>(J.rows()), n = static_cast<int>(J.cols());
    Vec diag = J.colwise().norm().transpose();
    for (int j = 0; j < n; ++j) diag(j) = std::max(diag(j), 1e-12L);
    bool accepted = false;
    while (!accepted && lambda < 1e12L) {
      Mat A(m + n, n);
      A.topRows(m) = J;
      A.bottomRows(n) = (std::sqrt(lambda) * diag).asDiagonal();
      Vec rhs = Vec::Zero(m + n);
      rhs.head(m) = -r;
      const Vec step = A.colPivHouseholderQr().solve(rhs);
      const Vec trial = u + step;
      if (!far_outside(unpack(st, trial))) {
        residual(basis, st, trial, rt, nullptr);
        if (rt.norm() < norm) {
          u = trial;
          lambda = std::max(lambda / 5, 1e-18L);
          accepted = true;
          break;
        }
      }
      lambda *= 8;
    }
    if (!accepted) break;
    residual(basis, st, u, r, &J);
    norm = r.norm();
  }
  return norm;
}

/// Weights positive, points strictly inside (with margin), orbits non-degenerate and distinct.
bool admissible(const std::vector<Orbit>& orbits) {
  const Real tol = 1e-8L;
  for (const Orbit& o : orbits) {
    if (!(o.w > 0) || std::min({o.a, o.b, o.c}) < tol) return false;
    if (o.type == 1 && std::fabs(o.a - o.c) < 1e-6L) return false;
    if (o.type == 2 && (std::fabs(o.a - o.b) < 1e-6L || std::fabs(o.b - o.c) < 1e-6L || std::fabs(o.a - o.c) < 1e-6L))
      return false;
  }
  for (std::size_t i = 0; i < orbits.size(); ++i)
    for (std::size_t j = i + 1; j < orbits.size(); ++j) {
      if (orbits[i].type != orbits[j].type) continue;
      // Compare as sorted barycentric triples (the orbit's canonical representative).
      Real p[3] = {orbits[i].a, orbits[i].b, orbits[i].c}, q[3] = {orbits[j].a, orbits[j].b, orbits[j].c};
      std::sort(p, p + 3);
      std::sort(q, q + 3);
      if (std::fabs(p[0] - q[0]) + std::fabs(p[1] - q[1]) + std::fabs(p[2] - q[2]) < 1e-6L) return false;
    }
  return true;
}

/// All points of the orbits: (x, y, weight) with (x, y) two of the barycentric coordinates.
std::vector<std::array<Real, 3>> expand(const std::vector<Orbit>& orbits) {
  std::vector<std::array<Real, 3>> pts;
  for (const Orbit& o : orbits) {
    if (o.type == 0) pts.push_back({o.a, o.b, o.w});
    if (o.type == 1) {
      pts.push_back({o.a, o.a, o.w});
      pts.push_back({o.a, o.c, o.w});
      pts.push_back({o.c, o.a, o.w});
    }
    if (o.type == 2) {
      const Real l[3] = {o.a, o.b, o.c};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (i != j) pts.push_back({l[i], l[j], o.w});
    }
  }
  return pts;
}

/// Worst relative monomial error over i + j <= d (exact: i! j! / (i + j + 2)!).
Real monomial_error(const std::vector<Orbit>& orbits, int d) {
  const auto pts = expand(orbits);
  Real worst = 0;
  for (int i = 0; i <= d; ++i)
    for (int j = 0; i + j <= d; ++j) {
      Real exact = 1;
      for (int k = 1; k <= j; ++k) exact *= Real(k) / (i + k);
      exact /= (i + j + 1.0L) * (i + j + 2.0L);
      Real s = 0;
      for (const auto& p : pts) s += p[2] * std::pow(p[0], i) * std::pow(p[1], j);
      worst = std::max(worst, std::fabs(s - exact) / exact);
    }
  return worst;
}

struct Found {
  int degree = -1;  ///< degree actually achieved (may exceed the target)
  int target = 0;
  Structure st;
  std::vector<Orbit> orbits;
  Real residual = 0;
};

/// Candidate structures with `points` points that pass the counting conditions: the invariant
/// equations, those vanishing at the centroid (seen only by the 3- and 6-orbits) and those
/// divisible by the squared discriminant, which vanish on the medians (seen only by the 6-orbits).
std::vector<Structure> structures_with(int points, int d) {
  std::vector<Structure> out;
  for (int n2 = points / 6; n2 >= 0; --n2)
    for (int n0 = 0; n0 <= 1; ++n0) {
      const int rest = points - n0 - 6 * n2;
      if (rest < 0 || rest % 3) continue;
      const Structure st{n0, rest / 3, n2};
      if (st.unknowns() < invariant_count(d)) continue;
      if (2 * st.n1 + 3 * st.n2 < invariant_count(d - 2)) continue;
      if (3 * st.n2 < invariant_count(d - 6)) continue;
      out.push_back(st);
    }
  return out;
}

Found search(int d, int attempts) {
  const InvariantBasis basis = make_invariant_basis(d);
  const InvariantBasis check = make_invariant_basis(d + 1);
  for (int points = 1; points < 400; ++points) {
    for (const Structure& st : structures_with(points, d)) {
      for (int a = 0; a < attempts; ++a) {
        std::mt19937_64 rng(1000003ULL * d + 7919ULL * points + 104729ULL * (st.n0 + 2 * st.n2) + a);
        Vec u = random_start(st, rng);
        const Real norm = levenberg_marquardt(basis, st, u);
        if (!(norm < 1e-15L)) continue;
        const std::vector<Orbit> orbits = unpack(st, u);
        if (!admissible(orbits)) continue;
        if (!(monomial_error(orbits, d) < 1e-16L)) continue;
        Found f{d, d, st, orbits, norm};
        Vec r;
        residual(check, st, u, r, nullptr);  // symmetric rules of even degree are often one higher
        if (r.norm() < 1e-15L && monomial_error(orbits, d + 1) < 1e-16L) f.degree = d + 1;
        std::fprintf(stderr, "degree %2d: %3d points (n0=%d n1=%d n2=%d), attempt %d, residual %.2Le, achieves %d\n",
                     d, points, st.n0, st.n1, st.n2, a, norm, f.degree);
        return f;
      }
    }
  }
  return {};
}

void print_real(Real v) { std::printf("%.21Le", v); }

}  // namespace

int main(int argc, char** argv) {
  const int max_degree = argc > 1 ? std::atoi(argv[1]) : 20;
  const int threads = argc > 2 ? std::atoi(argv[2]) : 1;
  const int attempts = argc > 3 ? std::atoi(argv[3]) : 40;
  std::vector<Found> found(max_degree + 1);
  // Degrees are independent; each is fully determined by its seeds, so threads only save time.
  std::atomic<int> next{max_degree};
  auto worker = [&] {
    for (int d; (d = next--) >= 1;) found[d] = search(d, attempts);
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < std::max(threads, 1); ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();

  std::printf(
      "// Generated by quadrature/tools/generate_triangle_rules.cc (max degree %d, %d attempts per structure).\n"
      "// Do not edit: rerun the generator (see its header) to reproduce or extend the tables.\n"
      "\n"
      "#include \"quadrature/quadrature_rule.hpp\"\n"
      "\n"
      "namespace iga {\n"
      "\n"
      "namespace {\n"
      "\n"
      "/// One orbit of a fully symmetric rule: per-point weight and barycentric coordinates (a, b, c).\n"
      "/// type 0: centroid; 1: the 3 points of (a, a, c); 2: the 6 points of (a, b, c).\n"
      "struct Orbit {\n"
      "  int type;\n"
      "  double w, a, b, c;\n"
      "};\n"
      "\n"
      "struct TabulatedRule {\n"
      "  int degree;  ///< total degree integrated exactly\n"
      "  int points;\n"
      "  int first, count;  ///< range in kOrbits\n"
      "};\n"
      "\n"
      "// clang-format off\n"
      "constexpr Orbit kOrbits[] = {\n",
      max_degree, attempts);
  int first = 0;
  std::vector<std::array<int, 4>> rules;
  for (int d = 1; d <= max_degree; ++d) {
    const Found& f = found[d];
    if (f.degree < 0) continue;
    std::printf("    // degree %d, %d points\n", f.degree, f.st.points());
    for (const Orbit& o : f.orbits) {
      std::printf("    {%d, ", o.type);
      print_real(o.w);
      std::printf(", ");
      print_real(o.a);
      std::printf(", ");
      print_real(o.b);
      std::printf(", ");
      print_real(o.c);
      std::printf("},\n");
    }
    rules.push_back({f.degree, f.st.points(), first, static_cast<int>(f.orbits.size())});
    first += static_cast<int>(f.orbits.size());
  }
  std::printf("};\n\nconstexpr TabulatedRule kRules[] = {\n");
  for (const auto& r : rules) std::printf("    {%d, %d, %d, %d},\n", r[0], r[1], r[2], r[3]);
  std::printf(
      "};\n"
      "// clang-format on\n"
      "\n"
      "QuadratureRule expand(const TabulatedRule& t) {\n"
      "  QuadratureRule rule;\n"
      "  rule.degree = t.degree;\n"
      "  for (int k = t.first; k < t.first + t.count; ++k) {\n"
      "    const Orbit& o = kOrbits[k];\n"
      "    const double l[3] = {o.a, o.b, o.c};\n"
      "    // Points are (x, y) = pairs of barycentric coordinates, so each orbit is exactly symmetric.\n"
      "    const int n = o.type == 0 ? 1 : (o.type == 1 ? 3 : 6);\n"
      "    static constexpr int pairs[6][2] = {{0, 2}, {2, 0}, {0, 1}, {1, 0}, {1, 2}, {2, 1}};\n"
      "    for (int i = 0; i < n; ++i) {\n"
      "      const int* p = o.type == 0 ? pairs[2] : pairs[i];\n"
      "      rule.points.emplace_back(l[p[0]], l[p[1]]);\n"
      "      rule.weights.push_back(o.w);\n"
      "    }\n"
      "  }\n"
      "  return rule;\n"
      "}\n"
      "\n"
      "}  // namespace\n"
      "\n"
      "QuadratureRule triangle_rule_tabulated(int degree) {\n"
      "  // The smallest tabulated rule that is exact for `degree` (a higher-degree rule may be smaller).\n"
      "  const TabulatedRule* best = nullptr;\n"
      "  for (const TabulatedRule& t : kRules)\n"
      "    if (t.degree >= degree && (!best || t.points < best->points)) best = &t;\n"
      "  return best ? expand(*best) : QuadratureRule{};\n"
      "}\n"
      "\n"
      "}  // namespace iga\n");
  return 0;
}
