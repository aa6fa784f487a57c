#pragma once
/// @file
/// ParaView output through VTK's XML writers: one .vtu per level (the solution sampled on every
/// element through ElementValues, so every space is drawn the same way) and a .pvd collection.

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "spaces/space.hpp"

namespace iga {

struct VtkFieldOptions {
  int samples = 8;  ///< samples per element edge (Space::sample_cell resolution)
  /// Exact solution, if known: adds point fields `u_exact` and `error` (u - u_exact).
  /// Called from several threads at once, so it must be thread-safe (as every ScalarField).
  std::function<double(const Point2&)> exact;
  /// The same on a surface in 3D (spaces with ambient_dimension() == 3), used instead of `exact`.
  std::function<double(const Eigen::Vector3d&)> exact3;
  /// Adds the point field `laplace_u` (for biharmonic problems).
  bool laplacian = false;
};

/// Write the discrete function sum_i coefficients(i) N_i as an unstructured grid with point fields
/// `u`, `grad_u` (3 components, z = 0 in the plane; on a surface in 3D the points are the surface's
/// and grad_u its surface gradient) and the optional ones of `options`.
/// Throws std::runtime_error if the file cannot be written.
void write_solution_vtu(const Space& space, const Eigen::VectorXd& coefficients, const VtkFieldOptions& options,
                        const std::string& filename);

/// Write the outline of every element (its boundary through the element map, `samples` points per
/// edge) as closed poly-lines with a cell field `element`: the mesh, including where it was refined.
void write_mesh_vtu(const Space& space, int samples, const std::string& filename);

/// Write a ParaView collection listing `datasets` (paths relative to the .pvd) as time steps 0, 1, ...
void write_pvd(const std::vector<std::string>& datasets, const std::string& filename);

}  // namespace iga
