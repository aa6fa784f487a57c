#include "mesh/planar_coordinates.hpp"

#include "config/config_node.hpp"
#include "config/errors.hpp"

namespace iga {

std::vector<Eigen::Vector2d> planar_coordinates(const std::vector<Eigen::Vector3d>& points,
                                                const std::vector<std::string>& origins, const std::string& source) {
  std::vector<Eigen::Vector2d> result;
  for (std::size_t k = 0; k < points.size(); ++k)
    if (!points[k].allFinite())
      throw InputError(source + ": vertex " + std::to_string(k) +
                       (k < origins.size() ? " (" + origins[k] + ")" : std::string()) +
                       " has a coordinate that is not finite");
  if (points.empty()) return result;
  Eigen::Vector2d lo = points[0].head<2>(), hi = lo;
  for (const auto& p : points) {
    lo = lo.cwiseMin(p.head<2>());
    hi = hi.cwiseMax(p.head<2>());
  }
  const double eps = 1e-10 * (hi - lo).norm();
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (std::abs(points[k].z() - points[0].z()) > eps) {
      const std::string origin = k < origins.size() ? " (" + origins[k] + ")" : "";
      throw InputError(source + ": vertex " + std::to_string(k) + origin + " has z = " + format_number(points[k].z()) +
                       ", vertex 0 has z = " + format_number(points[0].z()) +
                       ": the mesh must lie in a plane z = const");
    }
    result.push_back(points[k].head<2>());
  }
  return result;
}

}  // namespace iga
