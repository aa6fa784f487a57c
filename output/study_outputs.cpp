#include "output/study_outputs.hpp"

#include <chrono>
#include <filesystem>
#include <vector>

#include "output/surface_geometry_vtk.hpp"
#include "output/surface_files.hpp"
#include "output/matrix_market_sink.hpp"
#include "output/parallel_vtk.hpp"
#include "spaces/space_part.hpp"
#include "solver/petsc_session.hpp"
#include "output/vtk_writer.hpp"

namespace iga {

StudyResult run_study_with_vtk(const StudySettings& settings, const std::string& directory,
                               const ProgressSink& progress) {
  // Under mpirun every rank comes here and writes its piece of the solution; rank 0 all the rest.
  const bool root = is_root_rank();
  const LevelSink matrices = settings.write_matrices && root ? matrix_market_sink(settings, directory, progress) : LevelSink{};
  // A surface is the same at every level: its files are written once (surface.vtu with VTK output,
  // surface_patches.txt always).
  const auto with_surface_files = [&](StudyResult result) {
    if (result.surface && root) {
      progress("writing the surface");
      write_surface_files(*result.surface, directory, "surface", settings.vtk_samples, settings.write_vtk);
    }
    return result;
  };
  if (!settings.write_vtk) return with_surface_files(run_study(settings, progress, matrices));
  const std::filesystem::path dir(directory);
  const ExactSolution exact = settings.problem.exact_solution();
  std::vector<std::string> vtu_files, mesh_files, surface_files;
  double t_vtk = 0;
  const LevelSink write_level = [&](int level, const Space& space, const DiscreteSolution& sol) {
    // output.vtk.levels: last. A uniform study knows its last level; an adaptive one may stop at
    // any level, so each level replaces the files of the one before.
    const bool last_only = settings.vtk_last_level_only;
    if (last_only && !settings.adaptive && level + 1 < settings.levels) return;
    const auto t0 = std::chrono::steady_clock::now();
    progress("[level " + std::to_string(level) + "] writing VTK");
    if (last_only && !vtu_files.empty() && root) {
      remove_solution_dataset((dir / vtu_files.back()).string());
      std::filesystem::remove(dir / mesh_files.back());
      vtu_files.clear();
      mesh_files.clear();
      if (!surface_files.empty()) std::filesystem::remove(dir / surface_files.back());
      surface_files.clear();
    }
    VtkFieldOptions opt;
    opt.samples = settings.vtk_samples;
    opt.lagrange = settings.vtk_lagrange;
    opt.compression = settings.vtk_compression;
    opt.exact = exact;
    if (settings.problem.surface_exact)
      opt.exact3 = [u = *settings.problem.surface_exact](const Eigen::Vector3d& x) { return u.at(x); };
    opt.laplacian = settings.problem.pde == Pde::biharmonic;
    if (!sol.indicators.empty()) {
      opt.element_fields.emplace_back("estimator", sol.indicators);
      std::vector<double> marked(space.num_elements(), 0.0);
      for (int e : sol.marked) marked.at(e) = 1.0;
      opt.element_fields.emplace_back("marked", std::move(marked));
    }
    for (int j = 0; j < sol.modes.cols(); ++j)  // eigenproblems: every mode (the first is also u)
      opt.point_functions.emplace_back("mode_" + std::to_string(j + 1), sol.modes.col(j));
    // A shell's displacement (three components in blocks): the vector field `displacement`, and
    // its vertical component u_z as the scalar `u`.
    const int n = space.dimension();
    const bool vector = sol.coefficients.size() == 3 * n;
    const Eigen::VectorXd u = vector ? Eigen::VectorXd(sol.coefficients.segment(2 * n, n)) : sol.coefficients;
    if (vector) opt.vector_functions.emplace_back("displacement", sol.coefficients);
    if (vector && settings.problem.shell && settings.problem.shell->exact)  // u_exact and error of u_z
      opt.exact3 = [u = (*settings.problem.shell->exact)[2]](const Eigen::Vector3d& x) { return u.at(x); };
    const bool pieces = parallel_vtk_output();
    const std::string name = "solution_" + std::to_string(level) + (pieces ? ".pvtu" : ".vtu");
    const bool lagrange = pieces ? write_solution_pvtu(space, u, opt, (dir / name).string())
                                 : write_solution_vtu(space, u, opt, (dir / name).string());
    vtu_files.push_back(name);
    if (!root) return;
    // The mesh outlines and the surface are one file of the whole space, from rank 0.
    const auto* part = dynamic_cast<const SpacePart*>(&space);
    const Space& whole = part ? part->whole() : space;
    const std::string mesh = "mesh_" + std::to_string(level) + ".vtu";
    // Outlines as fine as the solution's drawing: Lagrange cells of degree p have p + 1 nodes per
    // edge, a subdivided element 2p + 1; the straight edges of affine elements need their ends only.
    const int outline_samples = space.affine_elements() ? 1
                                : lagrange              ? space.degree()
                                : settings.vtk_lagrange ? opt.divisions * space.degree()
                                                        : settings.vtk_samples;
    write_mesh_vtu(whole, outline_samples, (dir / mesh).string(), settings.vtk_compression);
    mesh_files.push_back(mesh);
    // The surface itself, shaded by its own normals, level by level unless the space carries one
    // fixed surface (written once, below).
    if (space.ambient_dimension() == 3 && !space.surface_patches()) {
      const std::string surface = "surface_" + std::to_string(level) + ".vtu";
      write_surface_geometry_vtu(whole, settings.vtk_samples, (dir / surface).string());
      surface_files.push_back(surface);
    }
    t_vtk += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  StudyResult result = run_study(settings, progress, [&](int level, const Space& space, const DiscreteSolution& sol) {
    write_level(level, space, sol);
    if (matrices) matrices(level, space, sol);
  });
  if (root) {
    write_pvd(vtu_files, (dir / "solution.pvd").string());
    write_pvd(mesh_files, (dir / "mesh.pvd").string());
    if (!surface_files.empty()) write_pvd(surface_files, (dir / "surface.pvd").string());
  }
  result.t_vtk = t_vtk;
  return with_surface_files(std::move(result));
}

}  // namespace iga
