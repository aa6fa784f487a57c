#pragma once
/// @file
/// Quadrature rules on reference cells.
///
/// Reference cells used throughout iga-run:
///  - quadrilateral: the unit square [0,1]^2;
///  - triangle: the unit triangle with vertices (0,0), (1,0), (0,1).
/// Weights of a cell rule sum to the area of the reference cell (1 or 1/2).
/// Weights of an edge rule are with respect to the edge parameter t in [0,1] and sum to 1.

#include <Eigen/Core>
#include <memory>
#include <vector>

namespace iga {

using Point2 = Eigen::Vector2d;

/// Points and weights, plus the polynomial degree the rule integrates exactly.
struct QuadratureRule {
  std::vector<Point2> points;
  std::vector<double> weights;
  int degree = 0;  ///< exact for polynomials of total (triangle) or per-direction (quad) degree <= this

  int size() const { return static_cast<int>(points.size()); }
};

using RulePtr = std::shared_ptr<const QuadratureRule>;

/// Gauss–Legendre rule with n points on [0,1] (stored in the x coordinate; y = 0).
/// Exact for polynomials of degree 2n-1.
QuadratureRule gauss_legendre(int n);

/// Smallest Gauss–Legendre rule on [0,1] exact for degree `degree`.
QuadratureRule gauss_legendre_for_degree(int degree);

/// Tensor Gauss rule on [0,1]^2 exact for polynomials of degree `degree` in each variable.
QuadratureRule tensor_gauss(int degree);

/// Rule on the unit triangle exact for all polynomials of total degree `degree` (any degree >= 0).
/// Symmetric under the six permutations of the barycentric coordinates; all weights positive,
/// all points inside the triangle.
QuadratureRule triangle_rule(int degree);

/// Symmetrized collapsed (Duffy) Gauss product rule on the unit triangle, exact for total degree
/// `degree`. Valid for any degree but larger than the tabulated rules: the fallback of triangle_rule.
QuadratureRule triangle_rule_collapsed(int degree);

/// Smallest precomputed compact fully symmetric rule on the unit triangle with degree >= `degree`
/// (quadrature/triangle_rule_tables.cpp); an empty rule when no tabulated rule reaches that degree.
QuadratureRule triangle_rule_tabulated(int degree);

/// The rule `ref` (on the unit triangle) mapped affinely onto the triangle (a, b, c);
/// weights are scaled by the area ratio, so they sum to the area of (a, b, c).
QuadratureRule map_to_triangle(const QuadratureRule& ref, const Point2& a, const Point2& b, const Point2& c);

/// The rule `ref` (on [0,1]^2) mapped affinely onto the axis-aligned box [lo, hi].
QuadratureRule map_to_box(const QuadratureRule& ref, const Point2& lo, const Point2& hi);

/// Concatenation of rules on disjoint sub-cells: a composite rule for a macro-element.
/// The degree of the result is the smallest degree among the parts.
QuadratureRule concatenate(const std::vector<QuadratureRule>& parts);

}  // namespace iga
