#include "spaces/surface_patch/spline_direction.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "spaces/bspline/bspline_basis_1d.hpp"

namespace iga {

namespace {

/// The Bézier extraction of the p + 1 B-splines defined by the 2p + 2 knots `local`
/// (t_{μ−p} … t_{μ+p+1}) on their middle span [t_μ, t_{μ+1}]: pad them into an open knot vector
/// (one value below and above, p + 1 times) so that bezier_extraction can run on it.
Eigen::MatrixXd local_extraction(int p, const std::vector<double>& local) {
  const double below = local.front() - 1.0, above = local.back() + 1.0;
  std::vector<double> knots(p + 1, below);
  knots.insert(knots.end(), local.begin(), local.end());
  knots.insert(knots.end(), p + 1, above);
  return bezier_extraction(KnotVector(p, std::move(knots)), (p + 1) + p);
}

}  // namespace

SplineDirection make_spline_direction(int p, bool periodic, const std::vector<double>& breakpoints,
                                      const std::vector<int>& continuity) {
  const int M = static_cast<int>(breakpoints.size()) - 1;
  if (M < 1 || static_cast<int>(continuity.size()) != M)
    throw std::invalid_argument("make_spline_direction: breakpoints and continuities do not match");
  SplineDirection d;
  d.degree = p;
  d.periodic = periodic;
  d.min_continuity = p - 1;
  for (int k = periodic ? 0 : 1; k < M; ++k) d.min_continuity = std::min(d.min_continuity, continuity[k]);
  if (!periodic) {
    std::vector<double> knots(p + 1, 0.0);
    for (int k = 1; k < M; ++k) knots.insert(knots.end(), p - continuity[k], breakpoints[k]);
    knots.insert(knots.end(), p + 1, 1.0);
    const KnotVector kv(p, knots);
    d.open_knots = knots;
    d.num_functions = kv.num_functions();
    d.extraction = bezier_extractions(kv);
    for (int mu : kv.spans()) {
      d.element_lo.push_back(kv[mu]);
      d.element_hi.push_back(kv[mu + 1]);
      std::vector<int> a;
      for (int i = 0; i <= p; ++i) a.push_back(mu - p + i);
      d.active.push_back(std::move(a));
    }
    return d;
  }
  // One period of knots, the seam at 0 first.
  std::vector<double> tau;
  std::vector<int> last_of;  // index of the last copy of breakpoint k
  for (int k = 0; k < M; ++k) {
    tau.insert(tau.end(), p - continuity[k], breakpoints[k]);
    last_of.push_back(static_cast<int>(tau.size()) - 1);
  }
  const int N = static_cast<int>(tau.size());
  if (N < p + 1)
    throw std::invalid_argument("a periodic direction of degree " + std::to_string(p) + " needs at least " +
                                std::to_string(p + 1) + " functions per period (got " + std::to_string(N) +
                                "): use more elements");
  auto t = [&](int i) {
    const int r = static_cast<int>(std::floor(double(i) / N));
    return tau[i - r * N] + r;
  };
  d.num_functions = N;
  for (int k = 0; k < M; ++k) {
    const int mu = last_of[k];
    d.element_lo.push_back(breakpoints[k]);
    d.element_hi.push_back(breakpoints[k + 1]);
    std::vector<double> local;
    for (int i = mu - p; i <= mu + p + 1; ++i) local.push_back(t(i));
    d.extraction.push_back(local_extraction(p, local));
    std::vector<int> a;
    for (int i = 0; i <= p; ++i) a.push_back(((mu - p + i) % N + N) % N);
    d.active.push_back(std::move(a));
  }
  return d;
}

}  // namespace iga
