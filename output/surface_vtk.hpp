#pragma once
/// @file
/// ParaView output of a triangulated surface in 3D (e.g. a sampled G1 surface): an unstructured
/// grid of linear triangles with the point field `Normals` (set as the active normals, so the
/// surface is shaded smoothly) and the cell field `patch`.

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace iga {

/// Writes `filename` (.vtu). Sizes must agree (one normal per point, one patch per triangle).
/// Throws std::runtime_error (and leaves no file) if writing fails.
void write_surface_vtu(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& normals,
                       const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& patch,
                       const std::string& filename);

}  // namespace iga
