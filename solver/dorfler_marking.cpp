#include "solver/dorfler_marking.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace iga {

std::vector<int> dorfler_marking(const std::vector<double>& eta, double theta) {
  if (!(theta > 0.0 && theta <= 1.0)) throw std::invalid_argument("Dörfler parameter must be in (0, 1]");
  std::vector<int> order(eta.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return eta[a] > eta[b]; });
  double total = 0.0;
  for (double x : eta) total += x * x;
  std::vector<int> marked;
  if (total <= 0.0) return marked;
  double sum = 0.0;
  for (int k : order) {
    if (sum >= theta * total) break;
    marked.push_back(k);
    sum += eta[k] * eta[k];
  }
  std::sort(marked.begin(), marked.end());
  return marked;
}

}  // namespace iga
