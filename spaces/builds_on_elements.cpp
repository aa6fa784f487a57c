#include "spaces/builds_on_elements.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace iga {

void check_element_set(const std::vector<int>& elements, int num_elements, const char* who) {
  if (!std::is_sorted(elements.begin(), elements.end()) ||
      std::adjacent_find(elements.begin(), elements.end()) != elements.end() ||
      (!elements.empty() && (elements.front() < 0 || elements.back() >= num_elements)))
    throw std::invalid_argument(std::string(who) + ": the elements must be increasing element numbers");
}

SpacePtr on_elements(const SpacePtr& space, const std::vector<int>& elements) {
  const auto* builds = dynamic_cast<const BuildsOnElements*>(space.get());
  if (!builds || std::all_of(elements.begin(), elements.end(), [&](int e) { return builds->built_on(e); }))
    return space;
  return builds->build_on(elements);
}

}  // namespace iga
