#include "output/study_outputs.hpp"

#include <filesystem>
#include <vector>

#include "output/surface_geometry_vtk.hpp"
#include "output/surface_files.hpp"
#include "output/matrix_market_sink.hpp"
#include "output/vtk_writer.hpp"

namespace iga {

StudyResult run_study_with_vtk(const StudySettings& settings, const std::string& directory,
                               const ProgressSink& progress) {
  const LevelSink matrices = settings.write_matrices ? matrix_market_sink(settings, directory, progress) : LevelSink{};
  // A surface is the same at every level: its files are written once (surface.vtu with VTK output,
  // surface_patches.txt always).
  const auto with_surface_files = [&](StudyResult result) {
    if (result.surface) {
      progress("writing the surface");
      write_surface_files(*result.surface, directory, "surface", settings.vtk_samples, settings.write_vtk);
    }
    return result;
  };
  if (!settings.write_vtk) return with_surface_files(run_study(settings, progress, matrices));
  const std::filesystem::path dir(directory);
  const ExactSolution exact = settings.problem.exact_solution();
  std::vector<std::string> vtu_files, mesh_files, surface_files;
  const LevelSink write_level = [&](int level, const Space& space, const DiscreteSolution& sol) {
    progress("[level " + std::to_string(level) + "] writing VTK");
    VtkFieldOptions opt;
    opt.samples = settings.vtk_samples;
    opt.exact = exact.u;
    if (settings.problem.surface_exact)
      opt.exact3 = [u = *settings.problem.surface_exact](const Eigen::Vector3d& x) { return u.at(x); };
    opt.laplacian = settings.problem.pde == Pde::biharmonic;
    const std::string name = "solution_" + std::to_string(level) + ".vtu";
    write_solution_vtu(space, sol.coefficients, opt, (dir / name).string());
    vtu_files.push_back(name);
    const std::string mesh = "mesh_" + std::to_string(level) + ".vtu";
    write_mesh_vtu(space, settings.vtk_samples, (dir / mesh).string());
    mesh_files.push_back(mesh);
    // The surface itself, shaded by its own normals, level by level unless the space carries one
    // fixed surface (written once, below).
    if (space.ambient_dimension() == 3 && !space.surface_patches()) {
      const std::string surface = "surface_" + std::to_string(level) + ".vtu";
      write_surface_geometry_vtu(space, settings.vtk_samples, (dir / surface).string());
      surface_files.push_back(surface);
    }
  };
  StudyResult result = run_study(settings, progress, [&](int level, const Space& space, const DiscreteSolution& sol) {
    write_level(level, space, sol);
    if (matrices) matrices(level, space, sol);
  });
  write_pvd(vtu_files, (dir / "solution.pvd").string());
  write_pvd(mesh_files, (dir / "mesh.pvd").string());
  if (!surface_files.empty()) write_pvd(surface_files, (dir / "surface.pvd").string());
  return with_surface_files(std::move(result));
}

}  // namespace iga
