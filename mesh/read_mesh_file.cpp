#include "mesh/read_mesh_file.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "mesh/geo_script_check.hpp"
#include "mesh/gismo_xml.hpp"
#include "mesh/gmsh_worker.hpp"
#include "mesh/msh_structure_check.hpp"
#include "mesh/read_text_meshes.hpp"

namespace iga {

namespace {

/// Checks the file in our own code first (a .geo's statements, a .msh's structure), then lets the
/// Gmsh worker read or mesh it.
PlanarMesh read_with_gmsh(const std::string& path, const MeshFileOptions& options, bool mesh_geometry) {
  const MeshLimits& limits = options.limits;
  namespace fs = std::filesystem;
  std::vector<fs::path> roots = {fs::absolute(path).parent_path()};
  if (!options.config_folder.empty()) roots.push_back(fs::absolute(options.config_folder));
  std::vector<fs::path> inputs = {path};
  if (mesh_geometry) {
    inputs = check_geo_script(path, roots, limits);
  } else {
    check_msh_structure(path, limits);
    // Gmsh runs "<file>.opt" when it opens <file>, whatever the file is.
    if (std::error_code ec; fs::exists(path + ".opt", ec)) {
      const auto options_file = check_geo_script(path + ".opt", roots, limits);
      inputs.insert(inputs.end(), options_file.begin(), options_file.end());
    }
  }
  GmshJob job;
  job.kind = mesh_geometry ? GmshJob::mesh_geo : GmshJob::read_msh;
  job.path = fs::absolute(path).string();
  job.source = path;
  job.mesh_size = options.mesh_size;
  job.recombine = options.recombine;
  for (const auto& root : roots) job.readable_folders.push_back(root.string());
  job.limits = limits;
  return run_gmsh_job_cached(job, inputs);
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
  if (extension == ".xml") return bilinear_patch_mesh(read_gismo_xml(path));
  throw InputError(path + ": unknown mesh file extension '" + extension + "' (supported: .msh, .geo, .obj, .off, .xml)");
}

}  // namespace iga
