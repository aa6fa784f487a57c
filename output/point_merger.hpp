#pragma once
/// @file
/// Merges points that coincide up to a tolerance, so that elements sharing an edge share its
/// points in the written grid (continuous fields stay continuous, and ParaView's filters see one
/// connected surface instead of loose pieces).

#include <Eigen/Core>
#include <cstdint>
#include <unordered_map>

namespace iga {

class PointMerger {
 public:
  /// Points closer than `tolerance` in every coordinate are the same point.
  explicit PointMerger(double tolerance, std::size_t expected_points = 0);

  /// The id of `x` among the distinct points seen so far (0, 1, ... in order of first sight);
  /// `inserted` tells whether x was new.
  std::int64_t insert(const Eigen::Vector3d& x, bool& inserted);
  /// A new id for a point known to coincide with no other (not looked up, not remembered).
  std::int64_t append() { return count_++; }
  /// Number of distinct points.
  std::int64_t size() const { return count_; }

 private:
  struct Key {
    std::int64_t i, j, k;
    bool operator==(const Key& o) const { return i == o.i && j == o.j && k == o.k; }
  };
  struct KeyHash {
    std::size_t operator()(const Key& key) const;
  };
  double scale_;
  std::int64_t count_ = 0;
  std::unordered_map<Key, std::int64_t, KeyHash> ids_;
};

}  // namespace iga
