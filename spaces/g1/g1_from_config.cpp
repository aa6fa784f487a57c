#include "spaces/g1/g1_from_config.hpp"

#include <filesystem>

#include "solver/errors.hpp"
#include "spaces/g1/g1_space.hpp"
#include "spaces/g1/multipatch_domains.hpp"
#include "spaces/g1/patch_mesh_from_file.hpp"

namespace iga {

namespace {

/// Runs `build`, prefixing its InputError with the config place of `node` (FILE:LINE:COL: key).
template <class Build>
auto at_config(const ConfigNode& node, Build&& build) {
  try {
    return build();
  } catch (const InputError& e) {
    node.fail(e.what());
  }
}

/// `domain: {type: mesh_file, file, mesh_size, recombine}`: a relative path is relative to the
/// config file's folder; mesh_size and recombine apply to .geo files (meshed by Gmsh) only.
PatchMesh mesh_file(const ConfigNode& domain) {
  domain.check_keys({"type", "file", "mesh_size", "recombine"});
  const ConfigNode file = domain["file"];
  std::filesystem::path path = file.as_string();
  if (path.is_relative()) path = std::filesystem::path(file.file()).parent_path() / path;
  MeshFileOptions options;
  for (const char* key : {"mesh_size", "recombine"})
    if (const auto n = domain.find(key); n && path.extension() != ".geo")
      n->fail(std::string(key) + " applies to .geo files only (a mesh file is used as it is)");
  if (const auto n = domain.find("mesh_size")) {
    options.mesh_size = n->as_double();
    if (!(options.mesh_size > 0.0)) n->fail("mesh_size must be positive");
  }
  if (const auto n = domain.find("recombine")) options.recombine = n->as_bool();
  return at_config(file, [&] { return patch_mesh_from_file(path.string(), options); });
}

}  // namespace

SpacePtr make_g1_space(const ConfigNode& domain, const ConfigNode& space, int level) {
  space.check_keys({"type", "degree"});
  if (space.has("type")) space["type"].as_choice({"g1"});
  const std::string type = domain["type"].as_choice({"multipatch", "mesh_file"});
  if (type == "multipatch") domain.check_keys({"type", "name"});
  const ConfigNode dn = space["degree"];
  const int k = dn.as_int();
  if (k < 3) dn.fail("G1 splines need degree >= 3 (got " + std::to_string(k) + "); generic vertices need 5");
  if (k > 10) dn.fail("G1 degree must be at most 10 (got " + std::to_string(k) + ")");
  if (level < 0 || level > 8) space.fail("refinement level must be in 0..8 (got " + std::to_string(level) + ")");
  PatchMesh mesh = type == "multipatch" ? multipatch_domain(domain["name"].as_choice(multipatch_domain_names()))
                                        : mesh_file(domain);
  for (int l = 0; l < level; ++l) mesh = mesh.refined();
  return at_config(dn, [&] { return std::make_shared<const G1Space>(std::make_shared<const PatchMesh>(std::move(mesh)), k); });
}

}  // namespace iga
