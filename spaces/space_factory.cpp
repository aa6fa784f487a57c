#include "spaces/space_factory.hpp"

#include "spaces/bspline/bspline_from_config.hpp"
#include "spaces/tmesh/tmesh_from_config.hpp"

namespace iga {

std::vector<std::string> space_types() { return {"bspline", "tmesh"}; }

SpacePtr make_space(const ConfigNode& domain, const ConfigNode& space, int level) {
  const std::string type = space["type"].as_choice(space_types());
  if (type == "bspline") return make_bspline_space(domain, space, level);
  if (type == "tmesh") return make_tmesh_space(domain, space, level);
  space["type"].fail("unsupported space type '" + type + "'");
}

}  // namespace iga
