#include "output/surface_geometry_vtk.hpp"

#include <Eigen/Geometry>  // cross
#include <stdexcept>

#include "output/surface_vtk.hpp"

namespace iga {

void write_surface_geometry_vtu(const Space& space, int samples, const std::string& filename) {
  if (space.ambient_dimension() != 3)
    throw std::invalid_argument("write_surface_geometry_vtu: the space is not on a surface in 3D");
  const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
  std::vector<Eigen::Vector3d> points, normals;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> patch;
  std::vector<int> first_point;
  PointValues geometry;
  for (int e = 0; e < space.num_elements(); ++e) {
    const SampleCell cell = space.sample_cell(e, samples);
    QuadratureRule rule;
    rule.points = cell.points;
    rule.weights.assign(cell.points.size(), 0.0);
    evaluator->evaluate_geometry(e, rule, geometry);
    const int base = static_cast<int>(points.size());
    first_point.push_back(base);
    for (int k = 0; k < rule.size(); ++k) {
      points.push_back(geometry.x3.col(k));
      normals.push_back(geometry.jacobian3[k].col(0).cross(geometry.jacobian3[k].col(1)).normalized());
    }
    for (const std::vector<int>& c : cell.cells) {
      triangles.push_back({base + c[0], base + c[1], base + c[2]});
      patch.push_back(e);
      if (c.size() == 4) {
        triangles.push_back({base + c[0], base + c[2], base + c[3]});
        patch.push_back(e);
      }
    }
  }
  first_point.push_back(static_cast<int>(points.size()));
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& p : points) centroid += p;
  centroid /= std::max<std::size_t>(points.size(), 1);
  // One orientation per element: the one that points away from the centroid on average.
  for (int e = 0; e < space.num_elements(); ++e) {
    double outward = 0.0;
    for (int k = first_point[e]; k < first_point[e + 1]; ++k) outward += normals[k].dot(points[k] - centroid);
    if (outward < 0.0)
      for (int k = first_point[e]; k < first_point[e + 1]; ++k) normals[k] = -normals[k];
  }
  write_surface_vtu(points, normals, triangles, patch, filename);
}

}  // namespace iga
