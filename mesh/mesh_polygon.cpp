#include "mesh/mesh_polygon.hpp"

#include <cmath>

#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "mesh/gmsh_worker.hpp"
#include "mesh/planar_vectors.hpp"

namespace iga {

namespace {

using Loop = std::vector<Eigen::Vector2d>;

/// Whether closed segments pq and rs have a point in common.
bool segments_meet(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r,
                   const Eigen::Vector2d& s) {
  const double d1 = cross(q - p, r - p), d2 = cross(q - p, s - p), d3 = cross(s - r, p - r), d4 = cross(s - r, q - r);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  // Collinear touching: an endpoint on the other segment.
  auto on = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& x, double d) {
    return d == 0.0 && x.x() >= std::min(a.x(), b.x()) && x.x() <= std::max(a.x(), b.x()) &&
           x.y() >= std::min(a.y(), b.y()) && x.y() <= std::max(a.y(), b.y());
  };
  return on(p, q, r, d1) || on(p, q, s, d2) || on(r, s, p, d3) || on(r, s, q, d4);
}

/// Even-odd rule; `x` is assumed not to lie on the loop (the crossing check ran first).
bool inside(const Loop& loop, const Eigen::Vector2d& x) {
  bool in = false;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++)
    if ((loop[i].y() > x.y()) != (loop[j].y() > x.y()) &&
        x.x() < loop[j].x() + (x.y() - loop[j].y()) * (loop[i].x() - loop[j].x()) / (loop[i].y() - loop[j].y()))
      in = !in;
  return in;
}

std::string loop_name(std::size_t l) { return l == 0 ? "outer" : "hole " + std::to_string(l); }

std::string side_name(const std::vector<const Loop*>& loops, std::size_t l, std::size_t k) {
  const Loop& loop = *loops[l];
  return loop_name(l) + " side " + std::to_string(k + 1) + " (" + describe_point(loop[k]) + "-" +
         describe_point(loop[(k + 1) % loop.size()]) + ")";
}

}  // namespace

void check_polygon_domain(const PolygonDomain& domain, const std::string& source) {
  std::vector<const Loop*> loops = {&domain.outer};
  for (const Loop& hole : domain.holes) loops.push_back(&hole);
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const Loop& loop = *loops[l];
    for (std::size_t k = 0; k < loop.size(); ++k)
      if (!std::isfinite(loop[k].x()) || !std::isfinite(loop[k].y()))
        throw InputError(source + ": " + loop_name(l) + " vertex " + std::to_string(k + 1) + " " +
                         describe_point(loop[k]) + " is not finite");
    if (loop.size() < 3)
      throw InputError(source + ": the " + loop_name(l) + " polygon needs at least 3 vertices (got " +
                       std::to_string(loop.size()) + ")");
    for (std::size_t k = 0; k < loop.size(); ++k)
      if (loop[k] == loop[(k + 1) % loop.size()])
        throw InputError(source + ": " + loop_name(l) + " vertices " + std::to_string(k + 1) + " and " +
                         std::to_string((k + 1) % loop.size() + 1) + " coincide at " + describe_point(loop[k]));
  }
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (std::size_t m = l; m < loops.size(); ++m) {
      const Loop &a = *loops[l], &b = *loops[m];
      for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = (l == m ? i + 1 : 0); j < b.size(); ++j) {
          const bool neighbours = l == m && (j == i + 1 || (i == 0 && j == a.size() - 1));
          const Eigen::Vector2d &p = a[i], &q = a[(i + 1) % a.size()], &r = b[j], &s = b[(j + 1) % b.size()];
          // Neighbours share one vertex; they may only meet there (not overlap along a line).
          const bool meet =
              neighbours ? cross(q - p, s - r) == 0.0 && (q - p).dot(s - r) < 0.0 : segments_meet(p, q, r, s);
          if (meet)
            throw InputError(source + ": " + side_name(loops, l, i) + " " +
                             (neighbours ? "folds back onto" : "crosses") + " " + side_name(loops, m, j) +
                             "; the polygon must be simple");
        }
    }
  for (std::size_t l = 1; l < loops.size(); ++l) {
    if (!inside(domain.outer, loops[l]->front()))
      throw InputError(source + ": " + loop_name(l) + " is not inside the outer polygon");
    for (std::size_t m = 1; m < loops.size(); ++m)
      if (m != l && inside(*loops[m], loops[l]->front()))
        throw InputError(source + ": " + loop_name(l) + " lies inside " + loop_name(m));
  }
}

PlanarMesh mesh_polygon(const PolygonDomain& domain, double mesh_size, bool recombine, const std::string& source,
                        const MeshLimits& limits) {
  check_polygon_domain(domain, source);
  if (!(mesh_size > 0.0)) throw InputError(source + ": mesh size must be > 0 (got " + format_number(mesh_size) + ")");
  // Shoelace areas: the element estimate is checked before Gmsh allocates anything.
  auto area = [](const Loop& loop) {
    double a = 0.0;
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) a += cross(loop[j], loop[i]);
    return std::abs(a) / 2.0;
  };
  double total = area(domain.outer);
  for (const Loop& hole : domain.holes) total -= area(hole);
  check_element_estimate(total, mesh_size, limits, source);
  GmshJob job;
  job.kind = GmshJob::mesh_polygon;
  job.source = source;
  job.mesh_size = mesh_size;
  job.recombine = recombine;
  job.polygon = domain;
  job.limits = limits;
  return run_gmsh_job_cached(job, {});
}

}  // namespace iga
