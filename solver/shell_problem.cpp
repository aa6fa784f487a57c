#include "solver/shell_problem.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "assembly/shell_rotation.hpp"
#include "assembly/surface_essential.hpp"
#include "assembly/surface_load.hpp"
#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "solver/boundary_edge_kinds.hpp"
#include "solver/surface_problem.hpp"
#include "spaces/surface_point_location.hpp"

namespace iga {

namespace {


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
  for (const ShellSupport& s : p.shell->supports) check_boundary_part(space(), s.part, s.where, "this surface");
  for (const ShellSupport& s : p.shell->supports)
    if (space().boundary_edges(s.part).empty())
      throw InputError(s.where + ": this surface is closed: it has no boundary edges to hold");
}

const RigidMotions& ShellFormulation::free_motions() const {
  if (!motions_) motions_ = free_rigid_motions(space(), problem().shell->supports, quadrature_degree());
  return *motions_;
}

const SurfaceOrientation& ShellFormulation::orientation() const {
  if (orientation_) return *orientation_;
  const ShellSpec& shell = *problem().shell;
  const std::string where = shell.pressure ? shell.pressure_where : problem().source_where;
  SurfaceOrientation o = orient_surface(space(), quadrature_degree());
  if (!o.orientable)
    throw InputError(where + ": this surface has no consistent normal (going round some cycle of its elements flips "
                     "it: a non-orientable surface), so a pressure has no direction; give the force as 'load'");
  if (!o.decided)
    throw InputError(where + ": this surface's outward side cannot be told (neither curved to one side nor with a "
                     "mean normal), so a pressure has no direction; give the force as 'load'");
  orientation_ = std::move(o);
  return *orientation_;
}

Eigen::VectorXd ShellFormulation::load(const WorkShare& share) const {
  const ShellSpec& shell = *problem().shell;
  const int n = space().dimension();
  notes_.clear();
  Eigen::VectorXd b(3 * n);
  // f(x) + p(x) s_e n: the load per area and the pressure along the oriented normal.
  const std::vector<int> no_signs;
  const std::vector<int>& sign = shell.pressure ? orientation().sign : no_signs;
  const std::optional<SymbolicFunction>& pressure = shell.pressure;
  const AreaForce force = [&shell, &pressure, &sign](int e, const Eigen::Vector3d& x, const Eigen::Vector3d& normal) {
    Eigen::Vector3d f(shell.load[0].at(x), shell.load[1].at(x), shell.load[2].at(x));
    if (pressure) f += pressure->at(x) * sign[e] * normal;
    return f;
  };
  for (int c = 0; c < 3; ++c) {
    const SymbolicFunction& f = shell.load[c];
    b.segment(c * n, n) =
        pressure ? surface_element_load(
                       space(),
                       [&f, &pressure, &sign, c](int e, const Eigen::Vector3d& x, const Eigen::Vector3d& normal) {
                         return f.at(x) + pressure->at(x) * sign[e] * normal(c);
                       },
                       quadrature_degree(), share.elements)
                 : surface_load(
                       space(), [&f](const Eigen::Vector3d& x, const Eigen::Vector3d&, double) { return f.at(x); },
                       quadrature_degree(), share.elements);
  }
  if (pressure) {
    const SurfaceOrientation& o = orientation();
    const bool closed = space().boundary_edges("all").empty();
    notes_.push_back(std::string("pressure along the normal oriented ") +
                     (closed     ? "outward (the closed surface encloses a volume of " + format_number(o.volume) + ")"
                      : o.flat   ? "with the mean normal's largest component positive (a flat surface)"
                                 : "away from the surface's centroid (to its convex side; ∫ (x − x₀)·n dA / 3 = " +
                                     format_number(o.volume) + ")"));
  }
  // Point loads: F_c N_i(p) on the element holding p (in this share). A snapped load goes to the
  // surface's nearest point (within 1 % of the surface's size), and the resultant is taken there.
  const RigidMotions& motions = free_motions();
  const double tolerance = 1e-6 * motions.length;  // relative to the surface's size
  const std::unique_ptr<Space::Evaluator> evaluator = space().make_evaluator();
  PointValues g;
  std::vector<ShellPointLoad> applied = shell.point_loads;
  for (std::size_t k = 0; k < shell.point_loads.size(); ++k) {
    const ShellPointLoad& p = shell.point_loads[k];
    double snapped = 0;
    const auto at = p.snap ? nearest_on_surface(space(), p.point, *evaluator, snapped)
                           : locate_on_surface(space(), p.point, *evaluator, tolerance);
    if (!at)
      throw InputError(p.where + ": the point load's point " + format_number(p.point.x()) + ", " +
                       format_number(p.point.y()) + ", " + format_number(p.point.z()) +
                       " is not on the surface (no point of it within " + format_number(tolerance) +
                       " = 1e-6 of the surface's size, its largest distance from its centroid); 'snap: true' moves "
                       "it to the surface's nearest point");
    if (p.snap && !(snapped <= 1e-2 * motions.length))
      throw InputError(p.where + ": the surface's nearest point to the point load's point " +
                       format_number(p.point.x()) + ", " + format_number(p.point.y()) + ", " +
                       format_number(p.point.z()) + " is " + format_number(snapped) +
                       " away, more than 1 % of the surface's size (" + format_number(motions.length) +
                       "): not snapped");
    QuadratureRule one;
    one.points = {at->reference};
    one.weights = {0.0};
    evaluator->evaluate_geometry(at->element, one, g);
    applied[k].point = g.x3.col(0);
    const double distance = (g.x3.col(0) - p.point).norm();
    notes_.push_back("point load " + std::to_string(k + 1) + " at (" + format_number(p.point.x()) + ", " +
                     format_number(p.point.y()) + ", " + format_number(p.point.z()) + "): element " +
                     std::to_string(at->element) + ", reference point (" + format_number(at->reference.x()) + ", " +
                     format_number(at->reference.y()) + "), " + format_number(distance) + " from the given point" +
                     (p.snap ? " (snapped to the surface's nearest point, (" + format_number(g.x3(0, 0)) + ", " +
                                   format_number(g.x3(1, 0)) + ", " + format_number(g.x3(2, 0)) + "))"
                             : ""));
    if (share.elements && std::find(share.elements->begin(), share.elements->end(), at->element) == share.elements->end()) continue;
    Eigen::VectorXd local;
    for (int c = 0; c < 3; ++c) {
      evaluator->integrate_values(at->element, one, g, Eigen::VectorXd::Constant(1, p.force(c)), local);
      for (int i = 0; i < local.size(); ++i) b(c * n + g.dofs[i]) += local(i);
    }
  }
  // Equilibrium with the free rigid motions: ℓ(r) = a·F + θ/L·M must vanish for each.
  if (motions.count() > 0) {
    const LoadResultant r = load_resultant(space(), force, applied, motions.center, quadrature_degree());
    double work = 0;
    for (int m = 0; m < motions.count(); ++m)
      work = std::max(work, std::abs(motions.modes.col(m).head<3>().dot(r.force) +
                                     motions.modes.col(m).tail<3>().dot(r.moment) / motions.length));
    if (work > 1e-9 * r.magnitude) {
      // The old wording for a single unheld translation along an axis, kept for its clarity.
      std::string what = "the loads have a resultant force (" + format_number(r.force.x()) + ", " +
                         format_number(r.force.y()) + ", " + format_number(r.force.z()) + ") and moment (" +
                         format_number(r.moment.x()) + ", " + format_number(r.moment.y()) + ", " +
                         format_number(r.moment.z()) + ") about the centroid";
      for (int c = 0; c < 3; ++c)
        if (motions.count() == 1 && std::abs(std::abs(motions.modes(c, 0)) - 1.0) < 1e-12)
          what = "the load has a resultant " + format_number(r.force(c)) + " along " + std::string(1, "xyz"[c]) +
                 " that no support holds";
      throw InputError(shell.loads_where + ": " + what + ", which the supports leave free to move rigidly (" +
                       motions.describe() + "): balance the loads, or hold more components in problem.boundary");
    }
  }
  return b;
}

void ShellFormulation::finish(Eigen::VectorXd& coefficients, const WorkShare&) const {
  remove_rigid_motions(basis_, coefficients);
}

std::vector<BoundaryEdge> ShellFormulation::support_edges(const std::function<bool(const ShellSupport&)>& holds) const {
  std::vector<BoundaryEdge> edges;
  for (const ShellSupport& s : problem().shell->supports)
    if (holds(s))
      for (const BoundaryEdge& e : space().boundary_edges(s.part))
        if (std::none_of(edges.begin(), edges.end(), [&](const BoundaryEdge& f) {
              return f.element == e.element && f.local_edge == e.local_edge;
            }))
          edges.push_back(e);
  return edges;
}

std::vector<BoundaryEdge> ShellFormulation::rotation_edges() const {
  return support_edges([](const ShellSupport& s) { return s.rotation_held; });
}

SplitMatrix ShellFormulation::matrix(const std::vector<FormTerm>& terms) const {
  SplitMatrix m = Formulation::matrix(terms);
  const std::vector<BoundaryEdge> edges = rotation_edges();
  if (edges.empty()) return m;
  m.high = m.high + shell_rotation_nitsche(space(), edges, problem().shell->material, nitsche_penalty(), quadrature_degree());
  m.low.resize(0);  // the pattern changed; the element part is summed in double anyway
  return m;
}

void ShellFormulation::for_each_extra_element_matrix(const std::vector<int>& elements,
                                                     const ElementMatrixSink& sink) const {
  const std::vector<BoundaryEdge> edges = edges_of_share(rotation_edges(), {&elements}, space().num_elements());
  if (edges.empty()) return;
  const std::unique_ptr<Space::Evaluator> evaluator = space().make_evaluator();
  Eigen::MatrixXd local;
  std::vector<int> dofs;
  DoubleDoubleMatrix K;
  for (const BoundaryEdge& e : edges) {
    shell_rotation_edge_matrix(space(), e, problem().shell->material, nitsche_penalty(), quadrature_degree(),
                               *evaluator, local, dofs);
    K.hi = local;  // summed in double, as the serial matrix() sums them
    K.lo.setZero(local.rows(), local.cols());
    sink(e.element, dofs, K);
  }
}

Constraints ShellFormulation::constraints() const {
  const ShellSpec& shell = *problem().shell;
  const int n = space().dimension();
  Constraints all;
  all.values = Eigen::VectorXd::Zero(3 * n);
  for (int c = 0; c < 3; ++c) {
    const std::vector<BoundaryEdge> edges = support_edges([c](const ShellSupport& s) { return s.fixed[c]; });
    Constraints one;
    if (edges.empty()) {
      one = all_free(n);
    } else {
      const SurfaceField g = shell.exact ? surface_field((*shell.exact)[c]) : SurfaceField([](const Eigen::Vector3d&) { return 0.0; });
      one = surface_essential_constraints(space(), edges, g, {}, quadrature_degree());
    }
    append_component(all, one, c, n);
  }
  // The rigid motions the supports leave free: one coefficient each pinned, removed in finish.
  const RigidMotions& motions = free_motions();
  basis_ = iga::rigid_motion_basis(space(), motions, quadrature_degree());
  pinned_ = pin_rigid_motions(basis_, all);
  if (!pinned_.empty()) {
    std::string list;
    for (int i : pinned_) list += (list.empty() ? "" : ", ") + std::string(1, "xyz"[i / n]) + std::to_string(i % n);
    notes_.push_back(std::to_string(motions.count()) + " rigid motion(s) left free by the supports: " +
                     motions.describe() + "; pinned coefficients " + list +
                     " (component and function), removed after the solve");
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
