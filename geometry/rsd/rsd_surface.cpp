#include "geometry/rsd/rsd_surface.hpp"

#include <algorithm>

#include "config/errors.hpp"
#include "geometry/rsd/hermite_edge_solver.hpp"
#include "geometry/rsd/paper_edge_solver.hpp"
#include "geometry/rsd/rsd_patch.hpp"
#include "geometry/rsd/surface_checks.hpp"

namespace iga::rsd {

namespace {

Vec3<double> as_array(const Eigen::Vector3d& x) { return {x[0], x[1], x[2]}; }

/// Relative residual above which a 3×2 end system counts as inconsistent (data off the plane).
constexpr double consistency_tolerance = 1e-8;

std::vector<VecPoly<double>> hermite_corrections(RsdTuple tuple, const TriangleSurfaceMesh& mesh,
                                                 const std::vector<SurfaceEdge>& edges, const FirstOrderData& data) {
  std::vector<VecPoly<double>> z(edges.size());
  for (std::size_t m = 0; m < edges.size(); ++m) {
    const SurfaceEdge& e = edges[m];
    if (!e.interior()) continue;
    const HermiteEdgeSolution s = solve_edge_hermite(tuple, edge_end_data(data, e));
    const std::string edge = "edge (" + std::to_string(e.i) + ", " + std::to_string(e.j) + ")";
    for (const auto& [vertex, residual, Y] : {std::tuple{e.j, s.residual0, s.Y0}, std::tuple{e.i, s.residual1, s.Y1}}) {
      if (residual > consistency_tolerance)
        throw InputError(mesh.source + ": condition (28) violated at " + mesh.vertex_name(vertex) + " on " + edge +
                         ": the tangents of the two triangles are not coplanar (relative residual " +
                         std::to_string(residual) + ")");
      if (!(Y > -1 && Y < 0))
        throw InputError(mesh.source + ": condition (12) violated at " + mesh.vertex_name(vertex) + " on " + edge +
                         ": the tangent triangles overlap (Y = " + std::to_string(Y) + " not in (−1, 0))");
    }
    z[m] = s.z;
  }
  return z;
}

RsdSurface assemble(const TriangleSurfaceMesh& mesh, std::vector<SurfaceEdge> edges, FirstOrderData data,
                    const RsdOptions& options, std::vector<VecPoly<double>> z) {
  RsdSurface s;
  s.mesh = mesh;
  s.edges = std::move(edges);
  s.data = std::move(data);
  s.options = options;
  s.z = std::move(z);
  int degree = rsd_degree(options.tuple);
  for (const auto& zm : s.z)
    if (iga::rsd::degree(zm) >= 0) degree = std::max(degree, iga::rsd::degree(zm) + 5);
  s.report.patch_degree = degree;
  std::vector<std::vector<LocalEdgeCorrection>> corrections(mesh.triangles.size());
  for (std::size_t m = 0; m < s.edges.size(); ++m) {
    const SurfaceEdge& e = s.edges[m];
    if (e.interior()) {
      ++s.report.interior_edges;
    } else {
      ++s.report.boundary_edges;
      continue;
    }
    if (iga::rsd::degree(s.z[m]) < 0) continue;
    for (const auto& [n, k] : {std::pair{e.n, e.k}, std::pair{e.nbar, e.kbar}})
      corrections[n].push_back({s.local_index(n, e.i), s.local_index(n, e.j), s.local_index(n, k), s.z[m]});
  }
  for (int n = 0; n < mesh.num_triangles(); ++n) {
    const auto& t = mesh.triangles[n];
    TriangleData local;
    for (int a = 0; a < 3; ++a) {
      local.f[a] = s.data.f[t[a]];
      for (int b = 0; b < 3; ++b)
        local.g[a][b] = a == b ? Eigen::Vector3d::Zero() : s.data.g_of(t[a], t[b]);
    }
    s.patches.push_back(rsd_patch(options.tuple, local, corrections[n], degree));
  }
  measure_surface(s);
  return s;
}

}  // namespace

std::string method_name(RsdMethod method) {
  switch (method) {
    case RsdMethod::hermite: return "hermite";
    case RsdMethod::paper: return "paper";
    case RsdMethod::none: return "none";
  }
  return "?";
}

int RsdSurface::local_index(int n, int v) const {
  const auto& t = mesh.triangles[n];
  return t[0] == v ? 0 : (t[1] == v ? 1 : 2);
}

EdgeEndData<double> edge_end_data(const FirstOrderData& data, const SurfaceEdge& e) {
  return {as_array(data.f[e.i]),        as_array(data.f[e.j]),        as_array(data.g_of(e.i, e.j)),
          as_array(data.g_of(e.j, e.i)), as_array(data.g_of(e.i, e.k)), as_array(data.g_of(e.j, e.k)),
          as_array(data.g_of(e.i, e.kbar)), as_array(data.g_of(e.j, e.kbar))};
}

RsdSurface build_rsd_surface(const TriangleSurfaceMesh& mesh, const RsdOptions& options) {
  validate_surface_mesh(mesh);
  std::vector<SurfaceEdge> edges = surface_edges(mesh);
  FirstOrderData data = projected_chord_data(mesh, edges);
  check_data_conditions(mesh, edges, data);
  if (options.method != RsdMethod::paper) return build_rsd_surface(mesh, data, options);
  std::vector<VecPoly<double>> z = paper_corrections(options.tuple, mesh, edges, data);
  return assemble(mesh, std::move(edges), std::move(data), options, std::move(z));
}

RsdSurface build_rsd_surface(const TriangleSurfaceMesh& mesh, const FirstOrderData& data, const RsdOptions& options) {
  if (options.method == RsdMethod::paper)
    throw InputError(mesh.source + ": method 'paper' derives its exact data from the mesh; use the mesh overload");
  validate_surface_mesh(mesh);
  std::vector<SurfaceEdge> edges = surface_edges(mesh);
  if (data.f.size() != mesh.points.size() || data.n.size() != mesh.points.size())
    throw InputError(mesh.source + ": one data point f and one unit normal n per vertex are required");
  for (const auto& e : edges)
    if (!data.g.count(FirstOrderData::directed_key(e.i, e.j)) || !data.g.count(FirstOrderData::directed_key(e.j, e.i)))
      throw InputError(mesh.source + ": no tangent data g for edge (" + std::to_string(e.i) + ", " +
                       std::to_string(e.j) + ")");
  check_data_conditions(mesh, edges, data);
  std::vector<VecPoly<double>> z(edges.size());
  if (options.method == RsdMethod::hermite) z = hermite_corrections(options.tuple, mesh, edges, data);
  return assemble(mesh, std::move(edges), data, options, std::move(z));
}

}  // namespace iga::rsd
