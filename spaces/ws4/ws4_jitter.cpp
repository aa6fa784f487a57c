#include "spaces/ws4/ws4_jitter.hpp"

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

namespace iga::ws4 {

void jitter_interior_vertices(Triangulation& mesh, double fraction, unsigned seed) {
  const int nv = mesh.num_vertices();
  std::vector<bool> on_boundary(nv, false);
  std::vector<double> shortest(nv, std::numeric_limits<double>::infinity());
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const int a = mesh.edge(e)[0], b = mesh.edge(e)[1];
    const double len = (mesh.vertices()[a] - mesh.vertices()[b]).norm();
    shortest[a] = std::min(shortest[a], len);
    shortest[b] = std::min(shortest[b], len);
    if (mesh.is_boundary_edge(e)) on_boundary[a] = on_boundary[b] = true;
  }
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int v = 0; v < nv; ++v) {
    const double dx = u(gen), dy = u(gen);  // drawn for every vertex: the pattern depends on seed only
    if (on_boundary[v]) continue;
    mesh.move_vertex(v, mesh.vertices()[v] + fraction * shortest[v] * Point2(dx, dy));
  }
}

}  // namespace iga::ws4
