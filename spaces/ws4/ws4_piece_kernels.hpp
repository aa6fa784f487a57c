#pragma once
/// @file
/// The arithmetic of Ws4Evaluator (ws4_evaluator.hpp), written with the vector types of GCC
/// and Clang over contiguous arrays (compiled for the x86-64 baseline, AVX2 + FMA and AVX-512, the
/// copy chosen at load time).
///
/// One discrete function on one element is a sequence of tables of polynomial coefficients, each
/// for block_slots *slots* (regions of the split holding points of the rule), one column per slot
/// and one row per monomial coefficient (a table stays in the first-level cache):
/// rows [0, 15) the quartic u_h, then the physical derivatives (cubics ∂x, ∂y: 10 rows each,
/// quadratics ∂xx, ∂xy, ∂yy: 6 rows each), all in the coordinates of the region's representative
/// (Ws4PieceTable). Rows are contiguous over slots, so derivatives are taken for all the slots of
/// a table at once.

#include <Eigen/Core>

#include "quadrature/quadrature_rule.hpp"
#include "spaces/ws4/ws4_piece_table.hpp"

namespace iga::ws4::piece_kernels {

/// First row of each polynomial in the coefficient table, and the number of rows.
inline constexpr int value_row = 0, dx_row = 15, dy_row = 25, dxx_row = 35, dxy_row = 41, dyy_row = 47, rows = 53;
/// Slots per coefficient table: one AVX-512 vector per row. A table is rows x block_slots.
inline constexpr int block_slots = 8;

/// values[m * stride + slots[i]] = Σ_j b[j] piece(regions[i], j) (m < 15, i < members): u_h on
/// regions of one orbit (the same representative in Ws4PieceTable), in the representative's
/// coordinates.
void orbit_polynomials(const Ws4PieceTable& table, const int* regions, const int* slots, int members, const double* b,
                       double* values, int stride);

/// The derivative rows of a table from its value rows, for all its slots: ∂x_j = Σ_k
/// g_s(k, j) ∂ξ_k where ξ = g_s x + const are slot s's coordinates of the physical point x; g holds
/// g_s(0, 0), g_s(1, 0), g_s(0, 1), g_s(1, 1) as four rows of block_slots numbers. `order` 1 fills
/// the gradient rows, 2 the Hessian rows too.
void derivative_polynomials(const double* g, int order, double* coefficients);

/// u_h (order 0), with its gradient (1) and Hessian (2), at `count` points of the region in
/// `slot` of a table, from their coordinates x, y in the region's representative's coordinates
/// (RuleTables::local of ws4_evaluator.hpp): Horner per point.
/// out[0..5] = value, dx, dy, dxx, dxy, dyy (the first 1, 3 or 6 are written).
void evaluate_run(const double* coefficients, int slot, int order, const double* x, const double* y, int count,
                  double* const* out);

/// moments[Poly4::index(a, b)] += Σ_k w[k] x[k]^a y[k]^b over `count` points.
void add_moments(const double* x, const double* y, const double* w, int count, double* moments);

/// b[j] += piece(regions[i], j) · moments[16 slots[i] .. 16 slots[i] + 15) for regions of one
/// orbit and their active functions j: the transposed orbit_polynomials.
void orbit_transposed(const Ws4PieceTable& table, const int* regions, const int* slots, int members,
                      const double* moments, double* b);

/// x(:, k) = p0 + j (xi[k], eta[k]) for k < count, x a 2 x count column-major array: the
/// element's affine map at the points of a rule.
void affine_points(const Eigen::Matrix2d& j, const Point2& p0, const double* xi, const double* eta, int count,
                   double* x);

/// count copies of the 2 x 2 matrix j, column-major, one after the other (out: 4 count numbers).
void repeat_matrix(const Eigen::Matrix2d& j, int count, double* out);

}  // namespace iga::ws4::piece_kernels
