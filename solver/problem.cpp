#include "solver/problem.hpp"

#include <algorithm>
#include <cmath>

#include "solver/shell_config.hpp"

namespace iga {

std::string to_string(Pde pde) {
  switch (pde) {
    case Pde::poisson: return "poisson";
    case Pde::biharmonic: return "biharmonic";
    case Pde::laplace_beltrami: return "laplace_beltrami";
    case Pde::surface_biharmonic: return "surface_biharmonic";
    case Pde::kirchhoff_love_shell: return "kirchhoff_love_shell";
  }
  return "?";
}

std::string to_string(BoundaryKind kind) {
  switch (kind) {
    case BoundaryKind::dirichlet: return "dirichlet";
    case BoundaryKind::neumann: return "neumann";
    case BoundaryKind::clamped: return "clamped";
    case BoundaryKind::simply_supported: return "simply_supported";
  }
  return "?";
}

namespace {

BatchField batch_field(FunctionBatch batch) {
  return [batch](const Eigen::Matrix2Xd& points, Eigen::MatrixXd& values) { batch.evaluate(points, values); };
}

SymbolicFunction parse_expression(const ConfigNode& node) { return SymbolicFunction::parse(node.as_string(), node.where()); }

/// `eigen` with any of `data_keys` (data of an inhomogeneous problem) is an input error.
std::optional<EigenSpec> parse_eigen_of(const ConfigNode& node, const std::vector<std::string>& data_keys) {
  const auto eigen = node.find("eigen");
  if (!eigen) return std::nullopt;
  for (const std::string& key : data_keys)
    if (const auto data = node.find(key))
      data->fail("an eigenproblem (problem.eigen) has homogeneous conditions and no source: remove '" + key + "'");
  return parse_eigen(*eigen);
}

void derive_from_exact(ProblemSpec& p, const SymbolicFunction& u) {
  p.exact = u;
  p.value = u;
  p.gradient_x = u.diff_x();
  p.gradient_y = u.diff_y();
  p.laplacian = u.laplacian();
  p.source = p.pde == Pde::poisson ? -u.laplacian() : u.bilaplacian();
}

/// `boundary:`, a map from boundary part names to one of the two condition `kinds` ("all" first,
/// named parts after it override it). `hessian`: the Hessian form, which refuses simply_supported.
std::vector<BoundaryPart> parse_boundary_parts(const ConfigNode& boundary, const std::vector<std::string>& kinds,
                                               bool hessian) {
  if (!boundary.is_map() || boundary.keys().empty())
    boundary.fail("expected a map from boundary part (all, left, ...) to a condition (" + kinds[0] + ", " +
                  kinds[1] + ")");
  std::vector<BoundaryPart> parts;
  for (const std::string& name : boundary.keys()) {
    const ConfigNode entry = boundary[name];
    const std::string k = entry.as_choice(kinds);
    BoundaryKind kind = k == "dirichlet"   ? BoundaryKind::dirichlet
                        : k == "neumann"   ? BoundaryKind::neumann
                        : k == "clamped"   ? BoundaryKind::clamped
                                           : BoundaryKind::simply_supported;
    if (kind == BoundaryKind::simply_supported && hessian)
      entry.fail("simply_supported needs form: laplacian (the Hessian form has another natural condition)");
    BoundaryPart part{name, kind, entry.where()};
    if (name == "all") parts.insert(parts.begin(), part);
    else parts.push_back(part);
  }
  return parts;
}

/// `problem:` with `pde: laplace_beltrami` or `surface_biharmonic` (keys pde, exact, source, reaction,
/// eigen; expressions in x, y, z; boundary {all: dirichlet} and boundary_value for laplace_beltrami,
/// boundary {all: clamped} with data from exact for surface_biharmonic). With
/// both exact and source, the source is used as given and exact measures the errors.
ProblemSpec parse_surface_problem(const ConfigNode& node) {
  node.check_keys({"pde", "exact", "source", "reaction", "boundary", "boundary_value", "eigen"});
  ProblemSpec p;
  p.eigen = parse_eigen_of(node, {"exact", "source", "boundary_value"});
  if (const auto c = node.find("reaction")) {
    p.reaction = c->as_double();
    if (!(p.reaction >= 0.0 && std::isfinite(p.reaction))) c->fail("reaction must be a number >= 0");
  }
  p.pde = node["pde"].as_string() == "surface_biharmonic" ? Pde::surface_biharmonic : Pde::laplace_beltrami;
  if (p.pde == Pde::surface_biharmonic) {
    // Δ_Γ²u + c u = f: ∫ Δ_Γu Δ_Γv + c ∫ u v (the planar bilaplace integrator reads the covariant
    // Hessian on a surface). On a closed surface with c = 0 the constants are the kernel (fixed by
    // the mean, as for Laplace–Beltrami); open ones are clamped (u, ∂_ν u) or simply supported
    // (u, and Δ_Γu as a natural condition) part by part ("all" first, named parts override it;
    // the names and that every edge has a condition are checked against the space), data from
    // `exact`; either fixes u for any c >= 0.
    const auto boundary = node.find("boundary");
    if (boundary) {
      p.boundary = parse_boundary_parts(*boundary, {"clamped", "simply_supported"}, false);
      const bool clamped = std::any_of(p.boundary.begin(), p.boundary.end(),
                                       [](const BoundaryPart& b) { return b.kind == BoundaryKind::clamped; });
      if (!node.has("exact"))
        boundary->fail(clamped ? "clamped data (u and its conormal derivative) are taken from 'exact': give it"
                               : "simply supported data (u and Δ_Γu) are taken from 'exact': give it");
    }
    if (const auto value = node.find("boundary_value"))
      value->fail("surface_biharmonic takes its boundary data from 'exact' (no boundary_value)");
    // Not yet verified against a known spectrum (the smooth cube has none in closed form).
    if (const auto eigen = node.find("eigen"))
      eigen->fail("eigenproblems of surface_biharmonic are not supported yet (laplace_beltrami's are)");
    p.terms = {bilaplace_integrator()};
  }
  if (p.reaction > 0) p.terms.push_back(mass_integrator(p.reaction));
  const auto exact = node.find("exact");
  const auto source = node.find("source");
  if (!exact && !source && !p.eigen) node.fail("give 'exact' (a solution in x, y, z), 'source', both, or 'eigen'");
  // Messages about the problem as a whole (SurfaceFormulation::check) name the eigen block then.
  if (p.eigen) p.source_where = node["eigen"].where();
  if (exact) {
    p.surface_exact = SymbolicFunction::parse_xyz(exact->as_string(), exact->where());
    p.source_where = p.data_where = exact->where();
  }
  // With both, the source is used as given and `exact` only measures the errors: data of another
  // surface (the true sphere) on the constructed one, where the geometric error shows.
  if (source) {
    p.surface_source = SymbolicFunction::parse_xyz(source->as_string(), source->where());
    p.source_where = source->where();
  }
  // Open surfaces: u = g on the whole boundary curve, g from boundary_value or else from exact.
  if (const auto boundary = node.find("boundary"); boundary && p.pde == Pde::laplace_beltrami) {
    // Not check_keys: part names are free names elsewhere; a surface has only `all`.
    for (const std::string& key : boundary->keys())
      if (key != "all") (*boundary)[key].fail("a surface has one boundary part, 'all' (its whole boundary curve)");
    const ConfigNode all = (*boundary)["all"];
    if (all.as_choice({"dirichlet"}) != "dirichlet") all.fail("expected dirichlet");
    p.boundary.push_back({"all", BoundaryKind::dirichlet, all.where()});
    if (const auto value = node.find("boundary_value")) {
      p.surface_dirichlet = SymbolicFunction::parse_xyz(value->as_string(), value->where());
      p.data_where = value->where();
    } else if (p.surface_exact) {
      p.surface_dirichlet = p.surface_exact;
    } else if (p.eigen) {
      p.surface_dirichlet = SymbolicFunction::constant(0.0);
    } else {
      boundary->fail("Dirichlet data need 'boundary_value' (a function of x, y, z) or 'exact'");
    }
  } else if (const auto value = node.find("boundary_value"); value && p.pde == Pde::laplace_beltrami) {
    value->fail("'boundary_value' needs 'boundary: {all: dirichlet}'");
  }
  return p;
}

}  // namespace

ExactSolution ProblemSpec::exact_solution() const {
  ExactSolution s;
  if (!exact) return s;
  const SymbolicFunction& u = *exact;
  const SymbolicFunction ux = u.diff_x(), uy = u.diff_y();
  s.u = u;
  s.ux = ux;
  s.uy = uy;
  const SymbolicFunction uxx = ux.diff_x(), uxy = ux.diff_y(), uyy = uy.diff_y();
  s.uxx = uxx;
  s.uxy = uxy;
  s.uyy = uyy;
  s.jet = batch_field(FunctionBatch({u, ux, uy, uxx, uxy, uyy}));
  return s;
}

BoundaryField ProblemSpec::normal_derivative_field() const {
  if (gradient_x && gradient_y) {
    const SymbolicFunction gx = *gradient_x, gy = *gradient_y;
    return [gx, gy](const Point2& x, const Point2& n) { return gx(x) * n.x() + gy(x) * n.y(); };
  }
  const SymbolicFunction dn = normal_derivative;
  return [dn](const Point2& x, const Point2&) { return dn(x); };
}

ProblemSpec manufactured_problem(Pde pde, const SymbolicFunction& u, std::vector<BoundaryPart> boundary) {
  ProblemSpec p;
  p.pde = pde;
  if (pde == Pde::biharmonic) p.terms = {bilaplace_integrator()};
  derive_from_exact(p, u);
  p.boundary = std::move(boundary);
  return p;
}

ProblemSpec parse_problem(const ConfigNode& node) {
  // Surfaces have their own keys (no boundary; reaction).
  if (const auto pde = node.find("pde");
      pde && pde->is_scalar() && (pde->as_string() == "laplace_beltrami" || pde->as_string() == "surface_biharmonic"))
    return parse_surface_problem(node);
  if (const auto pde = node.find("pde"); pde && pde->is_scalar() && pde->as_string() == "kirchhoff_love_shell")
    return parse_shell_problem(node);
  node.check_keys({"pde", "exact", "source", "boundary", "data", "form", "eigen"});
  ProblemSpec p;
  p.eigen = parse_eigen_of(node, {"exact", "source", "data"});
  const std::string pde =
      node["pde"].as_choice({"poisson", "biharmonic", "laplace_beltrami", "surface_biharmonic", "kirchhoff_love_shell"});
  p.pde = pde == "poisson" ? Pde::poisson : Pde::biharmonic;  // the surface problems returned above

  bool hessian = false;
  if (auto form = node.find("form")) {
    if (p.pde == Pde::poisson) form->fail("'form' applies to biharmonic problems only");
    hessian = form->as_choice({"laplacian", "hessian"}) == "hessian";
  }
  if (p.pde == Pde::biharmonic) p.terms = {hessian ? hessian_integrator() : bilaplace_integrator()};

  if (auto exact = node.find("exact")) {
    derive_from_exact(p, parse_expression(*exact));
    p.source_where = p.data_where = exact->where();
  }
  if (auto source = node.find("source")) {
    p.source = parse_expression(*source);
    p.source_where = source->where();
  }
  else if (!p.exact && !p.eigen) node.fail("give 'exact' (a manufactured solution), 'source', or 'eigen'");

  if (auto data = node.find("data")) {
    if (p.exact) data->fail("'data' is derived from 'exact'; give one or the other");
    data->check_keys({"u", "dudn", "laplace_u"});
    p.data_where = data->where();
    if (auto u = data->find("u")) p.value = parse_expression(*u);
    if (auto dn = data->find("dudn")) p.normal_derivative = parse_expression(*dn);
    if (auto lap = data->find("laplace_u")) p.laplacian = parse_expression(*lap);
  }

  const std::vector<std::string> kinds = p.pde == Pde::poisson
                                             ? std::vector<std::string>{"dirichlet", "neumann"}
                                             : std::vector<std::string>{"clamped", "simply_supported"};
  p.boundary = parse_boundary_parts(node["boundary"], kinds, hessian);
  return p;
}

}  // namespace iga
