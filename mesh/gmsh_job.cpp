#include "mesh/gmsh_job.hpp"

#include <gmsh.h>

#include <algorithm>

#include "config/errors.hpp"
#include "mesh/gmsh_model_mesh.hpp"
#include "mesh/gmsh_model_surface.hpp"
#include "mesh/gmsh_session.hpp"

namespace iga {

namespace {

void mesh_polygon_here(const GmshJob& job) {
  using Loop = std::vector<Eigen::Vector2d>;
  const double h = job.mesh_size;
  std::vector<const Loop*> loops = {&job.polygon.outer};
  for (const Loop& hole : job.polygon.holes) loops.push_back(&hole);
  std::vector<int> curve_loops;
  std::vector<std::vector<int>> loop_lines;
  for (const Loop* loop : loops) {
    std::vector<int> points, lines;
    for (const auto& x : *loop) points.push_back(gmsh::model::geo::addPoint(x.x(), x.y(), 0.0, h));
    for (std::size_t k = 0; k < loop->size(); ++k)
      lines.push_back(gmsh::model::geo::addLine(points[k], points[(k + 1) % loop->size()]));
    curve_loops.push_back(gmsh::model::geo::addCurveLoop(lines));
    loop_lines.push_back(std::move(lines));
  }
  gmsh::model::geo::addPlaneSurface(curve_loops);
  gmsh::model::geo::synchronize();
  // Physical groups on the synchronized model (a later geo synchronize would drop them).
  for (std::size_t k = 0; k < loop_lines[0].size(); ++k)
    gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {loop_lines[0][k]}),
                                 "side" + std::to_string(k + 1));
  for (std::size_t l = 1; l < loop_lines.size(); ++l)
    gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, loop_lines[l]), "hole" + std::to_string(l));
  gmsh::option::setNumber("Mesh.MeshSizeMax", h);
}

/// The bounding box area of the model's surfaces (0 without surfaces).
double surface_box_area() {
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  if (surfaces.empty()) return 0.0;
  double lo_x = 0, lo_y = 0, hi_x = 0, hi_y = 0;
  for (std::size_t k = 0; k < surfaces.size(); ++k) {
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(2, surfaces[k].second, x0, y0, z0, x1, y1, z1);
    lo_x = k ? std::min(lo_x, x0) : x0, lo_y = k ? std::min(lo_y, y0) : y0;
    hi_x = k ? std::max(hi_x, x1) : x1, hi_y = k ? std::max(hi_y, y1) : y1;
  }
  return (hi_x - lo_x) * (hi_y - lo_y);
}

/// Surfaces in 3D: the sum of the surfaces' bounding-box surface areas (an estimate of the area
/// to mesh that does not depend on how the surfaces sit in space; 0 without surfaces).
double surface_box_area_3d() {
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  double area = 0.0;
  for (const auto& [dim, tag] : surfaces) {
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(dim, tag, x0, y0, z0, x1, y1, z1);
    const double a = x1 - x0, b = y1 - y0, c = z1 - z0;
    area += 2.0 * (a * b + b * c + c * a);
  }
  return area;
}

}  // namespace

SurfaceMeshFile run_gmsh_surface_job_here(const GmshJob& job) {
  if (job.kind == GmshJob::mesh_polygon) throw InputError(job.source + ": a polygon is not a surface in 3D");
  SurfaceMeshFile mesh;
  with_gmsh(job.source, [&] {
    gmsh::open(job.path);
    if (job.kind == GmshJob::mesh_geo) {
      if (job.mesh_size > 0.0) {
        check_element_estimate(surface_box_area_3d(), job.mesh_size, job.limits, job.source);
        gmsh::option::setNumber("Mesh.MeshSizeMax", job.mesh_size);
      }
      gmsh::model::mesh::generate(2);
    }
    mesh = surface_mesh_from_gmsh_model(job.source);
  });
  return mesh;
}

PlanarMesh run_gmsh_job_here(const GmshJob& job) {
  PlanarMesh mesh;
  with_gmsh(job.source, [&] {
    if (job.kind == GmshJob::mesh_polygon) {
      mesh_polygon_here(job);
    } else {
      gmsh::open(job.path);
      if (job.kind == GmshJob::mesh_geo && job.mesh_size > 0.0) {
        check_element_estimate(surface_box_area(), job.mesh_size, job.limits, job.source);
        gmsh::option::setNumber("Mesh.MeshSizeMax", job.mesh_size);
      }
    }
    if (job.kind != GmshJob::read_msh) {
      if (job.recombine) gmsh::option::setNumber("Mesh.RecombineAll", 1);
      gmsh::model::mesh::generate(2);
    }
    mesh = planar_mesh_from_gmsh_model(job.source);
  });
  return mesh;
}

}  // namespace iga
