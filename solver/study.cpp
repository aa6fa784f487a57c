#include "solver/study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>

#include "assembly/error_indicator.hpp"
#include "solver/boundary_edge_kinds.hpp"
#include "solver/data_finiteness.hpp"
#include "solver/dorfler_marking.hpp"
#include "solver/level_difference.hpp"
#include "solver/output_location.hpp"
#include "solver/resource_checks.hpp"
#include "config/errors.hpp"
#include "config/progress.hpp"
#include "solver/petsc_session.hpp"
#include "solver/rank_part.hpp"
#include "solver/petsc_settings.hpp"
#include "solver/solve_problem.hpp"
#include "spaces/lifted_space.hpp"
#include "spaces/space_factory.hpp"
#include "spaces/surface_label.hpp"

namespace iga {

namespace {
std::string format_seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f s", s);
  return buf;
}

/// Whether the levels may work on parts of the space (rank_part.hpp; the formulation has the last
/// word): then the spaces that can are built as skeletons, and each rank builds the per-element
/// data of its part only. Eigenproblems, adaptive studies, level differences and the matrix export
/// take the whole space.
bool may_work_on_parts(const StudySettings& s) {
  const bool differences = !s.problem.exact && !on_surface(s.problem.pde) && !s.problem.eigen;
  return s.solver == SolverKind::petsc && !s.problem.eigen && !s.adaptive && !differences && !s.write_matrices;
}

/// How the levels' spaces are built: as skeletons only when several ranks will each build a part.
/// One rank's part is the whole, and a G1 skeleton would solve every local problem twice (once
/// to count the functions, once for the part: the g1 benchmark's space 3.8 → 7.4 s).
SpaceExtent level_extent(const StudySettings& s) {
  return may_work_on_parts(s) && mpi_size() > 1 ? SpaceExtent::skeleton : SpaceExtent::whole;
}
}  // namespace

OptimalRates optimal_rates(Pde pde, int degree) {
  if (pde != Pde::biharmonic) return {degree + 1, degree, degree - 1};
  return {degree - 1 + std::min(2, degree - 1), degree - 1 + std::min(1, degree - 1), degree - 1};
}

