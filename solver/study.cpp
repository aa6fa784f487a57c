#include "solver/study.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "solver/errors.hpp"
#include "solver/solve_problem.hpp"
#include "solver/vtk_writer.hpp"
#include "solver/staged_directory.hpp"
#include "spaces/space_factory.hpp"

namespace iga {

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string format_seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f s", s);
  return buf;
}
}  // namespace

OptimalRates optimal_rates(Pde pde, int degree) {
  if (pde == Pde::poisson) return {degree + 1, degree, degree - 1};
  return {degree - 1 + std::min(2, degree - 1), degree - 1 + std::min(1, degree - 1), degree - 1};
}

StudySettings parse_study(const ConfigNode& root, const std::string& config_path, int levels_override,
                          const std::string& output_override) {
  root.check_keys({"problem", "domain", "space", "refinement", "solver", "output"});
  StudySettings s(root, parse_problem(root["problem"]));
  // Domain, space and boundary part names are validated on the coarsest space (cheap), so that
  // every input error surfaces before the study starts.
  const SpacePtr coarse = make_space(root["domain"], root["space"], 0);
  check_boundary_parts(*coarse, s.problem);
  if (s.problem.pde == Pde::biharmonic && coarse->continuity() < 1)
    root["space"].fail("the biharmonic problem needs a C1 (H2-conforming) space; this " + coarse->type() +
                       " space is only C" + std::to_string(coarse->continuity()) +
                       " (raise space.degree/space.regularity)");

  if (auto refinement = root.find("refinement")) {
    refinement->check_keys({"levels"});
    if (auto levels = refinement->find("levels")) {
      s.levels = levels->as_int();
      if (s.levels < 1 || s.levels > 12) levels->fail("levels must be between 1 and 12 (got " + std::to_string(s.levels) + ")");
    }
  }
  if (levels_override > 0) s.levels = levels_override;

  if (auto solver = root.find("solver")) {
    solver->check_keys({"type"});
    if (auto type = solver->find("type"))
      s.solver = type->as_choice({"cholmod", "umfpack"}) == "cholmod" ? SolverKind::cholmod : SolverKind::umfpack;
  }

  s.output_dir = "results/" + std::filesystem::path(config_path).stem().string();
  if (auto output = root.find("output")) {
    output->check_keys({"directory", "vtk", "plot"});
    if (auto dir = output->find("directory")) s.output_dir = dir->as_string();
    if (auto vtk = output->find("vtk")) {
      if (vtk->is_scalar()) {
        s.write_vtk = vtk->as_bool();
      } else {
        vtk->check_keys({"enabled", "samples"});
        s.write_vtk = vtk->get_bool("enabled", true);
        if (auto samples = vtk->find("samples")) {
          s.vtk_samples = samples->as_int();
          if (s.vtk_samples < 1 || s.vtk_samples > 64) samples->fail("samples must be between 1 and 64");
        }
      }
    }
    if (auto plot = output->find("plot")) s.write_plot = plot->as_bool();
  }
  if (!output_override.empty()) s.output_dir = output_override;
  check_output_location(s.output_dir);
  return s;
}

StudyResult run_study(const StudySettings& settings, const std::string& directory, const ProgressSink& progress) {
  StudyResult result;
  const ConfigNode domain = settings.root["domain"], space_node = settings.root["space"];
  const ExactSolution exact = settings.problem.exact_solution();
  std::vector<std::string> vtu_files, mesh_files;
  for (int level = 0; level < settings.levels; ++level) {
    const std::string tag = "[level " + std::to_string(level) + "] ";
    progress(tag + "building space");
    auto t0 = Clock::now();
    const SpacePtr space = make_space(domain, space_node, level);
    const double t_space = seconds_since(t0);
    progress(tag + "space: " + std::to_string(space->dimension()) + " dofs, " +
             std::to_string(space->num_elements()) + " elements (" + format_seconds(t_space) + ")");

    DiscreteSolution sol = solve_problem(*space, settings.problem, settings.solver,
                                         [&](const std::string& msg) { progress(tag + msg); });
    sol.result.level = level;
    sol.result.t_space = t_space;
    progress(tag + "done: assembled in " + format_seconds(sol.result.t_assemble) + ", solved (" + sol.solve.method + ") in " +
             format_seconds(sol.result.t_solve) + ", errors in " + format_seconds(sol.result.t_errors));

    if (settings.write_vtk) {
      progress(tag + "writing VTK");
      VtkFieldOptions opt;
      opt.samples = settings.vtk_samples;
      opt.exact = exact.u;
      opt.laplacian = settings.problem.pde == Pde::biharmonic;
      const std::string name = "solution_" + std::to_string(level) + ".vtu";
      write_solution_vtu(*space, sol.coefficients, opt, (std::filesystem::path(directory) / name).string());
      vtu_files.push_back(name);
      const std::string mesh = "mesh_" + std::to_string(level) + ".vtu";
      write_mesh_vtu(*space, settings.vtk_samples, (std::filesystem::path(directory) / mesh).string());
      mesh_files.push_back(mesh);
    }
    result.rows.push_back(sol.result);
    result.solver_methods.push_back(sol.solve.method);
    result.relative_residuals.push_back(sol.solve.relative_residual);
    result.space_parameters = space->parameters();
    result.space_type = space->type();
    result.expected = optimal_rates(settings.problem.pde, space->degree());
  }
  if (settings.write_vtk) {
    write_pvd(vtu_files, (std::filesystem::path(directory) / "solution.pvd").string());
    write_pvd(mesh_files, (std::filesystem::path(directory) / "mesh.pvd").string());
  }
  return result;
}

}  // namespace iga
