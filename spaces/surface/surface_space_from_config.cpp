#include "spaces/surface/surface_space_from_config.hpp"

#include <map>
#include <mutex>

#include <yaml-cpp/yaml.h>

#include "geometry/surface_from_config.hpp"
#include "spaces/surface/surface_space.hpp"

namespace iga {

namespace {

/// The surface of a domain node, built once per config place: every level refines the same surface
/// (and its construction is the expensive part on large meshes).
std::shared_ptr<const rsd::RsdSurface> cached_surface(const ConfigNode& domain) {
  static std::mutex mutex;
  static std::map<std::string, std::weak_ptr<const rsd::RsdSurface>> cache;
  static std::shared_ptr<const rsd::RsdSurface> last;  // keeps the latest alive between levels
  std::lock_guard<std::mutex> lock(mutex);
  // The place and the node's text: two YAML snippets may share a place name.
  const std::string key = domain.where() + "\n" + YAML::Dump(domain.yaml());
  if (auto hit = cache[key].lock()) {
    last = hit;
    return hit;
  }
  auto surface = std::make_shared<const rsd::RsdSurface>(surface_from_config(domain));
  cache[key] = surface;
  last = surface;
  return surface;
}

}  // namespace

SpacePtr make_surface_space(const ConfigNode& domain, const ConfigNode& space, int level) {
  if (domain["type"].as_choice({"surface"}) != "surface") domain["type"].fail("expected type: surface");
  space.check_keys({"type", "degree"});
  const ConfigNode degree_node = space["degree"];
  const int degree = degree_node.as_int();
  if (degree < 1 || degree > 8) degree_node.fail("degree must be in 1..8 (got " + std::to_string(degree) + ")");
  if (level < 0 || level > 6) domain.fail("surface spaces are refined at most 6 times (4096 sub-triangles per patch)");
  auto surface = cached_surface(domain);
  return std::make_shared<SurfaceBernsteinSpace>(std::move(surface), degree, 1 << level);
}

}  // namespace iga
