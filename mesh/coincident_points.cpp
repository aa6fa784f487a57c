#include "mesh/coincident_points.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace iga {

namespace {

template <int Dim>
using Cell = std::array<std::int64_t, Dim>;

template <int Dim>
struct CellHash {
  std::size_t operator()(const Cell<Dim>& c) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (std::int64_t k : c) {  // splitmix64 steps: neighbouring cells land in unrelated buckets
      h ^= static_cast<std::uint64_t>(k) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
      h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
      h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
      h ^= h >> 31;
    }
    return static_cast<std::size_t>(h);
  }
};

template <int Dim>
bool close(const Eigen::Matrix<double, Dim, 1>& a, const Eigen::Matrix<double, Dim, 1>& b, double tolerance,
           Closeness closeness) {
  if (closeness == Closeness::distance) return (a - b).norm() <= tolerance;
  return (a - b).cwiseAbs().maxCoeff() <= tolerance;
}

}  // namespace

template <int Dim>
std::optional<std::pair<int, int>> find_coincident_points(const std::vector<Eigen::Matrix<double, Dim, 1>>& points,
                                                          const std::vector<int>& ids, double tolerance,
                                                          Closeness closeness) {
  using Point = Eigen::Matrix<double, Dim, 1>;
  std::vector<int> finite;
  finite.reserve(ids.size());
  for (int id : ids)
    if (points[id].allFinite()) finite.push_back(id);
  if (finite.size() < 2) return std::nullopt;
  Point lo = points[finite[0]], hi = lo;
  for (int id : finite) lo = lo.cwiseMin(points[id]), hi = hi.cwiseMax(points[id]);
  // Cells twice the tolerance wide: two close points then lie in the same or adjacent cells even
  // after the cell index is rounded. Never so small that an index overflows (nor zero).
  const double extent = (hi - lo).maxCoeff();
  double width = 2.0 * std::max(tolerance, 0.0);
  width = std::max({width, extent * 1e-15, std::numeric_limits<double>::min()});
  const auto cell_of = [&](const Point& x) {
    Cell<Dim> c;
    for (int d = 0; d < Dim; ++d) c[d] = static_cast<std::int64_t>(std::floor((x[d] - lo[d]) / width));
    return c;
  };
  // Each cell holds a chain of the points in it: `head` its latest, `next` the one before.
  std::unordered_map<Cell<Dim>, int, CellHash<Dim>> head;
  head.reserve(finite.size());
  std::vector<int> next(finite.size(), -1);
  for (std::size_t k = 0; k < finite.size(); ++k) {
    const Point& x = points[finite[k]];
    const Cell<Dim> home = cell_of(x);
    std::optional<std::size_t> earliest;
    Cell<Dim> offset;
    offset.fill(-1);
    for (;;) {  // the 3^Dim cells around home
      Cell<Dim> c = home;
      for (int d = 0; d < Dim; ++d) c[d] += offset[d];
      if (const auto it = head.find(c); it != head.end())
        for (int j = it->second; j >= 0; j = next[j])
          if (close<Dim>(points[finite[j]], x, tolerance, closeness) && (!earliest || j < static_cast<int>(*earliest)))
            earliest = static_cast<std::size_t>(j);
      int d = 0;
      while (d < Dim && offset[d] == 1) offset[d++] = -1;
      if (d == Dim) break;
      ++offset[d];
    }
    if (earliest) return std::pair{finite[*earliest], finite[k]};
    auto [it, fresh] = head.try_emplace(home, static_cast<int>(k));
    if (!fresh) {
      next[k] = it->second;
      it->second = static_cast<int>(k);
    }
  }
  return std::nullopt;
}

template std::optional<std::pair<int, int>> find_coincident_points<2>(const std::vector<Eigen::Vector2d>&,
                                                                      const std::vector<int>&, double, Closeness);
template std::optional<std::pair<int, int>> find_coincident_points<3>(const std::vector<Eigen::Vector3d>&,
                                                                      const std::vector<int>&, double, Closeness);

}  // namespace iga
