#include "output/surface_report.hpp"

#include <cmath>

namespace iga {

nlohmann::json surface_report_json(const SurfacePatches& surface) {
  nlohmann::json j;
  for (const auto& [key, value] : surface.labels) j[key] = value;
  j["patches"] = surface.patches.size();
  for (const auto& [key, value] : surface.measures) {
    if (!std::isfinite(value))
      j[key] = nullptr;
    else if (value == std::round(value) && std::abs(value) < 1e15)
      j[key] = static_cast<long long>(value);
    else
      j[key] = value;
  }
  return j;
}

}  // namespace iga
