#include "spaces/g1/patch_mesh_from_file.hpp"

#include <filesystem>

#include "mesh/validate_planar_mesh.hpp"

namespace iga {

PatchMesh patch_mesh_from_planar(const PlanarMesh& mesh) {
  validate_planar_mesh(mesh, {true, true, "g1"});
  std::vector<Point2> vertices(mesh.vertices.begin(), mesh.vertices.end());
  BoundaryGroups groups;
  for (const auto& [name, edges] : mesh.boundary_groups)
    for (const auto& e : edges) groups[name].push_back({e[0], e[1]});
  // Messages of PatchMesh name the file; its patch numbers are the file's cell numbers.
  return PatchMesh(std::move(vertices), mesh.cells, std::filesystem::path(mesh.source).filename().string(),
                   std::move(groups));
}

PatchMesh patch_mesh_from_file(const std::string& path, const MeshFileOptions& options) {
  return patch_mesh_from_planar(read_mesh_file(path, options));
}

}  // namespace iga
