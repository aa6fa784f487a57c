#include "mesh/gmsh_job.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "config/errors.hpp"
#include "config/config_node.hpp"
#include "mesh/geo_script_check.hpp"
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

/// The diagonal of the whole model's bounding box (Gmsh's size where nothing gives one).
double model_diagonal() {
  double x0, y0, z0, x1, y1, z1;
  gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
  return std::hypot(x1 - x0, y1 - y0, z1 - z0);
}

/// Refuses an entity of dimension `dim` (volumes for surfaces in 3D, surfaces for planar meshes)
/// that is flat: its bounding box thinner than 1e-6 of its largest extent in some direction (a
/// solid dilated to zero thickness, a planar surface squeezed onto a line). Gmsh does not fail on
/// those: it meshes the surfaces that fold onto each other until the time limit.
void check_flat_entities(const GmshJob& job, int dim) {
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, dim);
  const int directions = dim == 3 ? 3 : 2;  // a planar surface is flat in z by nature
  for (const auto& [d, tag] : entities) {
    double lo[3], hi[3];
    gmsh::model::getBoundingBox(d, tag, lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
    for (int k = 0; k < directions; ++k) {
      largest = std::max(largest, hi[k] - lo[k]);
      smallest = std::min(smallest, hi[k] - lo[k]);
    }
    if (largest > 0.0 && !(smallest > 1e-6 * largest))
      throw InputError(job.source + ": " + (dim == 3 ? "volume " : "surface ") + std::to_string(tag) +
                       " is flat (its bounding box is " + format_number(hi[0] - lo[0]) + " x " +
                       format_number(hi[1] - lo[1]) + (dim == 3 ? " x " + format_number(hi[2] - lo[2]) : "") +
                       "): a shape dilated or scaled to zero thickness has no " + (dim == 3 ? "surface" : "area") +
                       " to mesh");
  }
}

/// How far the estimate below may exceed the element limit before a script is refused: the
/// bounding box overstates the area (4/pi for a disc, 2 for a triangle, more for a thin strip
/// across the box), and a mesh is refused only when it is clearly too fine.
constexpr double kScriptEstimateSafety = 8.0;

/// Refuses a .geo whose own sizes would give far more elements than the limit, after Gmsh has
/// read the script and before it meshes. The estimate assumes what Gmsh does by default: sizes
/// come from the points (`lc`, MeshSize), are interpolated along the curves and extended inside,
/// then clamped to [Mesh.MeshSizeMin, Mesh.MeshSizeMax] (the config's mesh_size is that maximum)
/// and scaled by Mesh.MeshSizeFactor (Mesh.CharacteristicLengthFactor is its old name). So no
/// element is larger than h = factor * clamp(largest point size, min, max), and at least
/// box area / (sqrt(3)/4 h^2) triangles cover a box-filling domain. Fields, curvature sizes and
/// transfinite counts only make a mesh finer; the time limit remains their backstop. A size the
/// static pass cannot evaluate counts as unbounded, so the estimate never refuses on a guess.
void check_script_sizes(const GmshJob& job, double box_area) {
  if (!(box_area > 0.0)) return;  // no surface: nothing to mesh (reported after meshing, as for any script)
  std::vector<std::filesystem::path> roots(job.readable_folders.begin(), job.readable_folders.end());
  double point_size = geo_script_largest_point_size(job.path, roots, job.limits);
  double from_points = 1.0, lo = 0.0, hi = 0.0, factor = 1.0;
  gmsh::option::getNumber("Mesh.MeshSizeFromPoints", from_points);
  gmsh::option::getNumber("Mesh.MeshSizeMin", lo);
  gmsh::option::getNumber("Mesh.MeshSizeMax", hi);
  gmsh::option::getNumber("Mesh.MeshSizeFactor", factor);
  if (from_points == 0.0) point_size = std::numeric_limits<double>::infinity();
  const double h = factor * std::min({std::max(point_size, lo), hi, model_diagonal()});
  const double estimate = estimated_triangles(box_area, h);
  if (!(estimate <= kScriptEstimateSafety * job.limits.max_elements))
    throw InputError(job.source + ": the script's mesh sizes (largest point size " + format_number(point_size) +
                     ", Mesh.MeshSizeMin " + format_number(lo) + ", Mesh.MeshSizeMax " + format_number(hi) +
                     ", Mesh.MeshSizeFactor " + format_number(factor) + ") give elements of size " +
                     format_number(h) + " or less: about " + format_number(estimate) +
                     " triangles on a bounding box of area " + format_number(box_area) +
                     ", far more than the limit of " + format_number(job.limits.max_elements) +
                     " elements (use larger sizes, or raise limits.max_elements in the config)");
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
      check_flat_entities(job, 3);
      check_script_sizes(job, surface_box_area_3d());
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
      if (job.kind == GmshJob::mesh_geo) {
        check_flat_entities(job, 2);
        check_script_sizes(job, surface_box_area());
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
