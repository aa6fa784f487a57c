#pragma once
/// @file
/// Ws4PieceTable: the nonzero pieces of the 51 reference simplex splines, region by region, laid
/// out for the piece kernels (ws4_piece_kernels.hpp). On each of the 252 regions about 20 of the
/// 51 functions are not zero; only those are stored, in two layouts:
///  - by function (the forward contraction u_h|r = Σ_i b_i piece(r, i)): 16 numbers per active
///    function, its 15 monomial coefficients and a zero, so that a region's polynomial is a sum
///    of whole 16-vectors;
///  - by monomial (the transposed contraction of load vectors, b_i += piece(r, i) · moments(r)):
///    per region a 15 x width block, row m holding coefficient m of each active function, width
///    the active count rounded up to 4 (zeros after it), so each row is a whole number of vectors.

#include <vector>

namespace iga::ws4 {

struct Ws4PieceTable {
  static constexpr int monomials = 15;  ///< quartic monomials, Poly4::index order
  static constexpr int padded = 16;     ///< one function's coefficients in `by_function`

  /// Active functions of region r: function[k] for k in [begin[r], begin[r + 1]).
  std::vector<int> begin;
  std::vector<int> function;
  /// padded numbers per active function k, from by_function[padded * k].
  std::vector<double> by_function;
  /// Region r's 15 x width block (width = block_begin[r + 1] - block_begin[r], a multiple of 4)
  /// starts at by_monomial[monomials * block_begin[r]], row-major.
  std::vector<int> block_begin;
  std::vector<double> by_monomial;

  int num_regions() const { return static_cast<int>(begin.size()) - 1; }
  int active(int region) const { return begin[region + 1] - begin[region]; }
  int width(int region) const { return block_begin[region + 1] - block_begin[region]; }
  /// Largest width over the regions (scratch size of the transposed contraction).
  int max_width = 0;

  /// The table of Ws4Basis::reference() (built on first use, then shared; thread-safe).
  static const Ws4PieceTable& reference();
};

}  // namespace iga::ws4
