#include "spaces/g1/g1_from_config.hpp"

#include <filesystem>

#include "config/errors.hpp"
#include "spaces/g1/g1_space.hpp"
#include "spaces/g1/multipatch_domains.hpp"
#include "spaces/g1/patch_mesh_from_file.hpp"
#include "mesh/mesh_file_from_config.hpp"
#include "spaces/space_catalogue.hpp"

namespace iga {

PatchMesh patch_mesh_from_config(const ConfigNode& domain) {
  domain.check_keys({"type", "file", "mesh_size", "recombine"});
  const MeshFileRequest request = mesh_file_request(domain);
  return domain["file"].guard([&] { return patch_mesh_from_file(request.path.string(), request.options); });
}

SpacePtr make_g1_space(const ConfigNode& domain, const ConfigNode& space, int level, SpaceExtent extent) {
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
                                        : patch_mesh_from_config(domain);
  for (int l = 0; l < level; ++l) mesh = mesh.refined();
  return dn.guard([&] { return std::make_shared<const G1Space>(std::make_shared<const PatchMesh>(std::move(mesh)), k, extent); });
}

SpaceCatalogueEntry g1_catalogue_entry() {
  // ../shared/notes/g1-multipatch-mvv.md and g1-routeA-evidence.md: geometry-derived G1 = C1 in the plane.
  return {"g1",
          "one polynomial per (sub-)patch, bidegree (k, k) on quadrilaterals, degree k on triangles, 3 <= k <= 10; "
          "C1 across all interfaces",
          {{"multipatch", "name: a built-in layout", "name", multipatch_domain_names()},
           {"mesh_file", "file: .msh, .geo (mesh_size, recombine), .obj, .off, G+Smo .xml of bilinear patches", "", {}}}};
}

}  // namespace iga
