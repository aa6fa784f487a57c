#pragma once
/// @file
/// The files of a smooth surface in an output directory: `<stem>.vtu`, the surface sampled with
/// `samples` segments per patch edge (shared points, point normals; output/surface_vtk.hpp), and
/// `<stem>_patches.txt`, its Bernstein control points (output/bernstein_patches.hpp).

#include <string>
#include <vector>

#include "geometry/surface_patches.hpp"

namespace iga {

/// Writes both files (the .vtu only with `vtk`) into `directory` and returns their names
/// (relative to it).
std::vector<std::string> write_surface_files(const SurfacePatches& surface, const std::string& directory,
                                             const std::string& stem, int samples, bool vtk = true);

}  // namespace iga
