#include "spaces/g1/g1_from_config.hpp"

#include "solver/errors.hpp"
#include "spaces/g1/g1_space.hpp"
#include "spaces/g1/multipatch_domains.hpp"

namespace iga {

SpacePtr make_g1_space(const ConfigNode& domain, const ConfigNode& space, int level) {
  space.check_keys({"type", "degree"});
  if (space.has("type")) space["type"].as_choice({"g1"});
  domain.check_keys({"type", "name"});
  domain["type"].as_choice({"multipatch"});
  const std::string name = domain["name"].as_choice(multipatch_domain_names());
  const ConfigNode dn = space["degree"];
  const int k = dn.as_int();
  if (k < 3) dn.fail("G1 splines need degree >= 3 (got " + std::to_string(k) + "); generic vertices need 5");
  if (k > 10) dn.fail("G1 degree must be at most 10 (got " + std::to_string(k) + ")");
  if (level < 0 || level > 8) space.fail("refinement level must be in 0..8 (got " + std::to_string(level) + ")");
  PatchMesh mesh = multipatch_domain(name);
  for (int l = 0; l < level; ++l) mesh = mesh.refined();
  try {
    return std::make_shared<const G1Space>(std::make_shared<const PatchMesh>(std::move(mesh)), k);
  } catch (const InputError& e) {
    dn.fail(e.what());
  }
}

}  // namespace iga
