#include "spaces/surface_label.hpp"

#include "geometry/surface_patches.hpp"

namespace iga {

std::string surface_label(const Space& space, const std::string& key) {
  if (!space.surface_patches()) return {};
  for (const auto& [k, value] : space.surface_patches()->labels)
    if (k == key) return value;
  return {};
}

}  // namespace iga
