#include "output/point_merger.hpp"

#include <cmath>

namespace iga {

PointMerger::PointMerger(double tolerance, std::size_t expected_points) : scale_(1.0 / tolerance) {
  ids_.reserve(expected_points);  // no rehashing while the points go in
}

std::size_t PointMerger::KeyHash::operator()(const Key& key) const {
  std::uint64_t h = static_cast<std::uint64_t>(key.i) * 0x9E3779B97F4A7C15ull;
  h ^= static_cast<std::uint64_t>(key.j) + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2);
  h ^= static_cast<std::uint64_t>(key.k) + 0x85EBCA77C2B2AE63ull + (h << 6) + (h >> 2);
  return static_cast<std::size_t>(h);
}

std::int64_t PointMerger::insert(const Eigen::Vector3d& x, bool& inserted) {
  // Each coordinate is rounded to a grid of the tolerance. Two copies of one point differ by
  // round-off, far below the grid, so they round alike unless the point lies almost exactly
  // half-way between grid values: only then is the neighbouring value looked up as well.
  std::int64_t rounded[3], other[3];
  bool ambiguous[3];
  for (int d = 0; d < 3; ++d) {
    const double s = x(d) * scale_;
    const double r = std::nearbyint(s);
    rounded[d] = static_cast<std::int64_t>(r);
    const double off = s - r;  // in [-0.5, 0.5]
    ambiguous[d] = std::abs(off) > 0.499;
    other[d] = rounded[d] + (off > 0 ? 1 : -1);
  }
  const Key key{rounded[0], rounded[1], rounded[2]};
  if (auto it = ids_.find(key); it != ids_.end()) {
    inserted = false;
    return it->second;
  }
  if (ambiguous[0] || ambiguous[1] || ambiguous[2])
    for (int mask = 1; mask < 8; ++mask) {
      std::int64_t c[3];
      bool valid = true;
      for (int d = 0; d < 3; ++d) {
        const bool flip = mask & (1 << d);
        if (flip && !ambiguous[d]) valid = false;
        c[d] = flip ? other[d] : rounded[d];
      }
      if (!valid) continue;
      if (auto it = ids_.find(Key{c[0], c[1], c[2]}); it != ids_.end()) {
        inserted = false;
        return it->second;
      }
    }
  inserted = true;
  ids_.emplace(key, count_);
  return count_++;
}

}  // namespace iga
