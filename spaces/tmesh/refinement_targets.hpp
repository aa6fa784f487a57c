#pragma once
/// @file
/// Which cells of a T-mesh meet a point, a box or a polyline (a sampled curve), for the local
/// refinement asked for by `space.refine_near` (tmesh_from_config.hpp).

#include <Eigen/Core>
#include <vector>

#include "spaces/tmesh/tmesh.hpp"

namespace iga {

/// Points and polylines meet the closed cells (a point on a cell side meets the cells on both
/// sides, a point at a vertex every cell around it); a box meets the cells it overlaps with
/// positive area (cells merely touching it do not count).
struct RefinementTarget {
  enum class Kind { point, box, polyline };
  Kind kind = Kind::point;
  /// point: one point; box: lower-left and upper-right corners; polyline: its vertices in order (>= 2).
  std::vector<Eigen::Vector2d> points;
};

/// Cells of `mesh` (increasing indices) that meet `target` in the sense above, with a tolerance of
/// 1e-12 times the mesh's bounding-box diagonal.
std::vector<int> cells_meeting(const TMesh& mesh, const RefinementTarget& target);

}  // namespace iga
