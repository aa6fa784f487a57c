#include "spaces/bspline/knot_vector.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

namespace iga {

KnotVector::KnotVector(int degree, std::vector<double> knots) : degree_(degree), knots_(std::move(knots)) {
  const int p = degree_;
  const int m = size();
  if (p < 0) throw std::invalid_argument("knot vector: degree must be >= 0 (got " + std::to_string(p) + ")");
  if (m < 2 * p + 2)
    throw std::invalid_argument("knot vector: degree " + std::to_string(p) + " needs at least " +
                                std::to_string(2 * p + 2) + " knots (got " + std::to_string(m) + ")");
  for (int i = 0; i < m; ++i) {
    if (!std::isfinite(knots_[i])) throw std::invalid_argument("knot vector: knots must be finite numbers");
    if (i > 0 && knots_[i] < knots_[i - 1])
      throw std::invalid_argument("knot vector: knots must be nondecreasing (knot " + std::to_string(i) + ")");
  }
  if (!(front() < back())) throw std::invalid_argument("knot vector: first and last knot must differ");
  // Open: exactly p+1 copies of each end value.
  if (multiplicity(front()) != p + 1 || multiplicity(back()) != p + 1)
    throw std::invalid_argument("knot vector: first and last knot must be repeated exactly degree+1 = " +
                                std::to_string(p + 1) + " times (open knot vector)");
  if (max_interior_multiplicity() > p + 1)
    throw std::invalid_argument("knot vector: an interior knot is repeated more than degree+1 = " +
                                std::to_string(p + 1) + " times");
  for (int mu = p; mu < num_functions(); ++mu)
    if (knots_[mu] < knots_[mu + 1]) spans_.push_back(mu);
}

KnotVector KnotVector::from_breakpoints(int degree, int regularity, const std::vector<double>& breakpoints) {
  if (regularity < -1 || regularity > degree - 1)
    throw std::invalid_argument("knot vector: regularity must be in -1..degree-1 = " + std::to_string(degree - 1) +
                                " (got " + std::to_string(regularity) + ")");
  if (breakpoints.size() < 2) throw std::invalid_argument("knot vector: need at least two breakpoints");
  for (size_t i = 1; i < breakpoints.size(); ++i)
    if (!(breakpoints[i - 1] < breakpoints[i]))
      throw std::invalid_argument("knot vector: breakpoints must be strictly increasing");
  std::vector<double> knots(degree + 1, breakpoints.front());
  for (size_t i = 1; i + 1 < breakpoints.size(); ++i) knots.insert(knots.end(), degree - regularity, breakpoints[i]);
  knots.insert(knots.end(), degree + 1, breakpoints.back());
  return KnotVector(degree, std::move(knots));
}

KnotVector KnotVector::uniform(int degree, int regularity, int elements, double a, double b) {
  if (elements < 1) throw std::invalid_argument("knot vector: need at least one element");
  std::vector<double> bp(elements + 1);
  for (int i = 0; i <= elements; ++i) bp[i] = a + (b - a) * i / elements;
  bp.back() = b;  // exact end point
  return from_breakpoints(degree, regularity, bp);
}

std::vector<double> KnotVector::breakpoints() const {
  std::vector<double> bp;
  for (double t : knots_)
    if (bp.empty() || t > bp.back()) bp.push_back(t);
  return bp;
}

int KnotVector::find_span(double t) const {
  if (t <= knots_[degree_]) return spans_.front();
  if (t >= back()) return spans_.back();
  // First knot > t among t_p..t_n; the one before it starts a nonzero span containing t.
  const auto first = knots_.begin() + degree_;
  const auto last = knots_.begin() + num_functions() + 1;
  return static_cast<int>(std::upper_bound(first, last, t) - knots_.begin()) - 1;
}

int KnotVector::multiplicity(double t) const {
  const auto range = std::equal_range(knots_.begin(), knots_.end(), t);
  return static_cast<int>(range.second - range.first);
}

int KnotVector::max_interior_multiplicity() const {
  int m = 0;
  for (double t : breakpoints())
    if (t != front() && t != back()) m = std::max(m, multiplicity(t));
  return m;
}

KnotVector KnotVector::with_knots(const std::vector<double>& new_knots) const {
  std::vector<double> sorted = new_knots;
  std::sort(sorted.begin(), sorted.end());
  std::vector<double> merged;
  merged.reserve(knots_.size() + sorted.size());
  std::merge(knots_.begin(), knots_.end(), sorted.begin(), sorted.end(), std::back_inserter(merged));
  return KnotVector(degree_, std::move(merged));
}

KnotVector KnotVector::refined(int multiplicity) const {
  std::vector<double> mid;
  for (int mu : spans_) mid.insert(mid.end(), multiplicity, 0.5 * (knots_[mu] + knots_[mu + 1]));
  return with_knots(mid);
}

bool KnotVector::refines(const KnotVector& coarse) const {
  if (coarse.degree() != degree_ || coarse.front() != front() || coarse.back() != back()) return false;
  for (double t : coarse.breakpoints())
    if (multiplicity(t) < coarse.multiplicity(t)) return false;
  return true;
}

KnotVector KnotVector::on_unit_interval() const {
  const double a = front(), b = back();
  std::vector<double> t(knots());
  for (double& x : t) x = (x - a) / (b - a);
  for (int i = 0; i <= degree(); ++i) {
    t[i] = 0.0;
    t[t.size() - 1 - i] = 1.0;
  }
  return KnotVector(degree(), std::move(t));
}

}  // namespace iga
