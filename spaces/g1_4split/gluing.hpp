#pragma once
/// @file
/// Gluing data of the 4-split G1 space (symmetric choice b ≡ -1, c ≡ 1): per interior edge the
/// function a(t), t in [0,1] from the edge's first vertex g0 to its second g1, a spline with one
/// polynomial piece (degree <= 3) on [0,1/2] and one on [1/2,1]. The G1 condition reads
/// D_{n0} f0 + D_{n1} f1 = a(t) D_t f with inward transversal derivatives D_n.

#include <array>
#include <string>
#include <vector>

namespace iga {

/// The blending function d0 of a(t) = A0 d0(t) - A1 d0(1 - t):
///  q0: 1 - 4t² | 0 (C0 at 1/2; the paper's example, degenerate for analysis);
///  q1: 1 - 2t² | 2(1-t)² (C1, d0 + d1 ≡ 1);  c1: 1 - 12t² + 16t³ | 0 (C1 cubic Hermite).
///  linear: 1 - t (one polynomial; its restrictions to sub-edges stay linear, so nested refinement
///  keeps every edge separable at degree 4; a'(γ) ≠ 0, so it is valid only where no interior
///  crossing vertex has opposite edges with different a'(γ)).
///  lines: linear along every mesh line through interior valence-4 vertices, with a twist-compatible
///  fallback where two such lines would both be non-zero at one vertex (spaces/g1_4split/line_gluing.hpp);
///  valid on every quad mesh, optimal after nesting.
enum class Blending { q0, q1, c1, linear, lines };

/// Parses "q0", "q1", "c1", "linear", "lines"; throws std::invalid_argument otherwise.
Blending blending_from_name(const std::string& name);
std::string blending_name(Blending b);

/// A spline on [0, 1/2, 1] with one polynomial of degree <= 3 per half, in powers of t.
struct SplitGluing {
  std::array<std::array<double, 4>, 2> piece{};  ///< piece[h][j]: coefficient of t^j on half h

  /// d^order a / dt^order at t (order <= 3) of half `half` (-1: the half containing t, right at 1/2).
  double eval(double t, int order = 0, int half = -1) const;
  /// a(t) = A0 d0(t) - A1 d0(1 - t) for the blending `b`.
  static SplitGluing symmetric(double A0, double A1, Blending b);
  /// The C0 spline linear on each half with a(0) = a0, a(1/2) = mid, a(1) = a1.
  static SplitGluing piecewise_linear(double a0, double mid, double a1);
  /// The data seen from the other end: t -> 1 - t and the sign flips (a(t) -> -a(1 - t)).
  SplitGluing reversed() const;
  /// sign(t1 - t0) a(t0 + (t1 - t0) s): the gluing inherited by the sub-edge [t0, t1] (inside one
  /// half) of a split edge, for nested refinement; the result has the same polynomial on both halves.
  SplitGluing restricted(double t0, double t1) const;
};

/// Gluing value of a vertex: 2 cos(2π/F) for an interior vertex with F faces, 2 cos(π/F) for a
/// boundary vertex with F faces (straight boundary angle); values below 1e-12 in magnitude are
/// snapped to 0 (crossing vertex).
double vertex_gluing_value(int faces, bool boundary);

}  // namespace iga
