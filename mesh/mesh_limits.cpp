#include "mesh/mesh_limits.hpp"

#include <cmath>

#include "config/config_node.hpp"
#include "config/errors.hpp"

namespace iga {

double estimated_triangles(double area, double h) { return area / (std::sqrt(3.0) / 4.0 * h * h); }

void check_element_estimate(double area, double h, const MeshLimits& limits, const std::string& source) {
  const double estimate = estimated_triangles(area, h);
  if (!(estimate <= limits.max_elements))
    throw InputError(source + ": mesh size " + format_number(h) + " on an area of " + format_number(area) +
                     " gives about " + format_number(estimate) + " triangles, more than the limit of " +
                     format_number(limits.max_elements) + " elements (use a larger mesh size, or raise limits.max_elements in the config)");
}

}  // namespace iga
