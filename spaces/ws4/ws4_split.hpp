#pragma once
/// @file
/// The WS4 split of the reference triangle p1 = (0,0), p2 = (1,0), p3 = (0,1): every segment
/// joining two of the 12 boundary points (vertices and quarter points of the edges). Built once,
/// in exact integer barycentric arithmetic; the split of any triangle is its affine image.
///
/// Reference coordinates (x, y) are the barycentric coordinates (lambda2, lambda3).

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "quadrature/quadrature_rule.hpp"

namespace iga::ws4 {

/// Homogeneous integer barycentric triple; a point (normalised: gcd 1, positive sum) or a line
/// {lambda : c . lambda = 0} (normalised: gcd 1, first nonzero entry positive).
using Triple = std::array<long long, 3>;

/// A convex region of the split: counterclockwise vertex indices, area and an interior point.
struct SplitRegion {
  std::vector<int> vertices;
  double area = 0.0;
  Point2 centroid = Point2::Zero();
};

class Ws4Split {
 public:
  /// The split of the reference triangle (built on first use, then shared; thread-safe).
  static const Ws4Split& reference();

  /// The 12 boundary points in the order p1, p2, p3, q31, q3, q32, q12, q1, q13, q21, q2, q23
  /// (barycentric x 4; q_kl on the edge opposite p_k, a quarter away from p_l; q_k midpoints).
  static const std::array<Triple, 12>& boundary_points();
  /// Cartesian reference coordinates of boundary point k.
  static Point2 boundary_point(int k);

  /// All 39 lines: the 3 edges first (lambda3 = 0, lambda1 = 0, lambda2 = 0), then 36 cross-cuts.
  const std::vector<Triple>& lines() const { return lines_; }
  /// The 178 split vertices (exact barycentric).
  const std::vector<Triple>& vertices() const { return vertices_; }
  Point2 vertex_point(int v) const;
  /// Number of split lines through each vertex (edges of the triangle included).
  const std::vector<int>& lines_through_vertex() const { return lines_through_; }
  /// Segments of the planar graph (pairs of vertex indices), 429.
  const std::vector<std::array<int, 2>>& segments() const { return segments_; }
  /// The 252 convex regions.
  const std::vector<SplitRegion>& regions() const { return regions_; }
  /// Fan triangulation of the regions: 342 triangles (vertex indices) and the region of each.
  const std::vector<std::array<int, 3>>& fan_triangles() const { return fan_; }
  const std::vector<int>& fan_region() const { return fan_region_; }

  /// Region containing reference point x. Points on split lines or on the boundary of the triangle
  /// take the region entered from x in the direction toward the generic interior point
  /// (0.3137, 0.2718) (the one-sided rule: a boundary point gets a region inside the triangle).
  /// Points slightly outside the triangle (round-off) are nudged inside.
  int locate(const Point2& x) const;

  /// Composite rule: triangle_rule(degree) on each of the 342 fan triangles; weights sum to 1/2.
  /// Every point lies strictly inside a region.
  QuadratureRule composite_rule(int degree) const;

 private:
  Ws4Split();
  std::uint64_t sign_mask(const Point2& x, const Point2& toward) const;

  std::vector<Triple> lines_, vertices_;
  std::vector<int> lines_through_;
  std::vector<std::array<int, 2>> segments_;
  std::vector<SplitRegion> regions_;
  std::vector<std::array<int, 3>> fan_;
  std::vector<int> fan_region_;
  std::unordered_map<std::uint64_t, int> region_of_mask_;
};

}  // namespace iga::ws4
