#include "solver/shell_problem.hpp"

#include <algorithm>
#include <cmath>

#include "assembly/surface_dirichlet.hpp"
#include "assembly/surface_load.hpp"
#include "config/errors.hpp"
#include "config/config_node.hpp"
#include "solver/surface_problem.hpp"

namespace iga {

namespace {

SurfaceField field(const SymbolicFunction& f) {
  return [f](const Eigen::Vector3d& x) { return f.at(x); };
}


/// Append one component's scalar constraints to the vector field's (component c, N functions).
void append_component(Constraints& all, const Constraints& one, int c, int n) {
  const int free_before = static_cast<int>(all.free.size());
  for (int i : one.constrained) all.constrained.push_back(c * n + i);
  for (int i : one.free) all.free.push_back(c * n + i);
  all.values.segment(c * n, n) = one.values;
  for (const auto& t : one.basis_change)
    all.basis_change.emplace_back(c * n + t.row(), free_before + t.col(), t.value());
}

}  // namespace

void ShellFormulation::check() const {
  const ProblemSpec& p = problem();
  if (space().ambient_dimension() != 3)
    throw InputError(p.source_where + ": kirchhoff_love_shell needs a space on a surface in 3D");
  const std::vector<std::string> names = space().boundary_names();
  for (const ShellSupport& s : p.shell->supports) {
    if (s.part == "all" || std::find(names.begin(), names.end(), s.part) != names.end()) continue;
    std::string list = "all";
    for (const auto& n : names) list += ", " + n;
    const std::string near = nearest_word(s.part, names);
    throw InputError(s.where + ": unknown boundary part '" + s.part + "' of this surface (parts: " + list + ")" +
                     (near.empty() ? "" : " (did you mean '" + near + "'?)"));
  }
  for (const ShellSupport& s : p.shell->supports)
    if (space().boundary_edges(s.part).empty())
      throw InputError(s.where + ": this surface is closed: it has no boundary edges to hold");
}

bool ShellFormulation::held(int c) const {
  const auto& supports = problem().shell->supports;
  return std::any_of(supports.begin(), supports.end(), [c](const ShellSupport& s) { return s.fixed[c]; });
}

Eigen::VectorXd ShellFormulation::load(const WorkShare& share) const {
  const int n = space().dimension();
  Eigen::VectorXd b(3 * n);
  for (int c = 0; c < 3; ++c) {
    const SymbolicFunction f = problem().shell->load[c];
    b.segment(c * n, n) = surface_load(
        space(), [f](const Eigen::Vector3d& x, const Eigen::Vector3d&, double) { return f.at(x); },
        quadrature_degree(), share.elements);
  }
  mass_of_one_ = surface_load(
      space(), [](const Eigen::Vector3d&, const Eigen::Vector3d&, double) { return 1.0; }, quadrature_degree(),
      share.elements);
  // A component no support holds: the load must not push the shell along it (Σ_i b_i = ∫ f_c,
  // the functions summing to 1), or there is no equilibrium.
  for (int c = 0; c < 3; ++c) {
    if (held(c)) continue;
    const double resultant = share.sum(b.segment(c * n, n).sum());
    const double size = share.sum(b.segment(c * n, n).cwiseAbs().sum());
    if (std::abs(resultant) > 1e-10 * size)
      throw InputError(problem().source_where + ": the load has a resultant " + format_number(resultant) +
                       " along " + std::string(1, "xyz"[c]) + " that no support holds (problem.boundary: add " +
                       std::string(1, "xyz"[c]) + " to some part's fixed components)");
  }
  return b;
}

void ShellFormulation::finish(Eigen::VectorXd& coefficients, const WorkShare& share) const {
  const int n = space().dimension();
  const double area = share.sum(mass_of_one_.sum());
  for (int c = 0; c < 3; ++c)
    if (!held(c)) coefficients.segment(c * n, n).array() -= share.sum(mass_of_one_.dot(coefficients.segment(c * n, n))) / area;
}

Constraints ShellFormulation::constraints() const {
  const ShellSpec& shell = *problem().shell;
  const int n = space().dimension();
  Constraints all;
  all.values = Eigen::VectorXd::Zero(3 * n);
  for (int c = 0; c < 3; ++c) {
    // The edges of every part that holds component c (a part listed twice adds its edges once).
    std::vector<BoundaryEdge> edges;
    for (const ShellSupport& s : shell.supports)
      if (s.fixed[c])
        for (const BoundaryEdge& e : space().boundary_edges(s.part))
          if (std::none_of(edges.begin(), edges.end(), [&](const BoundaryEdge& f) {
                return f.element == e.element && f.local_edge == e.local_edge;
              }))
            edges.push_back(e);
    Constraints one;
    if (edges.empty()) {
      // Unheld: coefficient 0 pinned against the translation along c (finish shifts it to zero mean).
      one.values = Eigen::VectorXd::Zero(n);
      one.constrained = {0};
      for (int i = 1; i < n; ++i) one.free.push_back(i);
    } else {
      const SurfaceField g = shell.exact ? field((*shell.exact)[c]) : SurfaceField([](const Eigen::Vector3d&) { return 0.0; });
      one = surface_dirichlet_constraints(space(), edges, g, quadrature_degree());
    }
    append_component(all, one, c, n);
  }
  return all;
}

ErrorNorms ShellFormulation::errors(const Eigen::VectorXd& coefficients, const WorkShare& share) const {
  const int n = space().dimension();
  double l2 = 0, h1 = 0, h2 = 0;
  for (int c = 0; c < 3; ++c) {
    const ErrorNorms e = surface_error_norms(space(), coefficients.segment(c * n, n),
                                             surface_exact_solution((*problem().shell->exact)[c], true),
                                             space().error_quadrature_degree(), share.elements);
    l2 += e.l2 * e.l2;
    h1 += e.h1.value_or(0) * e.h1.value_or(0);
    h2 += e.h2.value_or(0) * e.h2.value_or(0);
  }
  ErrorNorms out;
  out.l2 = std::sqrt(l2);
  out.h1 = std::sqrt(h1);
  out.h2 = std::sqrt(h2);
  return out;
}

Formulation::Messages ShellFormulation::messages() const {
  return {problem().source_where + ": the load is not finite at some point of the surface",
          problem().data_where + ": the boundary values of the held components are not finite",
          problem().data_where + ": the exact displacement or its derivatives are not finite somewhere on the surface"};
}

}  // namespace iga
