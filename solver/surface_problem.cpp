#include "solver/surface_problem.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

#include "assembly/error_norms.hpp"
#include "assembly/interior_penalty.hpp"
#include "assembly/surface_calculus.hpp"
#include "assembly/surface_conormal_load.hpp"
#include "assembly/surface_essential.hpp"
#include "assembly/surface_load.hpp"
#include "config/errors.hpp"
#include "solver/boundary_edge_kinds.hpp"
#include "spaces/lifted_space.hpp"

namespace iga {

SurfaceField surface_field(const SymbolicFunction& f) {
  return [f](const Eigen::Vector3d& x) { return f.at(x); };
}

namespace {

/// Δ_Γu(x, n, H) of an ambient u = tr ∇²u − n·∇²u n − H ∂_n u, with the surface's own n and H.
SurfaceSource surface_laplacian(const SymbolicFunction& u) {
  const SymbolicFunction ux = u.diff_x(), uy = u.diff_y(), uz = u.diff_z();
  const SymbolicFunction uxx = ux.diff_x(), uxy = ux.diff_y(), uxz = ux.diff_z(), uyy = uy.diff_y(),
                         uyz = uy.diff_z(), uzz = uz.diff_z();
  return [=](const Eigen::Vector3d& x, const Eigen::Vector3d& n, double H) {
    const Eigen::Vector3d g(ux.at(x), uy.at(x), uz.at(x));
    Eigen::Matrix3d D;
    D << uxx.at(x), uxy.at(x), uxz.at(x), uxy.at(x), uyy.at(x), uyz.at(x), uxz.at(x), uyz.at(x), uzz.at(x);
    return surface_laplacian_of_ambient(D, g, n, H);
  };
}

/// "FILE:LINE:COL: problem.boundary.left" → "FILE:LINE:COL: problem.boundary": messages about the
/// parts together.
std::string parent_key(const std::string& where) {
  const std::size_t colon = where.rfind(": ");
  const std::size_t dot = where.rfind('.');
  return dot != std::string::npos && (colon == std::string::npos || dot > colon) ? where.substr(0, dot) : where;
}

/// No free edge: the parts given cover the whole boundary curve (`covered` of its edges), else an
/// InputError naming the space's parts that have edges without a condition.
void check_every_edge_has_a_condition(const Space& space, const std::vector<BoundaryPart>& parts,
                                      std::size_t covered) {
  if (parts.empty() || covered == space.boundary_edges("all").size()) return;
  std::set<std::pair<int, int>> given;
  for (const BoundaryPart& part : parts)
    for (const BoundaryEdge& e : space.boundary_edges(part.name)) given.insert({e.element, e.local_edge});
  std::string missing;
  for (const std::string& name : space.boundary_names())
    for (const BoundaryEdge& e : space.boundary_edges(name))
      if (!given.count({e.element, e.local_edge})) {
        missing += (missing.empty() ? "" : ", ") + name;
        break;
      }
  throw InputError(parent_key(parts.front().where) + ": the boundary part(s) " +
                   (missing.empty() ? std::string("of some edges") : missing) +
                   " have no condition: give every part clamped or simply_supported, or 'all' for the rest (a free "
                   "edge, with Δ_Γu and its conormal derivative natural, is not supported)");
}

/// The exact solution's callables (empty when the problem has none).
SurfaceExactSolution surface_exact_solution(const ProblemSpec& problem, bool with_hessian) {
  return problem.surface_exact ? surface_exact_solution(*problem.surface_exact, with_hessian) : SurfaceExactSolution{};
}
}  // namespace

SurfaceExactSolution surface_exact_solution(const SymbolicFunction& u, bool with_hessian) {
  SurfaceExactSolution s;
  const SymbolicFunction ux = u.diff_x(), uy = u.diff_y(), uz = u.diff_z();
  s.u = surface_field(u);
  s.ux = surface_field(ux);
  s.uy = surface_field(uy);
  s.uz = surface_field(uz);
  if (!with_hessian) return s;
  s.uxx = surface_field(ux.diff_x());
  s.uxy = surface_field(ux.diff_y());
  s.uxz = surface_field(ux.diff_z());
  s.uyy = surface_field(uy.diff_y());
  s.uyz = surface_field(uy.diff_z());
  s.uzz = surface_field(uz.diff_z());
  return s;
}

SurfaceSource surface_source(const ProblemSpec& problem) {
  if (problem.surface_source || !problem.surface_exact) {
    const SymbolicFunction f = problem.surface_source.value_or(SymbolicFunction::constant(0.0));
    return [f](const Eigen::Vector3d& x, const Eigen::Vector3d&, double) { return f.at(x); };
  }
  const SymbolicFunction u = *problem.surface_exact;
  const SurfaceSource laplace_beltrami = surface_laplacian(u);
  const double c = problem.reaction;
  return [=](const Eigen::Vector3d& x, const Eigen::Vector3d& n, double H) {
    return -laplace_beltrami(x, n, H) + c * u.at(x);
  };
}

void SurfaceFormulation::check() const {
  const ProblemSpec& p = problem();
  if (space().ambient_dimension() != 3)
    throw InputError(p.source_where + ": laplace_beltrami needs a space on a surface in 3D");
  if (open() && !p.surface_dirichlet)
    throw InputError(p.source_where + ": this surface has a boundary: give Dirichlet data on it (problem.boundary: "
                                      "{all: dirichlet}" + (p.eigen ? ")" : ", with exact or boundary_value)"));
  if (!open() && p.surface_dirichlet)
    throw InputError(p.boundary.front().where + ": this surface is closed: it has no boundary for Dirichlet data");
}

Eigen::VectorXd SurfaceFormulation::load(const WorkShare& share) const {
  Eigen::VectorXd b = surface_load(space(), surface_source(problem()), quadrature_degree(), share.elements);
  if (pure()) kernel_.make_load_orthogonal(b, space(), quadrature_degree(), share);
  return b;
}

Constraints SurfaceFormulation::constraints() const {
  if (open())
    return surface_essential_constraints(space(), space().boundary_edges("all"),
                                         surface_field(*problem().surface_dirichlet), {}, quadrature_degree());
  if (pure()) return kernel_.pinned(space());
  return all_free(space().dimension());
}

void ScalarSurfaceFormulation::finish(Eigen::VectorXd& coefficients, const WorkShare& share) const {
  if (pure()) kernel_.finish(coefficients, space(), problem().surface_exact, share);
}

ErrorNorms ScalarSurfaceFormulation::errors(const Eigen::VectorXd& coefficients, const WorkShare& share) const {
  const bool with_hessian = problem().pde == Pde::surface_biharmonic;
  return surface_error_norms(space(), coefficients, surface_exact_solution(problem(), with_hessian),
                             space().error_quadrature_degree(), share.elements);
}

Formulation::Messages SurfaceFormulation::messages() const {
  return {problem().source_where + ": the source term is not finite at some point of the surface",
          problem().data_where + ": the boundary data are not finite at some point of the surface's boundary",
          problem().data_where + ": the exact solution or its gradient is not finite somewhere on the surface"};
}

namespace {
/// η of the C0 interior penalty for degree p (docs/surface-biharmonic.md: large enough that the
/// discrete form stays coercive; the inverse inequality constant grows like p²).
double c0ip_penalty(int degree) { return 4.0 * degree * degree; }
}  // namespace

void SurfaceBiharmonicFormulation::check() const {
  const ProblemSpec& p = problem();
  if (space().ambient_dimension() != 3)
    throw InputError(p.source_where + ": surface_biharmonic needs a space on a surface in 3D");
  const bool open = !space().boundary_edges("all").empty();
  if (!open && !p.boundary.empty())
    throw InputError(p.boundary.front().where + ": this surface is closed: it has no boundary for clamped or simply supported data");
  for (const BoundaryPart& part : p.boundary)
    check_boundary_part(space(), part.name, part.where, "this " + space().type() + " surface");
  bool clamped = p.boundary.empty();  // a lift without problem.boundary is clamped
  for (const BoundaryPart& part : p.boundary) clamped = clamped || part.kind == BoundaryKind::clamped;
  if (space().continuity() < 1) {  // the C0 interior penalty form
    if (space().num_elements() > 1 && space().interior_edges().empty())
      throw InputError(p.source_where + ": surface_biharmonic on a C0 space needs its interior edges (the interior "
                                        "penalty form); the " + space().type() + " space lists none");
    // Clamped data through a lift are the planar space's own (u and ∂_n u imposed on the boundary
    // edges, so the test functions have no boundary terms); simply supported boundaries need none
    // either (Δ_Γu is natural: its term is the load's); other clamped surfaces have no such terms yet.
    if (open && !dynamic_cast<const LiftedSpace*>(&space()) && clamped)
      throw InputError(p.source_where + ": the C0 interior penalty form of surface_biharmonic is for closed surfaces, "
                                        "graph surfaces and simply supported boundaries (no clamped boundary edge terms "
                                        "yet); use a C1 space here");
  }
  if (!open) return;
  // Lifted (graph) surfaces are built in code, where the clamped condition is implied.
  if (p.boundary.empty() && !dynamic_cast<const LiftedSpace*>(&space()))
    throw InputError(p.source_where + ": this surface has a boundary: give problem.boundary: {all: clamped} "
                                      "(u and its conormal derivative from exact) or {all: simply_supported} "
                                      "(u and Δ_Γu from exact)");
  if (!p.surface_exact)
    throw InputError(p.source_where + ": surface_biharmonic on an open surface takes its boundary data from 'exact'");
  check_every_edge_has_a_condition(space(), p.boundary, parts().essential.value_edges.size());
}

Eigen::VectorXd SurfaceBiharmonicFormulation::load(const WorkShare& share) const {
  const ProblemSpec& p = problem();
  if (p.surface_source || !p.surface_exact) {
    Eigen::VectorXd b = surface_load(space(), surface_source(p), quadrature_degree(), share.elements);
    // Simply supported parts: Δ_Γu = g is natural, ∫ g ∂_ν v ds on the load side, over their
    // edges of this share's elements (each rank its own, as the element part).
    if (p.surface_exact && open()) {
      const std::vector<BoundaryEdge> supported = edges_of_share(parts().simply_supported, share, space().num_elements());
      if (!supported.empty())
        b += surface_conormal_load(space(), supported, surface_laplacian(*p.surface_exact), quadrature_degree());
    }
    if (pure()) kernel_.make_load_orthogonal(b, space(), quadrature_degree(), share);
    return b;
  }
  // ℓ(v) = a(u, v) = ∫ Δ_Γu Δ_Γv + c u v with Δ_Γu from u's ambient derivatives, n and H. For a
  // simply supported boundary this is already consistent: a(u, v) = ∫ f v + ∫_∂ Δ_Γu ∂_ν v.
  const SymbolicFunction u = *p.surface_exact;
  const double c = p.reaction;
  const SurfaceSource value_part = [u, c](const Eigen::Vector3d& x, const Eigen::Vector3d&, double) {
    return c * u.at(x);
  };
  const SurfaceSource laplacian_part = surface_laplacian(u);
  Eigen::VectorXd b = surface_form_load(space(), value_part, laplacian_part, quadrature_degree(), share.elements);
  if (space().continuity() < 1) b += c0ip_edge_load(space(), laplacian_part, quadrature_degree());
  if (pure()) kernel_.make_load_orthogonal(b, space(), quadrature_degree(), share);
  return b;
}

SplitMatrix SurfaceBiharmonicFormulation::matrix(const std::vector<FormTerm>& terms) const {
  if (space().continuity() >= 1) {
    // Each term in double-double and their sum too, so that iterative refinement removes the
    // floor of a matrix rounded to double (ε h⁻⁴, split_matrix.hpp): on the open 4-split cube
    // (k = 5, c = 1) it held L2 / H1 at 5.5e−8 / 7.0e−8 at level 5 (docs/surface-biharmonic.md).
    // The terms share the assembler's pattern: added entry by entry, one term matrix at a time.
    SplitMatrix m = assembler().matrix_extended(terms.at(0), quadrature_degree());
    const Eigen::Index nnz = m.high.nonZeros();
    for (std::size_t i = 1; i < terms.size(); ++i) {
      const SplitMatrix t = assembler().matrix_extended(terms[i], quadrature_degree());
      if (t.high.nonZeros() != nnz) throw std::logic_error("SurfaceBiharmonicFormulation::matrix: the terms' patterns differ");
      double* hi = m.high.valuePtr();
      for (Eigen::Index k = 0; k < nnz; ++k) {
        const DoubleDouble v = DoubleDouble(hi[k], m.low(k)) + DoubleDouble(t.high.valuePtr()[k], t.low(k));
        hi[k] = v.hi;
        m.low(k) = v.lo;
      }
    }
    return m;
  }
  SplitMatrix m = Formulation::matrix(terms);
  m.high = m.high + c0ip_edge_matrix(space(), c0ip_penalty(space().degree()), quadrature_degree());
  m.low.resize(0);  // the pattern changed; the element part is summed in double anyway
  return m;
}

SurfaceBiharmonicFormulation::Parts SurfaceBiharmonicFormulation::parts() const {
  const std::vector<BoundaryEdge> all = space().boundary_edges("all");
  Parts out;
  if (problem().boundary.empty()) {  // a lift: clamped everywhere (check() refuses other open surfaces)
    out.essential = {all, all};
    return out;
  }
  std::map<std::pair<int, int>, BoundaryKind> kind_of_edge;
  for (const BoundaryPart& part : problem().boundary)
    for (const BoundaryEdge& e : space().boundary_edges(part.name)) kind_of_edge[{e.element, e.local_edge}] = part.kind;
  for (const BoundaryEdge& e : all) {
    const auto it = kind_of_edge.find({e.element, e.local_edge});
    if (it == kind_of_edge.end()) continue;  // no condition: refused by check()
    out.essential.value_edges.push_back(e);
    if (it->second == BoundaryKind::clamped) out.essential.normal_edges.push_back(e);
    else out.simply_supported.push_back(e);
  }
  return out;
}

Constraints SurfaceBiharmonicFormulation::constraints() const {
  // An open lifted surface: u on every boundary edge, ∇_Γu on the clamped ones, from the exact
  // solution, imposed as the planar space's clamped / simply supported conditions on u ∘ X (same
  // functions, numbering and boundary edges): û = u(X(x, y)) and ∂_n û = (J_Xᵀ ∇u) · n with n the
  // planar outward normal. Δ_Γu on simply supported edges is natural.
  const Parts boundary = open() ? parts() : Parts{};
  if (boundary.essential.empty()) {
    if (pure()) return kernel_.pinned(space());
    return all_free(space().dimension());  // closed surface, c > 0: no essential condition
  }
  const bool clamped = !boundary.essential.normal_edges.empty();
  const SymbolicFunction u = *problem().surface_exact;
  const SymbolicFunction ux = u.diff_x(), uy = u.diff_y(), uz = u.diff_z();
  if (const auto* lifted = dynamic_cast<const LiftedSpace*>(&space())) {
    const BoundaryField value = [lifted, u](const Point2& x, const Point2&) { return u.at(lifted->lift(x)); };
    BoundaryField normal;
    if (clamped)
      normal = [lifted, ux, uy, uz](const Point2& x, const Point2& n) {
        const Eigen::Vector3d X = lifted->lift(x);
        const Eigen::Vector3d g(ux.at(X), uy.at(X), uz.at(X));
        return (lifted->lift_jacobian(x).transpose() * g).dot(n);
      };
    return impose_essential(lifted->planar(), boundary.essential, value, normal, quadrature_degree());
  }
  // Any other open surface: through the surface's own conormal ν, u = u_exact and on clamped
  // edges ∂_ν u = ∇u_exact · ν (ν tangent to Γ, so the ambient gradient gives the surface one's
  // component).
  SurfaceConormalField conormal;
  if (clamped)
    conormal = [ux, uy, uz](const Eigen::Vector3d& x, const Eigen::Vector3d& nu) {
      return ux.at(x) * nu(0) + uy.at(x) * nu(1) + uz.at(x) * nu(2);
    };
  return surface_essential_constraints(space(), boundary.essential, surface_field(u), conormal, quadrature_degree());
}


Formulation::Messages SurfaceBiharmonicFormulation::messages() const {
  return {problem().source_where + ": the load is not finite at some point of the surface",
          problem().data_where + ": the boundary data are not finite",
          problem().data_where + ": the exact solution or its derivatives are not finite somewhere on the surface"};
}

}  // namespace iga
