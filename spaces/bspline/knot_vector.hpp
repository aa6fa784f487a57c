#pragma once
/// @file
/// Open knot vectors: the 1D ingredient of tensor-product B-splines and NURBS patches.
///
/// A knot vector of degree p is a nondecreasing sequence t_0 <= ... <= t_{m-1} whose first and last
/// values are repeated p+1 times (open / clamped). It defines n = m - p - 1 B-splines
/// N_0..N_{n-1}. A *span* is an index mu with t_mu < t_{mu+1}; the nonzero spans are the elements
/// of the 1D mesh and exactly N_{mu-p}..N_mu are nonzero on span mu.

#include <vector>

namespace iga {

class KnotVector {
 public:
  /// Throws std::invalid_argument unless degree >= 0, the knots are nondecreasing and finite, the
  /// first and last values are repeated exactly degree+1 times, first < last, and no interior knot
  /// is repeated more than degree+1 times.
  KnotVector(int degree, std::vector<double> knots);

  /// Open knot vector of degree p on the increasing `breakpoints` (at least two), each interior
  /// breakpoint repeated p - regularity times, so the splines are C^regularity there.
  /// Requires -1 <= regularity <= p - 1 (std::invalid_argument otherwise).
  static KnotVector from_breakpoints(int degree, int regularity, const std::vector<double>& breakpoints);
  /// `from_breakpoints` on `elements` equal spans of [a, b].
  static KnotVector uniform(int degree, int regularity, int elements, double a = 0.0, double b = 1.0);

  int degree() const { return degree_; }
  const std::vector<double>& knots() const { return knots_; }
  double operator[](int i) const { return knots_[i]; }
  int size() const { return static_cast<int>(knots_.size()); }
  /// Number of B-splines n = size() - degree - 1.
  int num_functions() const { return size() - degree_ - 1; }
  double front() const { return knots_.front(); }
  double back() const { return knots_.back(); }

  /// Distinct knot values, increasing.
  std::vector<double> breakpoints() const;
  /// Indices mu of the nonzero spans [t_mu, t_mu+1), increasing: one per 1D element.
  const std::vector<int>& spans() const { return spans_; }
  int num_spans() const { return static_cast<int>(spans_.size()); }
  /// The nonzero span containing t: t_mu <= t < t_mu+1, with t >= back() giving the last span and
  /// t <= front() the first (so every t has a span with p+1 nonzero functions).
  int find_span(double t) const;
  /// Number of times the value t occurs among the knots (0 when t is not a knot).
  int multiplicity(double t) const;
  /// Largest multiplicity of an interior breakpoint (0 when there is none).
  int max_interior_multiplicity() const;

  /// This knot vector with every knot of `new_knots` added (merged in order).
  KnotVector with_knots(const std::vector<double>& new_knots) const;
  /// Uniform refinement: the midpoint of every nonzero span inserted `multiplicity` times
  /// (p - r keeps the regularity r of the interior knots).
  KnotVector refined(int multiplicity) const;

  /// The same knots mapped affinely onto [0, 1], the end knots exactly 0 and 1.
  KnotVector on_unit_interval() const;
  /// True when every breakpoint of `coarse` is a knot of this vector with at least the same
  /// multiplicity (then the spline space of `coarse` is contained in this one).
  bool refines(const KnotVector& coarse) const;

 private:
  int degree_;
  std::vector<double> knots_;
  std::vector<int> spans_;
};

}  // namespace iga
