#include "spaces/tmesh/hermite_dofs.hpp"

#include <stdexcept>
#include <string>

namespace iga {

HermiteDofs number_hermite_dofs(const TMesh& mesh, int r) {
  if (!mesh.admissibility_problem().empty())
    throw std::invalid_argument("the T-mesh is not admissible: " + mesh.admissibility_problem());
  const int n = mesh.sections()[mesh.cells()[0].section_s].n;
  for (const SectionSpec& sp : mesh.sections())
    if (sp.n != n) throw std::invalid_argument("the Hermite extraction needs the same n in every section space");
  bool reduced = false;  // some edge with d_e = 0
  for (const CompositeEdge& e : mesh.edges()) {
    if (e.d == 1) throw std::invalid_argument("composite edges with d_e = 1 are not supported by the Hermite extraction");
    reduced = reduced || e.d == 0;
  }
  const int need = reduced ? 2 * r + 3 : 2 * r + 1;
  if (r < 0 || n < need)
    throw std::invalid_argument("C^" + std::to_string(r) + " generalized splines need n >= " + std::to_string(need) +
                                (reduced ? " (edges between different section spaces)" : "") + " (got n = " +
                                std::to_string(n) + ")");
  const int nr = r + 1, ni = n - 2 * r - 1;
  const auto& V = mesh.vertices();
  const auto& E = mesh.edges();
  HermiteDofs out;
  out.n = n;
  out.r = r;
  std::vector<int>&vbase = out.vertex_base, &ebase = out.edge_base, &cbase = out.cell_base;
  vbase.assign(V.size(), -1);
  ebase.resize(E.size());
  cbase.resize(mesh.num_cells());
  int next = 0;
  for (size_t v = 0; v < V.size(); ++v)
    if (!V[v].t_junction) {
      vbase[v] = next;
      next += nr * nr;
    }
  for (size_t e = 0; e < E.size(); ++e) {
    ebase[e] = next;
    next += nr * (out.last_order(E[e]) - r);  // (k_a - r) per normal order
  }
  for (int c = 0; c < mesh.num_cells(); ++c) {
    cbase[c] = next;
    next += ni * ni;
  }
  out.dimension = next;
  return out;
}

}  // namespace iga
