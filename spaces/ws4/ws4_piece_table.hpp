#pragma once
/// @file
/// Ws4PieceTable: the nonzero pieces of the 51 reference simplex splines, region by region, laid
/// out for the piece kernels (ws4_piece_kernels.hpp), and stored once per orbit of regions under
/// the symmetries of the triangle.
///
/// The six affine maps A of the reference triangle onto itself that permute its vertices map the
/// split onto itself and the basis onto itself: B_π(i)(A x) = B_i(x) for a permutation π of the
/// functions (the knot sets map onto each other). A region r = A(r0) of the orbit of its
/// representative r0 therefore has, in the coordinates ξ = L⁻¹ (x - center(r)) (L the linear
/// part of A), the pieces of r0: piece(r, π(i))(L ξ) = piece(r0, i)(ξ). Only the representatives'
/// pieces are stored (about a sixth of 252 x 20 quartics: a table that stays in the cache while
/// elements are evaluated one after the other), with, per region, π of the representative's
/// active functions and L⁻¹.
///
/// Two layouts of the representatives' pieces:
///  - by function (the forward contraction u_h|r = Σ_i b_i piece(r, i)): 16 numbers per active
///    function, its 15 monomial coefficients and a zero, so that a region's polynomial is a sum
///    of whole 16-vectors;
///  - by monomial (the transposed contraction of load vectors, b_i += piece(r, i) · moments(r)):
///    per representative a 15 x width block, row m holding coefficient m of each active function,
///    width the active count rounded up to 4 (zeros after it), so each row is whole vectors.

#include <Eigen/Core>
#include <vector>

namespace iga::ws4 {

struct Ws4PieceTable {
  static constexpr int monomials = 15;  ///< quartic monomials, Poly4::index order
  static constexpr int padded = 16;     ///< one function's coefficients in `by_function`

  /// Active functions of region r: function[k] for k in [begin[r], begin[r + 1]), in the order
  /// of the representative's pieces (function[begin[r] + j] = π(j-th active function of r0)).
  std::vector<int> begin;
  std::vector<int> function;
  /// Region r's pieces: `padded` numbers per active function from by_function[padded *
  /// piece_begin[r]] (shared by the regions of an orbit).
  std::vector<int> piece_begin;
  std::vector<double> by_function;
  /// Region r's 15 x width(r) block (width a multiple of 4) starts at by_monomial[monomials *
  /// block_begin[r]], row-major (shared by the regions of an orbit).
  std::vector<int> block_begin;
  std::vector<int> block_width;
  std::vector<double> by_monomial;
  /// L⁻¹ of each region (integer entries): the representative's coordinates of a point are
  /// inverse_linear[r] (x - center(r)).
  std::vector<Eigen::Matrix2d> inverse_linear;
  /// Representative of each region's orbit.
  std::vector<int> representative;

  int num_regions() const { return static_cast<int>(begin.size()) - 1; }
  int active(int region) const { return begin[region + 1] - begin[region]; }
  int width(int region) const { return block_width[region]; }
  /// Largest width over the regions (scratch size of the transposed contraction).
  int max_width = 0;

  /// The table of Ws4Basis::reference() (built on first use, then shared; thread-safe).
  static const Ws4PieceTable& reference();
};

}  // namespace iga::ws4
