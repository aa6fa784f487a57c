#include "geometry/rsd/surface_sampling.hpp"

#include <Eigen/Geometry>
#include <map>
#include <stdexcept>
#include <tuple>

namespace iga::rsd {

SampledSurface sample_surface(const RsdSurface& surface, int s) { return sample_surface(surface_patches_of(surface), s); }

SampledSurface sample_surface(const SurfacePatches& surface, int s) {
  if (s < 1) throw std::invalid_argument("sample_surface: subdivisions must be at least 1");
  SampledSurface out;
  // A lattice point is a mesh vertex, a point on a mesh edge (counted from its smaller vertex),
  // or interior to one patch; the key makes shared points unique.
  std::map<std::tuple<int, int, int, int>, int> index;
  for (int n = 0; n < static_cast<int>(surface.patches.size()); ++n) {
    const auto& tri = surface.vertices[n];
    const BezierTriangle& patch = surface.patches[n];
    auto point_id = [&](int a1, int a2) {
      const int alpha[3] = {a1, a2, s - a1 - a2};
      std::tuple<int, int, int, int> key;
      int zeros = 0;
      for (int a : alpha) zeros += a == 0;
      if (zeros == 2) {
        const int c = alpha[0] == s ? 0 : (alpha[1] == s ? 1 : 2);
        key = {0, tri[c], 0, 0};
      } else if (zeros == 1) {
        const int c = alpha[0] == 0 ? 0 : (alpha[1] == 0 ? 1 : 2);
        const int a = (c + 1) % 3, b = (c + 2) % 3;
        const int i = std::min(tri[a], tri[b]), j = std::max(tri[a], tri[b]);
        key = {1, i, j, tri[a] == i ? alpha[a] : alpha[b]};
      } else {
        key = {2, n, a1, a2};
      }
      const auto found = index.find(key);
      if (found != index.end()) return found->second;
      const Eigen::Vector3d t(double(alpha[0]) / s, double(alpha[1]) / s, double(alpha[2]) / s);
      const auto d = patch.partials(t);
      out.points.push_back(patch.value(t));
      out.normals.push_back((d[1] - d[0]).cross(d[2] - d[0]).normalized());
      const int id = static_cast<int>(out.points.size()) - 1;
      index.emplace(key, id);
      return id;
    };
    // Sub-triangles of the lattice, oriented like (e1, e2, e3).
    for (int a1 = 0; a1 < s; ++a1)
      for (int a2 = 0; a1 + a2 < s; ++a2) {
        out.triangles.push_back({point_id(a1 + 1, a2), point_id(a1, a2 + 1), point_id(a1, a2)});
        out.patch.push_back(n);
        if (a1 + a2 + 2 <= s) {
          out.triangles.push_back({point_id(a1 + 1, a2), point_id(a1 + 1, a2 + 1), point_id(a1, a2 + 1)});
          out.patch.push_back(n);
        }
      }
  }
  return out;
}

}  // namespace iga::rsd
