#include "solver/petsc_partition.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace iga {

unsigned long long hilbert_index(unsigned x, unsigned y, int order) {
  // The classical iterative conversion: at each scale, the quadrant contributes its position in
  // the curve's order and the coordinates are rotated into that quadrant's frame.
  unsigned long long d = 0;
  const unsigned n = 1u << order;
  for (unsigned s = n / 2; s > 0; s /= 2) {
    const unsigned rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += static_cast<unsigned long long>(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) {
        x = n - 1 - x;
        y = n - 1 - y;
      }
      std::swap(x, y);
    }
  }
  return d;
}

std::vector<int> partition_elements(const std::vector<Point2>& centres, int parts) {
  const int n = static_cast<int>(centres.size());
  std::vector<int> owner(n, 0);
  if (parts <= 1 || n == 0) return owner;
  Point2 lo = centres[0], hi = centres[0];
  for (const Point2& c : centres) {
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  // One square box (keeps the curve's locality on elongated domains), 2^20 cells per side.
  const double size = std::max((hi - lo).maxCoeff(), std::numeric_limits<double>::min());
  constexpr int order = 20;
  const double cells = static_cast<double>((1u << order) - 1);
  std::vector<unsigned long long> key(n);
  for (int e = 0; e < n; ++e) {
    const Point2 t = (centres[e] - lo) / size;
    key[e] = hilbert_index(static_cast<unsigned>(t.x() * cells), static_cast<unsigned>(t.y() * cells), order);
  }
  std::vector<int> order_of(n);
  std::iota(order_of.begin(), order_of.end(), 0);
  std::stable_sort(order_of.begin(), order_of.end(), [&](int a, int b) { return key[a] < key[b]; });
  for (int k = 0; k < n; ++k) owner[order_of[k]] = static_cast<int>(static_cast<long long>(k) * parts / n);
  return owner;
}

UnknownLayout layout_unknowns(const std::vector<int>& element_offsets, const std::vector<int>& element_unknowns,
                              const std::vector<int>& element_owner, int num_unknowns, int parts) {
  UnknownLayout layout;
  layout.owner.assign(num_unknowns, parts);
  const int ne = static_cast<int>(element_offsets.size()) - 1;
  for (int e = 0; e < ne; ++e)
    for (int k = element_offsets[e]; k < element_offsets[e + 1]; ++k) {
      int& o = layout.owner[element_unknowns[k]];
      o = std::min(o, element_owner[e]);
    }
  for (int& o : layout.owner)
    if (o == parts) o = 0;
  // Rows by rank, in the unknowns' own order within a rank (keeps the serial ordering at one rank).
  layout.first_row.assign(parts + 1, 0);
  for (int o : layout.owner) ++layout.first_row[o + 1];
  for (int r = 0; r < parts; ++r) layout.first_row[r + 1] += layout.first_row[r];
  std::vector<int> next(layout.first_row.begin(), layout.first_row.end() - 1);
  layout.global.resize(num_unknowns);
  for (int u = 0; u < num_unknowns; ++u) layout.global[u] = next[layout.owner[u]]++;
  return layout;
}

RowCouplings row_couplings(const std::vector<int>& element_offsets, const std::vector<int>& element_unknowns,
                           const UnknownLayout& layout, int rank) {
  const int first = layout.first_row[rank], last = layout.first_row[rank + 1];
  const int ne = static_cast<int>(element_offsets.size()) - 1;
  // Row -> elements it lives on (CSR), for this rank's rows only.
  std::vector<int> start(last - first + 1, 0);
  for (int e = 0; e < ne; ++e)
    for (int k = element_offsets[e]; k < element_offsets[e + 1]; ++k)
      if (layout.owner[element_unknowns[k]] == rank) ++start[layout.global[element_unknowns[k]] - first + 1];
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  std::vector<int> elements_of(start.back());
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int e = 0; e < ne; ++e)
    for (int k = element_offsets[e]; k < element_offsets[e + 1]; ++k)
      if (layout.owner[element_unknowns[k]] == rank) elements_of[fill[layout.global[element_unknowns[k]] - first]++] = e;

  RowCouplings out;
  out.on_rank_columns.assign(last - first, 0);
  out.off_rank_columns.assign(last - first, 0);
  std::vector<int> columns;
  for (int row = 0; row < last - first; ++row) {
    columns.clear();
    for (int i = start[row]; i < start[row + 1]; ++i) {
      const int e = elements_of[i];
      for (int k = element_offsets[e]; k < element_offsets[e + 1]; ++k)
        columns.push_back(layout.global[element_unknowns[k]]);
    }
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
    for (int c : columns) ++(c >= first && c < last ? out.on_rank_columns[row] : out.off_rank_columns[row]);
    out.off_rank += out.off_rank_columns[row];
    out.total += static_cast<long long>(columns.size());
  }
  return out;
}

}  // namespace iga
