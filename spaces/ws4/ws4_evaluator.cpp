#include "spaces/ws4/ws4_evaluator.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "spaces/ws4/ws4_basis.hpp"
#include "spaces/ws4/ws4_piece_kernels.hpp"
#include "spaces/ws4/ws4_piece_table.hpp"
#include "spaces/ws4/ws4_space.hpp"

namespace iga::ws4 {

Ws4Evaluator::Ws4Evaluator(const Ws4Space& space) : Space::Evaluator(space), space_(space), generic_(space.make_generic_evaluator()) {}

const Ws4Evaluator::RuleTables& Ws4Evaluator::tables(const QuadratureRule& rule) {
  auto it = cache_.find(&rule);
  // Bitwise comparison (memcmp, not point by point): it runs once per element and rule.
  if (it != cache_.end() && it->second.points.size() == rule.points.size() &&
      std::memcmp(it->second.points.data(), rule.points.data(), rule.points.size() * sizeof(Point2)) == 0)
    return it->second;
  if (it == cache_.end() && cache_.size() >= 64) cache_.clear();  // bound temporary rules
  RuleTables& t = cache_[&rule];
  const Ws4Basis& basis = Ws4Basis::reference();
  const Ws4PieceTable& pieces = Ws4PieceTable::reference();
  const int q = rule.size();
  t.points = rule.points;
  t.reference.resize(q, 2);
  t.local.resize(q, 2);
  t.regions.clear();
  t.runs.clear();
  std::vector<int> slot(basis.split().regions().size(), -1);
  for (int k = 0; k < q; ++k) {
    t.reference(k, 0) = rule.points[k].x();
    t.reference(k, 1) = rule.points[k].y();
    const int r = basis.split().locate(rule.points[k]);
    if (slot[r] < 0) {
      slot[r] = static_cast<int>(t.regions.size());
      t.regions.push_back(r);
    }
    if (!t.runs.empty() && t.runs.back()[0] == slot[r])
      ++t.runs.back()[2];
    else
      t.runs.push_back({slot[r], k, 1});
    // Coordinates of the orbit's representative region, whose pieces the table holds.
    const Point2 x = pieces.inverse_linear[r] * (rule.points[k] - basis.center(r));
    t.local(k, 0) = x.x();
    t.local(k, 1) = x.y();
  }
  // Runs by slot (the order of the coefficient blocks in evaluate_function); each run writes its
  // own points, so the order does not change the results.
  std::stable_sort(t.runs.begin(), t.runs.end(), [](const auto& a, const auto& b) { return a[0] < b[0]; });
  // Slots grouped by orbit (the kernels read each representative's pieces once per group).
  std::vector<std::array<int, 3>> members;  // (representative, region, slot)
  for (int s = 0; s < static_cast<int>(t.regions.size()); ++s)
    members.push_back({pieces.representative[t.regions[s]], t.regions[s], s});
  std::sort(members.begin(), members.end());
  t.orbit_regions.clear();
  t.orbit_slots.clear();
  t.orbit_begin.assign(1, 0);
  for (size_t i = 0; i < members.size(); ++i) {
    if (i > 0 && members[i][0] != members[i - 1][0]) t.orbit_begin.push_back(static_cast<int>(i));
    t.orbit_regions.push_back(members[i][1]);
    t.orbit_slots.push_back(members[i][2]);
  }
  t.orbit_begin.push_back(static_cast<int>(members.size()));
  return t;
}

void Ws4Evaluator::fill_geometry(int element, const RuleTables& t, PointValues& out) const {
  space_.element_dofs(element, out.dofs);
  const Eigen::Matrix2d j = space_.jacobian(element);
  const Point2 p0 = space_.mesh().vertices()[space_.mesh().triangle(element)[0]];
  const int q = static_cast<int>(t.points.size());
  out.x.resize(2, q);
  piece_kernels::affine_points(j, p0, t.reference.col(0).data(), t.reference.col(1).data(), q, out.x.data());
  // One Jacobian per point, as PointValues has it (the map is affine: all the same).
  static_assert(sizeof(Eigen::Matrix2d) == 4 * sizeof(double));
  out.jacobian.resize(q);
  piece_kernels::repeat_matrix(j, q, out.jacobian.data()->data());
}

void Ws4Evaluator::evaluate_geometry(int element, const QuadratureRule& rule, PointValues& out) {
  fill_geometry(element, tables(rule), out);
}

void Ws4Evaluator::evaluate_element_function(int element, const QuadratureRule& rule, const Eigen::VectorXd& local,
                                             unsigned flags, PointValues& geometry, FunctionValues& out) {
  if (flags & (update_laplacian_gradient | update_bilaplacian))
    throw std::logic_error("evaluate_function: this space provides derivatives up to order 2 only");
  const RuleTables& t = tables(rule);
  fill_geometry(element, t, geometry);
  for (int i = 0; i < Ws4Basis::size; ++i) c_(i) = local(i);
  b_.noalias() = space_.extraction(element) * c_;

  // u_h on each region holding points (15 rows over the slots, computed orbit by orbit), then
  // eight regions at a time its physical derivatives: a table of polynomial coefficients with
  // rows of eight slots (ws4_piece_kernels.hpp) that stays in the first-level cache while the
  // points of those regions are evaluated.
  constexpr int block = piece_kernels::block_slots;
  static_assert(4 * block == std::tuple_size_v<decltype(slot_maps_)>);
  const int order = (flags & update_hessians) ? 2 : (flags & update_gradients) ? 1 : 0;
  const int slots = static_cast<int>(t.regions.size());
  if (slot_values_.size() != static_cast<size_t>(piece_kernels::rows) * block)
    slot_values_.assign(static_cast<size_t>(piece_kernels::rows) * block, 0.0);
  const Eigen::Matrix2d g = space_.jacobian(element).inverse();
  const int q = rule.size();
  Eigen::VectorXd* targets[6] = {&out.value, &out.dx, &out.dy, &out.dxx, &out.dxy, &out.dyy};
  const int arrays = order == 2 ? 6 : order == 1 ? 3 : 1;
  for (int r = 0; r < arrays; ++r) targets[r]->resize(q);
  const Ws4PieceTable& pieces = Ws4PieceTable::reference();
  const int stride = (slots + block - 1) / block * block;
  values_.resize(static_cast<size_t>(Ws4PieceTable::monomials) * stride);
  for (int m = 0; m < Ws4PieceTable::monomials; ++m)
    std::fill(values_.begin() + m * stride + slots, values_.begin() + (m + 1) * stride, 0.0);
  for (size_t o = 0; o + 1 < t.orbit_begin.size(); ++o)
    piece_kernels::orbit_polynomials(pieces, t.orbit_regions.data() + t.orbit_begin[o],
                                     t.orbit_slots.data() + t.orbit_begin[o], t.orbit_begin[o + 1] - t.orbit_begin[o],
                                     b_.data(), values_.data(), stride);
  for (int first_slot = 0, run = 0; first_slot < slots; first_slot += block) {
    const int n = std::min(block, slots - first_slot);
    for (int m = 0; m < Ws4PieceTable::monomials; ++m)
      std::copy_n(values_.data() + m * stride + first_slot, block, slot_values_.data() + m * block);
    if (order > 0) {
      // Per slot, the inverse Jacobian in its representative's coordinates: L⁻¹ g.
      for (int s = 0; s < block; ++s) {
        const Eigen::Matrix2d gs =
            s < n ? Eigen::Matrix2d(pieces.inverse_linear[t.regions[first_slot + s]] * g) : Eigen::Matrix2d::Zero();
        slot_maps_[s] = gs(0, 0);
        slot_maps_[block + s] = gs(1, 0);
        slot_maps_[2 * block + s] = gs(0, 1);
        slot_maps_[3 * block + s] = gs(1, 1);
      }
      piece_kernels::derivative_polynomials(slot_maps_.data(), order, slot_values_.data());
    }
    for (; run < static_cast<int>(t.runs.size()) && t.runs[run][0] < first_slot + block; ++run) {
      const auto& [s, first, count] = t.runs[run];
      double* rows_out[6];
      for (int r = 0; r < arrays; ++r) rows_out[r] = targets[r]->data() + first;
      piece_kernels::evaluate_run(slot_values_.data(), s - first_slot, order, t.local.col(0).data() + first,
                                  t.local.col(1).data() + first, count, rows_out);
    }
  }
}

void Ws4Evaluator::integrate_values(int element, const QuadratureRule& rule, const PointValues& /*geometry*/,
                                    const Eigen::VectorXd& weights, Eigen::VectorXd& local) {
  const RuleTables& t = tables(rule);
  // Weighted monomial moments per region, then Σ_r (pieces of r)ᵀ moments, then C_Kᵀ.
  const int slots = static_cast<int>(t.regions.size());
  slot_values_.assign(static_cast<size_t>(Ws4PieceTable::padded) * slots, 0.0);
  for (const auto& [s, first, count] : t.runs)
    piece_kernels::add_moments(t.local.col(0).data() + first, t.local.col(1).data() + first, weights.data() + first,
                               count, slot_values_.data() + static_cast<size_t>(s) * Ws4PieceTable::padded);
  b_.setZero();
  const Ws4PieceTable& pieces = Ws4PieceTable::reference();
  for (size_t o = 0; o + 1 < t.orbit_begin.size(); ++o)
    piece_kernels::orbit_transposed(pieces, t.orbit_regions.data() + t.orbit_begin[o],
                                    t.orbit_slots.data() + t.orbit_begin[o], t.orbit_begin[o + 1] - t.orbit_begin[o],
                                    slot_values_.data(), b_.data());
  local.noalias() = space_.extraction(element).transpose() * b_;
}

}  // namespace iga::ws4
