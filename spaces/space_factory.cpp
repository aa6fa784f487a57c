#include "spaces/space_factory.hpp"

#include "spaces/bspline/bspline_from_config.hpp"
#include "spaces/g1/g1_from_config.hpp"
#include "spaces/g1_4split/g1_4split_from_config.hpp"
#include "spaces/graph/graph_from_config.hpp"
#include "spaces/surface/surface_space_from_config.hpp"
#include "spaces/tmesh/tmesh_from_config.hpp"
#include "spaces/ws4/ws4_from_config.hpp"

namespace iga {

std::vector<std::string> space_types() { return {"bspline", "ws4", "tmesh", "g1", "g1_4split", "surface"}; }

std::vector<SpaceCatalogueEntry> space_catalogue() {
  return {bspline_catalogue_entry(), ws4_catalogue_entry(),       tmesh_catalogue_entry(),
          g1_catalogue_entry(),      g1_4split_catalogue_entry(), surface_catalogue_entry()};
}

std::vector<DomainFamily> lifted_domain_families() { return {graph_domain_family()}; }

SpacePtr make_space(const ConfigNode& domain, const ConfigNode& space, int level, const Space* coarser,
                    SpaceExtent extent) {
  // A graph surface z = g(x, y): the planar space on domain.over, lifted.
  if (is_graph_domain(domain))
    return make_graph_space(domain, space, [&](const ConfigNode& over) {
      return make_space(over, space, level, planar_of_graph(coarser));
    });
  const std::string type = space["type"].as_choice(space_types());
  if (type == "bspline") return make_bspline_space(domain, space, level);
  if (type == "ws4") return make_ws4_space(domain, space, level, extent);
  if (type == "tmesh") return make_tmesh_space(domain, space, level);
  if (type == "g1") return make_g1_space(domain, space, level, extent);
  if (type == "g1_4split") return make_g1_4split_space(domain, space, level, extent);
  if (type == "surface") return make_surface_space(domain, space, level, coarser);
  space["type"].fail("unsupported space type '" + type + "'");
}

std::vector<SpaceRequestSize> requested_space_sizes(const ConfigNode& domain, const ConfigNode& space, int levels) {
  if (is_graph_domain(domain) && domain.find("over")) return requested_space_sizes(domain["over"], space, levels);
  const auto type = space.is_map() ? space.find("type") : std::nullopt;
  const auto domain_type = domain.is_map() ? domain.find("type") : std::nullopt;
  const bool surface_patch = domain_type && domain_type->is_scalar() && domain_type->as_string() == "surface_patch";
  if (type && type->is_scalar() && type->as_string() == "bspline" && !surface_patch)
    return bspline_requested_sizes(space, levels);
  if (type && type->is_scalar() && type->as_string() == "g1_4split")
    return g1_4split_requested_sizes(domain, space, levels);
  return {};
}

}  // namespace iga
