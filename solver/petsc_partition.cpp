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

}  // namespace iga
