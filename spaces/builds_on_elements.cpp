#include "spaces/builds_on_elements.hpp"

#include <algorithm>

namespace iga {

SpacePtr on_elements(const SpacePtr& space, const std::vector<int>& elements) {
  const auto* builds = dynamic_cast<const BuildsOnElements*>(space.get());
  if (!builds || std::all_of(elements.begin(), elements.end(), [&](int e) { return builds->built_on(e); }))
    return space;
  return builds->build_on(elements);
}

}  // namespace iga
