#include "geometry/surface_from_config.hpp"

#include <cctype>
#include <filesystem>

#include "config/config_file_path.hpp"
#include "geometry/builtin_surface_meshes.hpp"

namespace iga {

namespace {

const std::vector<std::string> builtin_names = {"icosphere", "octahedron", "tetrahedron", "perturbed_octahedron",
                                                "height_field"};

}  // namespace

TriangleSurfaceMesh surface_mesh_from_config(const ConfigNode& domain, int study_level) {
  domain.check_keys({"type", "mesh", "level", "file", "mesh_size", "normals", "tuple", "method"});
  const bool builtin = domain.has("mesh"), file = domain.has("file");
  if (builtin == file)
    domain.fail("give either 'mesh' (a built-in surface) or 'file' (.obj, .off, .stl, .msh or .geo), not both");
  if (const auto size = domain.find("mesh_size"); size && !file) size->fail("'mesh_size' applies to a .geo 'file' only");
  if (const auto level = domain.find("level"); level && (!builtin || domain["mesh"].as_string() != "icosphere"))
    level->fail("'level' applies to mesh: icosphere only");
  if (study_level >= 0) {
    if (!builtin || domain["mesh"].as_string() != "icosphere")
      domain.fail("a geometry study refines mesh: icosphere (its levels are the study's levels)");
    if (const auto level = domain.find("level")) level->fail("the geometry study sets the icosphere level (study.levels)");
  }
  TriangleSurfaceMesh mesh;
  std::string normals_default;
  std::vector<std::string> normal_choices;
  if (builtin) {
    const std::string name = domain["mesh"].as_choice(builtin_names);
    if (name == "icosphere") {
      if (study_level >= 0) {
        mesh = icosphere(study_level);
      } else {
        const ConfigNode level = domain["level"];
        const int l = level.as_int();
        if (l < 0 || l > 8) level.fail("level must be in 0..8");
        mesh = icosphere(l);
      }
    } else if (name == "octahedron") {
      mesh = regular_octahedron();
    } else if (name == "tetrahedron") {
      mesh = regular_tetrahedron();
    } else if (name == "perturbed_octahedron") {
      mesh = perturbed_octahedron();
    } else {
      mesh = height_field();
    }
    normals_default = "exact";
    normal_choices = {"exact", "estimated", "fan"};
  } else {
    const ConfigNode node = domain["file"];
    const std::filesystem::path path = resolve_config_file(node);
    SurfaceFileOptions options;
    options.config_folder = config_folder(node).string();
    if (const auto size = domain.find("mesh_size")) {
      options.mesh_size = size->as_double();
      if (!(options.mesh_size > 0.0)) size->fail("mesh_size must be > 0");
      std::string ext = path.extension().string();
      for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (ext != ".geo") size->fail("'mesh_size' applies to .geo files only (a mesh is used as it is)");
    }
    const SurfaceMeshFile read = node.guard([&] { return read_surface_mesh(path.string(), options); });
    mesh = node.guard([&] { return surface_mesh_from_file(read); });
    normals_default = read.normals.empty() ? "estimated" : "file";
    normal_choices = read.normals.empty() ? std::vector<std::string>{"estimated", "fan"}
                                          : std::vector<std::string>{"file", "estimated", "fan"};
  }
  const auto normals_node = domain.find("normals");
  const std::string normals = normals_node ? normals_node->as_choice(normal_choices) : normals_default;
  const ConfigNode& at = normals_node ? *normals_node : domain;
  if (normals == "estimated") mesh.normals = at.guard([&] { return angle_weighted_normals(mesh); });
  if (normals == "fan") mesh.normals = at.guard([&] { return fan_normals(mesh); });
  return mesh;
}

rsd::RsdOptions rsd_options_from_config(const ConfigNode& domain) {
  rsd::RsdOptions options;
  if (const auto n = domain.find("tuple"))
    options.tuple = n->as_choice({"pi0", "pi1"}) == "pi0" ? rsd::RsdTuple::pi0 : rsd::RsdTuple::pi1;
  if (const auto n = domain.find("method")) {
    const std::string m = n->as_choice({"hermite", "paper", "none"});
    options.method = m == "hermite" ? rsd::RsdMethod::hermite : (m == "paper" ? rsd::RsdMethod::paper : rsd::RsdMethod::none);
  }
  return options;
}

rsd::RsdSurface surface_from_config(const ConfigNode& domain, int study_level) {
  const TriangleSurfaceMesh mesh = surface_mesh_from_config(domain, study_level);
  const rsd::RsdOptions options = rsd_options_from_config(domain);
  return domain.guard([&] { return rsd::build_rsd_surface(mesh, options); });
}

}  // namespace iga
