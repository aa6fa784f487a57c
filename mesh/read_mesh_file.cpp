#include "mesh/read_mesh_file.hpp"

#include <gmsh.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "mesh/gmsh_model_mesh.hpp"
#include "mesh/gmsh_session.hpp"
#include "mesh/read_text_meshes.hpp"

namespace iga {

namespace {

PlanarMesh read_with_gmsh(const std::string& path, const MeshFileOptions& options, bool mesh_geometry) {
  PlanarMesh mesh;
  with_gmsh(path, [&] {
    gmsh::open(path);
    if (mesh_geometry) {
      if (options.mesh_size > 0.0) gmsh::option::setNumber("Mesh.MeshSizeMax", options.mesh_size);
      if (options.recombine) gmsh::option::setNumber("Mesh.RecombineAll", 1);
      gmsh::model::mesh::generate(2);
    }
    mesh = planar_mesh_from_gmsh_model(path);
  });
  return mesh;
}

}  // namespace

PlanarMesh read_mesh_file(const std::string& path, const MeshFileOptions& options) {
  if (!(options.mesh_size >= 0.0))
    throw InputError(path + ": mesh size must be >= 0 (got " + format_number(options.mesh_size) + ")");
  // Gmsh 4.8 only logs a missing file, so readability is checked here for every format.
  std::ifstream in(path);
  if (!in || std::filesystem::is_directory(path)) throw InputError(path + ": cannot read the mesh file");
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (extension != ".geo" && (options.mesh_size > 0.0 || options.recombine))
    throw InputError(path + ": a mesh size or recombination applies to .geo files only (a mesh is used as it is)");
  if (extension == ".msh") return read_with_gmsh(path, options, false);
  if (extension == ".geo") return read_with_gmsh(path, options, true);
  if (extension == ".obj") return read_obj_mesh(in, path);
  if (extension == ".off") return read_off_mesh(in, path);
  throw InputError(path + ": unknown mesh file extension '" + extension + "' (supported: .msh, .geo, .obj, .off)");
}

}  // namespace iga
