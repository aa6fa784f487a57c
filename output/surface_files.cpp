#include "output/surface_files.hpp"

#include <filesystem>

#include "geometry/rsd/surface_sampling.hpp"
#include "output/bernstein_patches.hpp"
#include "output/surface_vtk.hpp"

namespace iga {

std::vector<std::string> write_surface_files(const SurfacePatches& surface, const std::string& directory,
                                             const std::string& stem, int samples, bool vtk) {
  const std::filesystem::path dir(directory);
  const std::string vtu = stem + ".vtu", patches = stem + "_patches.txt";
  std::vector<std::string> written;
  if (vtk) {
    const rsd::SampledSurface sampled = rsd::sample_surface(surface, samples);
    write_surface_vtu(sampled.points, sampled.normals, sampled.triangles, sampled.patch, (dir / vtu).string());
    written.push_back(vtu);
  }
  std::string comment;
  for (const auto& [key, value] : surface.labels) comment += (comment.empty() ? "" : ", ") + key + " " + value;
  write_bernstein_patches_file(surface, (dir / patches).string(), comment);
  written.push_back(patches);
  return written;
}

}  // namespace iga
