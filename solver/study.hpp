#pragma once
/// @file
/// A convergence study: the same problem solved on a space refined level by level (uniformly or
/// adaptively). Files are written by the output layer (output/study_outputs.hpp).

#include <functional>
#include <string>
#include <vector>

#include "config/config_node.hpp"
#include "config/resource_limits.hpp"
#include "solver/eigen_table.hpp"
#include "solver/level_result.hpp"
#include "solver/linear_solver.hpp"
#include "solver/petsc_settings.hpp"
#include "solver/problem.hpp"
#include "solver/solve_problem.hpp"
#include "solver/study_functionals.hpp"

namespace iga {

/// How the .vtu files are compressed: LZ4 writes about five times faster than zlib, zlib's files
/// are about a third smaller.
enum class VtkCompression { lz4, zlib, none };

/// Everything a study needs, validated from the config (and command-line overrides).
struct StudySettings {
  StudySettings(ConfigNode root_node, ProblemSpec problem_spec, ConfigNode space_node, ConfigNode domain_node)
      : root(std::move(root_node)),
        problem(std::move(problem_spec)),
        space(std::move(space_node)),
        domain(std::move(domain_node)) {}
  ConfigNode root;
  ProblemSpec problem;
  ConfigNode space;         ///< the space block: root["space"], or one item of root["spaces"]
  ConfigNode domain;        ///< the domain block: root["domain"], or the item's own in a spaces: list
  std::string space_label;  ///< "<type>-p<degree>", names the space in comparisons
  int levels = 4;          ///< number of levels solved: 0 .. levels-1
  /// refinement.type: uniform (level l = make_space(..., l)) or adaptive (level l+1 = the space of
  /// level l refined where Dörfler marking of the residual indicator says; Poisson and plates).
  bool adaptive = false;
  double marking = 0.5;    ///< Dörfler θ (refinement.marking), adaptive only
  int max_dofs = 0;        ///< adaptive: stop before a level would exceed this many DOFs (0: no limit)
  double tolerance = 0.0;  ///< adaptive: stop once the estimator (Σ η_K²)^½ is <= this (0: no tolerance)
  SolverKind solver = SolverKind::cholmod;
  PetscSettings petsc;     ///< solver.type: petsc only
  std::string output_dir;  ///< final destination of the results
  bool write_vtk = true;
  int vtk_samples = 8;     ///< samples per element edge of linear sub-cells (output.vtk.samples)
  bool vtk_last_level_only = false;  ///< output.vtk.levels: last (default all)
  bool vtk_lagrange = true;          ///< output.vtk.cells: lagrange (default) or linear
  VtkCompression vtk_compression = VtkCompression::lz4;  ///< output.vtk.compression
  bool write_plot = true;
  bool write_matrices = false;  ///< output.matrices: each level's reduced system in Matrix Market
  ResourceLimits limits;   ///< the limits: section (defaults when absent)
  /// Level 0 as parse_study built it to validate the config, and its build time: run_study starts
  /// from it instead of building it again (a one-level study of a large space built it twice).
  SpacePtr level0;
  double level0_seconds = 0.0;
  std::vector<FunctionalSpec> functionals;  ///< output.functionals, evaluated at every level
};

/// Parse and validate the whole config (all sections) before anything is computed, so a typo
/// deep in the file fails before a long study starts. `levels_override` <= 0 means none.
/// `config_path` gives the default output directory results/<config name>.
/// `space_block` (default root["space"]) is the space to study, e.g. one item of root["spaces"].
StudySettings parse_study(const ConfigNode& root, const std::string& config_path, int levels_override,
                          const std::string& output_override, const ConfigNode* space_block = nullptr,
                          const ConfigNode* domain_block = nullptr);

/// One study per space: the config's `space:` block, or each block of its `spaces:` list (a
/// comparison of spaces on one problem). All are validated before any is run.
std::vector<StudySettings> parse_studies(const ConfigNode& root, const std::string& config_path, int levels_override,
                                         const std::string& output_override);


struct StudyResult {
  std::vector<LevelResult> rows;
  std::vector<std::pair<std::string, std::string>> space_parameters;  ///< of the finest level
  std::string space_type;
  /// Spaces on a smooth surface: the surface (the same at every level), for the outputs.
  std::shared_ptr<const SurfacePatches> surface;
  OptimalRates expected;     ///< for the space degree and PDE
  std::vector<SolveReport> solves;  ///< per level: method, relative residual, refinement steps
  /// Per level, (Σ η_K²)^{1/2} of the residual indicator (adaptive runs; nullopt otherwise).
  std::vector<std::optional<double>> estimators;
  bool adaptive = false;
  /// problem.eigen: every level's eigenvalues (rows[i].result has no errors then).
  std::vector<EigenLevel> eigen;
  /// Adaptive runs that ended before refinement.levels: "max_dofs", "tolerance" or why refinement failed.
  std::string stop_reason;
  double t_vtk = 0;          ///< seconds spent writing VTK files (all levels)
  double total_seconds = 0;  ///< wall time of the whole run, set by the caller that measures it
  int ranks = 1, threads = 1;  ///< MPI ranks and OpenMP threads per rank of the run, set by the same caller
};

/// Called once a level is solved, before the next level is built: how the outputs (VTK files) see
/// every level without the study loop knowing about files.
using LevelSink = std::function<void(int level, const Space& space, const DiscreteSolution& solution)>;

/// Run all levels, handing each solved level to `on_level` (if set).
StudyResult run_study(const StudySettings& settings, const ProgressSink& progress, const LevelSink& on_level = {});

/// Optimal orders of a conforming space of degree p (smooth solution): Poisson p+1, p, p−1;
/// biharmonic L2 p−1+min(2, p−1), H1 p−1+min(1, p−1), H2 p−1 (p = 2 gives 2, 2, 1).
OptimalRates optimal_rates(Pde pde, int degree);

}  // namespace iga