StudySettings parse_study(const ConfigNode& root, const std::string& config_path, int levels_override,
                          const std::string& output_override, const ConfigNode* space_block,
                          const ConfigNode* domain_block) {
  root.check_keys({"problem", "domain", "space", "spaces", "refinement", "solver", "output", "limits"});
  // A comparison (spaces:) asked for as one study: every space is validated, the first one returned.
  if (!space_block && root.has("spaces") && !root.has("space"))
    return parse_studies(root, config_path, levels_override, output_override).front();
  // In this order, so that of several mistakes the first section's is reported.
  ProblemSpec problem = parse_problem(root["problem"]);
  const ResourceLimits limits = parse_limits(root.find("limits"));
  const ConfigNode space_node = space_block ? *space_block : root["space"];
  const ConfigNode domain_node = domain_block ? *domain_block : root["domain"];
  StudySettings s(root, std::move(problem), space_node, domain_node);
  s.limits = limits;

  // The output location and the solver first: they cost nothing to check, and building level 0
  // below may take a while (a .geo meshed by Gmsh, a large first level).
  if (auto solver = root.find("solver")) parse_solver_settings(*solver, s.problem.pde, s.solver, s.petsc);
  s.output_dir = "results/" + std::filesystem::path(config_path).stem().string();
  std::string output_place = "the default output directory";
  if (auto output = root.find("output")) {
    output->check_keys({"directory", "vtk", "plot", "matrices", "functionals"});
    if (auto dir = output->find("directory")) {
      s.output_dir = dir->as_string();
      output_place = dir->where();
    }
    if (auto vtk = output->find("vtk")) {
      if (vtk->is_scalar()) {
        s.write_vtk = vtk->as_bool();
      } else {
        vtk->check_keys({"enabled", "samples", "levels", "cells", "compression"});
        s.write_vtk = vtk->get_bool("enabled", true);
        if (auto levels = vtk->find("levels")) s.vtk_last_level_only = levels->as_choice({"all", "last"}) == "last";
        if (auto cells = vtk->find("cells")) s.vtk_lagrange = cells->as_choice({"lagrange", "linear"}) == "lagrange";
        if (auto compression = vtk->find("compression")) {
          const std::string c = compression->as_choice({"lz4", "zlib", "none"});
          s.vtk_compression = c == "zlib" ? VtkCompression::zlib : c == "none" ? VtkCompression::none : VtkCompression::lz4;
        }
        if (auto samples = vtk->find("samples")) {
          s.vtk_samples = samples->as_int();
          if (s.vtk_samples < 1 || s.vtk_samples > 64) samples->fail("samples must be between 1 and 64");
        }
      }
    }
    if (auto plot = output->find("plot")) s.write_plot = plot->as_bool();
    if (auto matrices = output->find("matrices")) {
      s.write_matrices = matrices->as_bool();
      if (s.write_matrices && on_surface(s.problem.pde))
        matrices->fail("matrix export is for planar problems (poisson, biharmonic), not " + to_string(s.problem.pde));
    }
  }
  if (!output_override.empty()) {
    s.output_dir = output_override;
    output_place = "--output";
  } else if (output_place != "the default output directory") {
    check_config_output_directory(s.output_dir, output_place);
  }
  check_output_directory(s.output_dir, output_place, {config_path});
  // Domain, space and boundary part names are validated on the coarsest space (cheap), so that
  // every input error surfaces before the study starts; what it asks for is checked first.
  check_space_request(space_node, s.limits);
  // The refinement keys cost nothing to check either; the adaptive ones that ask the space follow
  // level 0.
  const auto refinement = root.find("refinement");
  std::optional<ConfigNode> levels_node;  // the key blamed for a level that is too large
  if (refinement) {
    refinement->check_keys({"type", "levels", "marking", "max_dofs", "tolerance"});
    if (auto type = refinement->find("type")) s.adaptive = type->as_choice({"uniform", "adaptive"}) == "adaptive";
    if (!s.adaptive) {
      for (const char* key : {"marking", "max_dofs", "tolerance"})
        if (auto k = refinement->find(key)) k->fail(std::string(key) + " is only used with refinement.type: adaptive");
    }
    const int max_levels = s.adaptive ? 40 : 12;
    if (auto levels = refinement->find("levels")) {
      s.levels = levels->as_int();
      if (s.levels < 1 || s.levels > max_levels)
        levels->fail("levels must be between 1 and " + std::to_string(max_levels) + " (got " + std::to_string(s.levels) + ")");
      if (levels_override <= 0) levels_node = levels;
    }
    if (auto marking = refinement->find("marking")) {
      s.marking = marking->as_double();
      if (!(s.marking > 0.0 && s.marking <= 1.0)) marking->fail("the Dörfler parameter marking must be in (0, 1]");
    }
    if (auto max_dofs = refinement->find("max_dofs")) {
      s.max_dofs = max_dofs->as_int();
      if (s.max_dofs < 1) max_dofs->fail("max_dofs must be positive");
    }
    if (auto tolerance = refinement->find("tolerance")) {
      s.tolerance = tolerance->as_double();
      if (!(s.tolerance > 0.0)) tolerance->fail("the estimator tolerance must be > 0 (got " + format_number(s.tolerance) + ")");
    }
  }
  if (levels_override > 0) s.levels = levels_override;
  const ConfigNode& blame = levels_node ? *levels_node : space_node;
  const MemoryModel memory = memory_model(s.solver, s.petsc);
  // Uniform levels whose size follows from the request are checked before level 0 is built
  // (adaptive levels follow the solutions: level 0 only).
  check_requested_levels(domain_node, space_node, s.adaptive ? 1 : s.levels, s.limits, blame,
                         levels_override > 0 ? "--levels" : "refinement.levels", memory);

  const Stopwatch t_coarse;
  const SpacePtr coarse = make_space(domain_node, space_node, 0, nullptr,
                                     level_extent(s));
  s.level0 = coarse;
  s.level0_seconds = t_coarse.seconds();
  if (on_surface(s.problem.pde) != (coarse->ambient_dimension() == 3))
    root["problem"]["pde"].fail(on_surface(s.problem.pde)
                                    ? to_string(s.problem.pde) +
                                          " needs a surface in 3D (domain.type: surface, space.type: surface)"
                                    : "a surface in 3D takes pde: laplace_beltrami, surface_biharmonic or "
                                      "kirchhoff_love_shell");
  // A C0 space listing its interior edges takes the C0 interior penalty form of the surface
  // biharmonic (solver/surface_problem.hpp) on a graph surface (a lift) and on a surface built from
  // a triangle mesh (RSD patches); any other C0 space is refused for plates.
  const bool patches = coarse->surface_patches() != nullptr;
  const bool c0ip = s.problem.pde == Pde::surface_biharmonic && coarse->continuity() < 1 &&
                    coarse->ambient_dimension() == 3 && !coarse->interior_edges().empty() &&
                    (dynamic_cast<const LiftedSpace*>(coarse.get()) || patches);
  // Π0 patches (the default tuple) are parametrised with an in-plane distortion whose second
  // derivatives are of the size of h, not h², on every mesh: the H2 approximation of polynomials in
  // those parameters then degrades as the mesh is refined (docs/surface-biharmonic.md). Π1 has linear
  // precision and no such distortion.
  if (c0ip && patches && surface_label(*coarse, "tuple") == "pi0")
    (domain_node.find("tuple") ? domain_node["tuple"] : domain_node)
        .fail("the C0 interior penalty form of surface_biharmonic on a surface from a triangle mesh needs its Π1 "
              "patches (tuple: pi1): the Π0 patches' parametrisation has an in-plane distortion that does not shrink "
              "with the mesh and spoils the H2 approximation (errors of the size of u on the first levels, larger on "
              "finer meshes)");
  // Without the G1 correction neighbouring patches meet with a kink: a smooth u has conormal jumps.
  if (c0ip && patches && surface_label(*coarse, "method") == "none")
    domain_node["method"].fail("the C0 interior penalty form of surface_biharmonic needs a G1 surface (its "
                               "consistency assumes one tangent plane across every patch edge); method: none "
                               "leaves the patches only C0");
  if ((s.problem.pde == Pde::biharmonic || s.problem.pde == Pde::surface_biharmonic ||
       s.problem.pde == Pde::kirchhoff_love_shell) &&
      coarse->continuity() < 1 && !c0ip)
    space_node.fail("the " + to_string(s.problem.pde) + " problem needs a C1 (H2-conforming) space; this " + coarse->type() +
                       " space is only C" + std::to_string(coarse->continuity()) +
                       " (raise space.degree/space.regularity" +
                       (s.problem.pde == Pde::surface_biharmonic
                            ? "; the C0 interior penalty form takes C0 spaces with interior edges on graph surfaces and on surfaces from triangle meshes)"
                            : ")"));
  if (c0ip && coarse->degree() < 2)
    space_node.fail("the C0 interior penalty form of surface_biharmonic needs degree >= 2 (piecewise linear "
                              "functions of degree 1 have no second derivatives to approximate Δ_Γu with)");
  if (c0ip && s.solver == SolverKind::petsc)
    root["solver"]["type"].fail("the C0 interior penalty form of surface_biharmonic (a C0 space) couples the elements "
                                "of every edge, which the PETSc assembly element by element does not; use cholmod "
                                "or umfpack");
  // The shell's three components: the adaptive indicators count one unknown per function (the
  // serial and PETSc linear backends take components; eigenproblems are refused at problem.eigen).
  if (s.problem.pde == Pde::kirchhoff_love_shell && s.adaptive)
    root["refinement"]["type"].fail("kirchhoff_love_shell has no adaptive refinement yet (uniform)");
  // Boundary part names; a surface's boundary against its Dirichlet data (the pipeline's own check).
  make_formulation(*coarse, s.problem)->check();
  if (s.problem.eigen) {
    if (s.solver == SolverKind::petsc) {
      if (!slepc_available())
        root["solver"]["type"].fail("eigenproblems under solver.type: petsc need SLEPc, and this iga-run was built "
                                    "without it (install libslepc-real-dev and rebuild); the serial eigensolver "
                                    "needs no solver.type");
      // The eigensolve factors K − σM with MUMPS (shift-and-invert): no Krylov solve to choose.
      for (const char* key : {"ksp", "pc", "rtol", "max_iterations"})
        if (const auto k = root["solver"].find(key))
          k->fail("not used by the eigensolver (SLEPc shift-and-invert with a MUMPS Cholesky factor): remove it");
    }
    // The indicator of −Δu = λu (eigen_residual_indicators); plates and surfaces have none yet.
    if (s.adaptive && s.problem.pde != Pde::poisson)
      refinement->fail("adaptive refinement of eigenproblems (problem.eigen) is for pde: poisson (driven by the first "
                       "eigenfunction of −Δu = λu), not " + to_string(s.problem.pde));
  }
  if (s.adaptive) {
    if (s.problem.pde == Pde::biharmonic) {
      if (!coarse->higher_derivatives() || (coarse->num_elements() > 1 && coarse->interior_edges().empty()))
        refinement->fail("adaptive biharmonic refinement needs third and fourth derivatives and the interior edges "
                         "of the space (the plate residual indicator); the " + coarse->type() + " space has not both");
    }
    if (!dynamic_cast<const LocallyRefinable*>(coarse.get()))  // asking refined({}) would build a space
      refinement->fail("adaptive refinement: the " + coarse->type() + " space does not support local refinement");
    // Without the normal-derivative jumps the indicator of a C0 space misses its dominant part.
    if (coarse->continuity() < 1 && coarse->num_elements() > 1 && coarse->interior_edges().empty())
      refinement->fail("adaptive refinement: this C0 " + coarse->type() +
                       " space cannot list its interior edges, so the residual indicator would miss the "
                       "normal-derivative jumps; use a C1 space");
  }

  // Every level's size before the study starts: level 0 as built, the others estimated from it.
  if (coarse->degree() > s.limits.max_degree)  // spaces whose degree is not the key `degree`
    space_node.fail("the " + coarse->type() + " space has degree " + std::to_string(coarse->degree()) +
                       ", more than limits.max_degree = " + std::to_string(s.limits.max_degree) +
                       how_to_raise("max_degree"));
  const SpaceSize level0 = measure(*coarse);
  check_size(level0, s.limits, space_node, "level 0", memory);
  if (!s.adaptive)
    for (int level = 1; level < s.levels; ++level)
      check_size(uniform_estimate(level0, level), s.limits, blame,
                 "level " + std::to_string(level) + " (estimated from level 0)", memory);

  if (auto output = root.find("output"))  // they name points and boundary parts of the space
    if (auto functionals = output->find("functionals")) s.functionals = parse_functionals(*functionals, *coarse, s.problem.shell ? 3 : 1);
  s.space_label = coarse->type() + "-p" + std::to_string(coarse->degree());
  return s;
}

