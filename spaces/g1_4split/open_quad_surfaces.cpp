#include "spaces/g1_4split/open_quad_surfaces.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "spaces/g1_4split/g1_4split_meshes.hpp"
#include "spaces/g1_4split/g1_4split_surface.hpp"

namespace iga {

std::vector<std::string> open_quad_surface_names() { return {"open_cube", "cylinder_band", "cap_fan5", "cap_fan5+"}; }

std::pair<QuadTopology, std::vector<Eigen::Vector3d>> open_quad_surface(const std::string& name) {
  if (name == "open_cube") {
    // cube_topology without face 1 (z = 1), same vertex ids x + 2y + 4z.
    const QuadTopology cube = cube_topology();
    std::vector<std::array<int, 4>> faces;
    for (int f = 0; f < cube.num_faces(); ++f)
      if (f != 1) faces.push_back(cube.face(f));
    return {QuadTopology(8, std::move(faces), name), cube_vertices()};
  }
  if (name == "cylinder_band") {
    const int around = 8, high = 2;
    const double pi = std::acos(-1.0);
    std::vector<Eigen::Vector3d> v;
    for (int j = 0; j <= high; ++j)
      for (int i = 0; i < around; ++i)
        v.emplace_back(std::cos(2 * pi * i / around), std::sin(2 * pi * i / around), double(j) / high);
    std::vector<std::array<int, 4>> faces;
    const auto id = [&](int i, int j) { return i % around + around * j; };
    for (int j = 0; j < high; ++j)
      for (int i = 0; i < around; ++i) faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    return {QuadTopology(static_cast<int>(v.size()), std::move(faces), name), v};
  }
  if (name == "cap_fan5" || name == "cap_fan5+") {
    const PatchMesh planar = g14_domain(name.substr(4));
    double reach = 0.0;
    for (int i = 0; i < planar.num_vertices(); ++i) reach = std::max(reach, planar.vertex(i).norm());
    const double R = 1.25 * reach;
    std::vector<Eigen::Vector3d> v;
    for (int i = 0; i < planar.num_vertices(); ++i) {
      const Point2 p = planar.vertex(i);
      v.emplace_back(p.x(), p.y(), std::sqrt(R * R - p.squaredNorm()));
    }
    std::vector<std::array<int, 4>> faces;
    for (int f = 0; f < planar.num_faces(); ++f) {
      const auto& q = planar.face(f);  // the fans are quads only
      faces.push_back({q[0], q[1], q[2], q[3]});
    }
    return {QuadTopology(planar.num_vertices(), std::move(faces), name), v};
  }
  throw std::invalid_argument("unknown open quad surface '" + name + "'");
}

}  // namespace iga
