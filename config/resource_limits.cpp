#include "config/resource_limits.hpp"

#include <unistd.h>

#include <cmath>

namespace iga {

double default_memory_gb() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page_size = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return 16.0;
  return 0.75 * static_cast<double>(pages) * static_cast<double>(page_size) / 1e9;
}

ResourceLimits parse_limits(const std::optional<ConfigNode>& section) {
  ResourceLimits limits;
  limits.max_memory_gb = default_memory_gb();
  if (!section) return limits;
  section->check_keys({"max_degree", "max_elements", "max_dofs", "max_memory_gb"});
  limits.where = section->where();
  auto positive = [&](const char* key, double& value) {
    if (auto node = section->find(key)) {
      value = node->as_double();
      if (!(value > 0.0) || !std::isfinite(value)) node->fail(std::string(key) + " must be a positive number");
    }
  };
  double degree = limits.max_degree;
  positive("max_degree", degree);
  if (degree != std::floor(degree) || degree > 1000) section->find("max_degree")->fail("max_degree must be an integer <= 1000");
  limits.max_degree = static_cast<int>(degree);
  positive("max_elements", limits.max_elements);
  positive("max_dofs", limits.max_dofs);
  positive("max_memory_gb", limits.max_memory_gb);
  return limits;
}

std::string how_to_raise(const std::string& key) {
  return " (raise limits." + key + " in the config if this is intended, e.g. limits: {" + key + ": ...})";
}

}  // namespace iga
