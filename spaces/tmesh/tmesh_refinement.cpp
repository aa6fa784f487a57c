#include "spaces/tmesh/tmesh_refinement.hpp"

#include <algorithm>
#include <stdexcept>

namespace iga {

namespace {

std::int64_t cell_size(const TCell& c) { return std::max(c.x1 - c.x0, c.y1 - c.y0); }

/// Overlap length of [a0, a1] and [b0, b1].
std::int64_t overlap(std::int64_t a0, std::int64_t a1, std::int64_t b0, std::int64_t b1) {
  return std::min(a1, b1) - std::max(a0, b0);
}

/// Grow `split` until no side neighbours differ by more than a factor 2 after splitting.
void balance(const TMesh& mesh, const std::vector<std::pair<int, int>>& pairs, std::vector<char>& split) {
  const auto& cells = mesh.cells();
  for (bool changed = true; changed;) {
    changed = false;
    for (auto [a, b] : pairs) {
      const std::int64_t sa = cell_size(cells[a]) / (split[a] ? 2 : 1), sb = cell_size(cells[b]) / (split[b] ? 2 : 1);
      if (sa > 2 * sb && !split[a]) split[a] = 1, changed = true;
      if (sb > 2 * sa && !split[b]) split[b] = 1, changed = true;
    }
  }
}

}  // namespace

std::vector<std::pair<int, int>> side_neighbours(const TMesh& mesh) {
  // Sweep over cells sorted by x0: a vertical-side neighbour b of a has b.x0 == a.x1, a horizontal
  // one overlaps a in x; both start before a.x1 ends, so only cells with x0 <= a.x1 are examined.
  const auto& cells = mesh.cells();
  std::vector<int> order(cells.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::sort(order.begin(), order.end(), [&](int i, int j) { return cells[i].x0 < cells[j].x0; });
  std::vector<std::pair<int, int>> out;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const TCell& a = cells[order[i]];
    for (std::size_t j = i + 1; j < order.size() && cells[order[j]].x0 <= a.x1; ++j) {
      const TCell& b = cells[order[j]];
      const bool vertical = (a.x1 == b.x0 || b.x1 == a.x0) && overlap(a.y0, a.y1, b.y0, b.y1) > 0;
      const bool horizontal = (a.y1 == b.y0 || b.y1 == a.y0) && overlap(a.x0, a.x1, b.x0, b.x1) > 0;
      if (vertical || horizontal) out.emplace_back(std::min(order[i], order[j]), std::max(order[i], order[j]));
    }
  }
  return out;
}

TMesh refine_admissibly(const TMesh& mesh, const std::vector<int>& marked) {
  std::vector<char> split(mesh.num_cells(), 0);
  for (int c : marked) split.at(c) = 1;
  const std::vector<std::pair<int, int>> pairs = side_neighbours(mesh);
  constexpr int kBufferRounds = 4;
  for (int round = 0; round <= kBufferRounds; ++round) {
    balance(mesh, pairs, split);
    std::vector<int> which;
    for (int c = 0; c < mesh.num_cells(); ++c)
      if (split[c]) which.push_back(c);
    for (int c : which) {
      const TCell& cell = mesh.cells()[c];
      if ((cell.x1 - cell.x0) % 2 || (cell.y1 - cell.y0) % 2)
        throw std::runtime_error("the T-mesh lattice allows no finer cells (cell " + std::to_string(c) + " is one lattice unit)");
    }
    TMesh out = mesh.refined(which);
    if (out.admissibility_problem().empty()) return out;
    std::vector<char> grown = split;
    for (auto [a, b] : pairs)
      if (split[a] || split[b]) grown[a] = grown[b] = 1;
    split = grown;
  }
  throw std::runtime_error("adaptive T-mesh refinement did not reach an admissible (regular, acyclic) mesh");
}

}  // namespace iga