std::vector<StudySettings> parse_studies(const ConfigNode& root, const std::string& config_path, int levels_override,
                                         const std::string& output_override) {
  const auto spaces = root.find("spaces");
  if (!spaces) return {parse_study(root, config_path, levels_override, output_override)};
  if (root.has("space")) root["space"].fail("give either space: (one study) or spaces: (a comparison), not both");
  if (!spaces->is_sequence() || spaces->items().empty())
    spaces->fail("spaces: must be a list of space blocks, e.g. [{type: bspline, degree: 3}, {type: ws4}]");
  std::vector<StudySettings> studies;
  for (const ConfigNode& item : spaces->items()) {
    // An item is a space block, or {space: ..., domain: ...} for a space that needs its own
    // description of the domain (e.g. a multi-patch layout of the same square).
    if (item.is_map() && item.has("space")) {
      item.check_keys({"space", "domain"});
      const ConfigNode block = item["space"];
      const std::optional<ConfigNode> domain = item.find("domain");
      studies.push_back(parse_study(root, config_path, levels_override, output_override, &block,
                                    domain ? &*domain : nullptr));
    } else {
      studies.push_back(parse_study(root, config_path, levels_override, output_override, &item));
    }
  }
  return studies;
}

StudyResult run_study(const StudySettings& settings, const ProgressSink& progress, const LevelSink& on_level) {
  StudyResult result;
  const ConfigNode domain = settings.domain, space_node = settings.space;
  const ExactSolution exact = settings.problem.exact_solution();
  result.adaptive = settings.adaptive;
  SpacePtr next;      // adaptive: the refined space for the next level
  SpacePtr previous;  // uniform: the last level's space, whose level-independent parts the next shares
  double t_next = 0.0;
  // Without an exact solution: the previous level's solution, located by its own space, for the
  // differences between successive levels (planar problems).
  const bool differences =
      !settings.problem.exact && !on_surface(settings.problem.pde) && !settings.problem.eigen;
  std::shared_ptr<const PointLocator> previous_locator;
  Eigen::VectorXd previous_coefficients;
  for (int level = 0; level < settings.levels; ++level) {
    const std::string tag = "[level " + std::to_string(level) + "] ";
    progress(tag + "building space");
    const Stopwatch t0;
    const bool reuse = !next && level == 0 && settings.level0;
    const SpaceExtent extent = level_extent(settings);
    SpacePtr space = next    ? next
                     : reuse ? settings.level0
                             : [&] {
                                 const ProgressPhase phase("building space", 0);
                                 return make_space(domain, space_node, settings.adaptive ? 0 : level, previous.get(),
                                                   extent);
                               }();
    previous = space;
    const double t_space = t0.seconds() + t_next + (reuse ? settings.level0_seconds : 0.0);
    check_size(measure(*space), settings.limits, space_node, "level " + std::to_string(level),
               memory_model(settings.solver, settings.petsc));  // before assembly
    progress(tag + "space: " + std::to_string(space->dimension()) + " dofs, " +
             std::to_string(space->num_elements()) + " elements (" + format_seconds(t_space) + ")");

    // Under PETSc each rank works on its part of the space (rank_part.hpp) where the problem
    // allows it; eigenproblems, adaptive studies, level differences and the matrix export (the
    // whole system from rank 0) still take the whole.
    std::shared_ptr<const SpacePart> part;
    std::vector<int> own;
    const Stopwatch t_part;  // a skeleton's per-element data are built here: part of building the space
    if (may_work_on_parts(settings) && make_formulation(*space, settings.problem)->works_on_parts()) {
      part = rank_part(space, mpi_rank(), mpi_size());  // builds the part's elements of a skeleton
      own = part->owned_elements();
    } else if (extent == SpaceExtent::skeleton) {  // the whole after all
      std::vector<int> all(space->num_elements());
      std::iota(all.begin(), all.end(), 0);
      space = on_elements(space, all);
    }
    const double t_built = t_space + (part || extent == SpaceExtent::skeleton ? t_part.seconds() : 0.0);
    const Space& work = part ? static_cast<const Space&>(*part) : *space;
    const WorkShare share = part ? WorkShare{&own, true} : WorkShare{};
    // Quadrature points miss poles on mesh lines; new vertices and edges come with every level.
    // On parts each rank checks its own (and an error on one reaches all).
    if (part) on_every_rank([&] { check_data_finite(work, settings.problem); });
    else check_data_finite(*space, settings.problem);
    DiscreteSolution sol = solve_problem(work, settings.problem, settings.solver,
                                         [&](const std::string& msg) { progress(tag + msg); }, settings.petsc);
    sol.result.level = level;
    sol.result.t_space = t_built;
    if (settings.problem.eigen)
      result.eigen.push_back(
          {level, sol.result.h, sol.result.dofs, sol.result.free_dofs, sol.eigenvalues, sol.spectrum});
    if (!result.rows.empty() && result.rows.back().energy && sol.result.energy)
      sol.result.energy_difference = std::sqrt(std::abs(*sol.result.energy - *result.rows.back().energy));
    std::shared_ptr<const PointLocator> locator;
    const bool points = std::any_of(settings.functionals.begin(), settings.functionals.end(),
                                    [](const FunctionalSpec& f) { return f.kind == FunctionalSpec::Kind::point; });
    if ((differences && level + 1 < settings.levels) || points)
      locator = std::make_shared<PointLocator>(part ? SpacePtr(part) : space);
    sol.result.functionals = evaluate_functionals(settings.functionals, work, sol.coefficients, locator.get(), share);
    if (differences && previous_locator) {
      const Stopwatch t_diff;
      progress(tag + "differences to the previous level");
      const ProgressPhase phase("differences", space->num_elements());
      const ErrorNorms d = level_difference(*space, sol.coefficients, *previous_locator, previous_coefficients,
                                            space->continuity() >= 1, difference_rule(*space));
      sol.result.difference_l2 = d.l2;
      sol.result.difference_h1 = d.h1;
      sol.result.difference_h2 = d.h2;
      sol.result.t_errors += t_diff.seconds();
    }
    if (differences) {
      previous_locator = locator;
      previous_coefficients = sol.coefficients;
    }
    progress(tag + "done: assembled in " + format_seconds(sol.result.t_assemble) + ", solved (" + sol.solve.method + ") in " +
             format_seconds(sol.result.t_solve) + ", errors in " + format_seconds(sol.result.t_errors));

    std::optional<double> estimator;
    next.reset();
    if (settings.adaptive) {
      const ScalarField f = settings.problem.source;
      // An eigenproblem refines for its first eigenpair: the residual of −Δu_h = λ_h u_h.
      const std::vector<double> eta =
          settings.problem.eigen
              ? eigen_residual_indicators(*space, sol.coefficients, sol.eigenvalues[0], space->error_quadrature_degree())
          : settings.problem.pde == Pde::poisson
              ? poisson_residual_indicators(*space, sol.coefficients, f, space->error_quadrature_degree())
              : plate_residual_indicators(
                    *space, sol.coefficients, f, space->error_quadrature_degree(),
                    split_boundary(*space, settings.problem).simply_supported,
                    [g = settings.problem.laplacian](const Point2& x, const Point2&) { return g(x); });
      estimator = total_indicator(eta);
      sol.indicators = eta;
      if (settings.tolerance > 0.0 && *estimator <= settings.tolerance) {
        progress(tag + "estimator " + std::to_string(*estimator) + " <= tolerance: stopping");
        result.stop_reason = "tolerance";
      } else if (level + 1 < settings.levels) {
        const Stopwatch t1;
        const std::vector<int> marked = dorfler_marking(eta, settings.marking);
        sol.marked = marked;
        progress(tag + "estimator " + std::to_string(*estimator) + ", refining " + std::to_string(marked.size()) +
                 " of " + std::to_string(space->num_elements()) + " elements");
        SpacePtr refined;
        try {
          refined = space->refined(marked);
        } catch (const std::runtime_error& e) {
          // E.g. a T-mesh whose integer lattice is exhausted at a singularity: the study ends here.
          progress(tag + "cannot refine further (" + e.what() + "): stopping");
          result.stop_reason = e.what();
        }
        t_next = t1.seconds();
        if (!refined) {
          if (result.stop_reason.empty()) throw std::logic_error("adaptive study on a space without local refinement");
        } else if (settings.max_dofs > 0 && refined->dimension() > settings.max_dofs) {
          progress(tag + "next level would have " + std::to_string(refined->dimension()) + " dofs > max_dofs: stopping");
          result.stop_reason = "max_dofs";
        } else
          next = std::move(refined);
      }
    }
    if (on_level) on_level(level, work, sol);  // after marking: the outputs show η_K and the marked elements
    result.estimators.push_back(estimator);
    result.rows.push_back(sol.result);
    result.solves.push_back(sol.solve);
    result.space_parameters = space->parameters();
    result.space_type = space->type();
    result.surface = space->surface_patches();
    result.expected = optimal_rates(settings.problem.pde, space->degree());
    if (settings.adaptive && !next) break;
  }
  return result;
}

}  // namespace iga
