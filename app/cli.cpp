#include "app/cli.hpp"

#include <CLI/CLI.hpp>
#include <omp.h>

#include <charconv>
#include <functional>
#include <chrono>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <optional>
#include <thread>

#include "app/catalogue.hpp"
#include "app/progress_bar.hpp"
#include "app/starter_configs.hpp"
#include "geometry/geometry_study.hpp"
#include "output/comparison.hpp"
#include "output/convergence_plot.hpp"
#include "output/eigen_plot.hpp"
#include "output/eigen_report.hpp"
#include "output/geometry_study_outputs.hpp"
#include "output/parallel_vtk.hpp"
#include "config/errors.hpp"
#include "output/report.hpp"
#include "output/staged_directory.hpp"
#include "output/study_outputs.hpp"
#include "solver/output_location.hpp"
#include "solver/blas_threads.hpp"
#include "solver/petsc_session.hpp"
#include "solver/study.hpp"

namespace iga {

namespace {

int fail(int code, const std::string& message) {
  // Under mpirun an error all ranks share is printed once; one rank's own error ends every rank.
  if (is_root_rank() || !failure_shared_by_all_ranks()) std::cerr << "iga-run: error: " << message << '\n';
  return end_ranks_after_failure(code);
}

using Clock = std::chrono::steady_clock;

ProgressSink progress_sink(bool quiet) {
  return [quiet](const std::string& msg) {
    if (!quiet && is_root_rank()) std::cerr << "iga-run: " << msg << std::endl;
  };
}

/// Checked before the study, not after it, and reported where the location came from.
void check_output(const std::string& directory, const std::string& output, const ConfigNode* root,
                  const std::vector<std::string>& config_paths) {
  std::string place = "the default output directory";
  if (!output.empty()) {
    place = "--output";
  } else if (const auto out = root ? root->find("output") : std::nullopt) {
    if (const auto dir = out->find("directory")) place = dir->where();
  }
  if (output.empty() && place != "the default output directory") check_config_output_directory(directory, place);
  check_output_directory(directory, place, config_paths);
}

/// A geometry study (a `study` section): the surface itself, no PDE.
int run_geometry_config(const ConfigNode& root, const std::string& config_path, const std::string& output, int levels,
                        const ProgressSink& progress) {
  const GeometryStudySettings settings = parse_geometry_study(root, config_path, levels, output);
  check_output(settings.output_dir, output, &root, {config_path});
  StagedDirectory staged(settings.output_dir);
  const std::vector<GeometryLevel> rows = run_geometry_study_with_files(settings, staged.path(), progress);
  staged.commit();
  std::cout << "geometry study — " << config_path << '\n'
            << format_geometry_table(rows) << "errors against the sphere: radial and normal (max), area and volume "
            << "(relative)\nresults: " << settings.output_dir << '\n';
  return 0;
}

/// "<space> p=<degree> <pde> — <config name>".
std::string plot_title(const StudySettings& settings, const StudyResult& result) {
  const std::string degree = settings.space_label.substr(settings.space_label.rfind("-p") + 2);
  return result.space_type + " p=" + degree + " " + to_string(settings.problem.pde) + " — " +
         std::filesystem::path(settings.root.file()).stem().string();
}

/// One study with all its files in `directory` (which exists), its table printed to stdout.
StudyResult run_into(const StudySettings& settings, const std::string& config_path, const std::string& directory,
                     const ProgressSink& progress, Clock::time_point t_start) {
  const std::filesystem::path dir(directory);
  shared_output_directory(directory);  // under mpirun every rank writes its VTK piece there
  StudyResult result = run_study_with_vtk(settings, directory, progress);
  progress("writing tables and plot");
  write_convergence_csv(result.rows, (dir / "convergence.csv").string(), result.adaptive,
                        functional_names(settings));
  const std::vector<EigenRow> eigen =
      settings.problem.eigen ? eigen_rows(result.eigen, settings.problem.eigen->exact) : std::vector<EigenRow>{};
  // Eigenvalue errors fall like twice the energy-norm order (docs/eigen.md).
  const int eigen_rate = 2 * (settings.problem.pde == Pde::biharmonic ? result.expected.h2 : result.expected.h1);
  if (settings.problem.eigen) {
    write_eigenvalues_csv(eigen, (dir / "eigenvalues.csv").string());
    if (settings.write_plot)
      plot_eigen_errors(eigen, eigen_rate, plot_title(settings, result), (dir / "eigenvalues.svg").string());
    write_spectrum_files(*settings.problem.eigen, result.eigen, dir.string(), plot_title(settings, result),
                         settings.write_plot);
  }
  if (settings.write_plot && !settings.problem.eigen) plot_convergence(result.rows, result.expected, plot_title(settings, result),
                                            (dir / "convergence.svg").string(), result.adaptive);
  result.total_seconds = std::chrono::duration<double>(Clock::now() - t_start).count();
  result.ranks = mpi_size();
  result.threads = omp_get_max_threads();
  write_summary_json(settings, result, (dir / "summary.json").string());

  if (settings.problem.eigen) {
    std::cout << result.space_type << " / " << to_string(settings.problem.pde) << " eigenvalues — " << config_path
              << '\n'
              << format_eigen_table(eigen);
    if (!settings.problem.eigen->exact.empty())
      std::cout << "expected rate for smooth eigenfunctions: twice the energy-norm order, h^" << eigen_rate << '\n';
    return result;
  }
  std::cout << result.space_type << " / " << to_string(settings.problem.pde) << " — " << config_path << '\n'
            << format_convergence_table(result.rows, result.adaptive, functional_names(settings));
  if (!has_errors(result.rows)) {
    // Nothing to compare with: no claim about rates (the functionals and differences show convergence).
  } else if (result.adaptive) {  // optimal order k in h is k/2 in the number of DOFs N (2D)
    std::cout << "optimal rates against N: L2 " << result.expected.l2 / 2.0 << ", H1 " << result.expected.h1 / 2.0
              << ", H2 " << result.expected.h2 / 2.0 << "   (H1, H2 are seminorms)\n";
  } else {
    std::cout << "expected rates: L2 " << result.expected.l2 << ", H1 " << result.expected.h1 << ", H2 "
              << result.expected.h2 << "   (H1, H2 are seminorms)\n";
  }
  return result;
}

/// Every study of every config (a config's `spaces:` list gives several), validated before any runs.
std::vector<std::pair<std::string, StudySettings>> parse_all(const std::vector<std::string>& paths,
                                                             const std::string& output, int levels) {
  std::vector<std::pair<std::string, StudySettings>> studies;
  for (const std::string& path : paths) {
    const ConfigNode root = ConfigNode::load_file(path);
    for (StudySettings& s : parse_studies(root, path, levels, output)) studies.emplace_back(path, std::move(s));
  }
  return studies;
}

int run_configs(const std::vector<std::string>& paths, const std::string& output, int levels, bool quiet) {
  const auto t_start = Clock::now();
  std::optional<ConfigNode> geometry;  // a geometry study runs alone
  std::string geometry_path;
  std::vector<std::pair<std::string, StudySettings>> studies;
  on_every_rank([&] {  // under mpirun: every rank leaves together on bad input
    for (const std::string& path : paths) {
      ConfigNode root = ConfigNode::load_file(path);
      if (!is_geometry_study(root)) continue;
      if (paths.size() > 1)
        throw InputError(path + ": a geometry study (study: {type: geometry}) runs alone, not in a comparison");
      geometry.emplace(std::move(root));
      geometry_path = path;
      return;
    }
    studies = parse_all(paths, output, levels);
  });
  const ProgressSink progress = progress_sink(quiet);
  if (geometry) return is_root_rank() ? run_geometry_config(*geometry, geometry_path, output, levels, progress) : 0;

  // One study goes where its config says; a comparison (one config's spaces:) too, several
  // configs to results/comparison. Checked before the study, not after it; under mpirun only
  // rank 0 writes and the other ranks hear of its error (solver/petsc_session.hpp).
  const bool single = studies.size() == 1;
  const std::string directory = single || !output.empty() || paths.size() == 1 ? studies.front().second.output_dir
                                                                               : "results/comparison";
  on_every_rank([&] {
    if (is_root_rank()) check_output(directory, output, paths.size() == 1 ? &studies.front().second.root : nullptr, paths);
  });
  if (!is_root_rank()) {  // takes part in the distributed solves, writes only its VTK pieces
    for (const auto& study : studies) run_study_with_vtk(study.second, shared_output_directory(""), progress);
    return 0;
  }
  if (single) {
    const StudySettings& settings = studies.front().second;
    StagedDirectory staged(settings.output_dir);
    run_into(settings, paths.front(), staged.path(), progress, t_start);
    staged.commit();
    std::cout << "results: " << settings.output_dir << '\n';
    return 0;
  }

  // A comparison: each study in a subfolder named after its space, then the combined report.
  StagedDirectory staged(directory);
  std::vector<ComparedStudy> compared;
  for (const auto& [path, settings] : studies) {
    std::string label = settings.space_label;
    for (int n = 2; std::any_of(compared.begin(), compared.end(), [&](const ComparedStudy& c) { return c.label == label; });
         ++n)
      label = settings.space_label + "-" + std::to_string(n);
    const std::filesystem::path sub = std::filesystem::path(staged.path()) / label;
    std::filesystem::create_directories(sub);
    progress("comparison: " + label);
    compared.push_back({label, run_into(settings, path, sub.string(), progress, Clock::now())});
    std::cout << '\n';
  }
  const std::filesystem::path dir(staged.path());
  write_comparison_csv(compared, (dir / "comparison.csv").string());
  std::string table;
  if (const auto& eigen = studies.front().second.problem.eigen) {
    // Eigenproblems: the largest relative eigenvalue error of each level against DOFs, per space.
    std::vector<std::pair<std::string, std::vector<EigenRow>>> spaces;
    for (const ComparedStudy& c : compared) spaces.emplace_back(c.label, eigen_rows(c.result.eigen, eigen->exact));
    const std::string name = std::filesystem::path(paths.front()).stem().string();
    plot_eigen_comparison(spaces, "eigenvalues — " + name, (dir / "comparison.svg").string());
    table = format_eigen_comparison(spaces);
    std::ofstream(dir / "comparison.txt") << table;
    // eigen.spectrum: the spaces' normalized spectra in one figure (each space's finest whole one).
    std::vector<SpectrumCurve> spectra;
    for (const ComparedStudy& c : compared)
      if (auto curve = finest_normalized_spectrum(*eigen, c.result.eigen, c.label)) spectra.push_back(std::move(*curve));
    if (!spectra.empty())
      plot_normalized_spectrum(spectra, "normalized spectra — " + name, (dir / "spectrum_comparison.svg").string());
  } else if (const auto norm = compared_norm(compared)) {
    const std::string name = std::filesystem::path(paths.front()).stem().string();
    plot_comparison(compared, *norm, to_string(studies.front().second.problem.pde) + " — " + name,
                    (dir / "comparison.svg").string());
    table = format_reach_table(compared, *norm);
    std::ofstream(dir / "comparison.txt") << table;
  }
  staged.commit();
  std::cout << table << "results: " << directory << " (one subfolder per space)\n";
  (void)t_start;
  return 0;
}

/// A whole number from the command line, or InputError naming the option.
int parse_count(const std::string& option, const std::string& text, int lo, int hi) {
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec == std::errc::invalid_argument || ptr != end)
    throw InputError(option + ": '" + text + "' is not a number");
  if (ec == std::errc::result_out_of_range || value < lo || value > hi)
    throw InputError(option + ": must be between " + std::to_string(lo) + " and " + std::to_string(hi) + " (got " +
                     text + ")");
  return value;
}

/// `iga-run check`: parse and validate every section (building the coarsest space) without solving.
int check_configs(const std::vector<std::string>& configs) {
  for (const std::string& path : configs) {
    const ConfigNode root = ConfigNode::load_file(path);
    if (is_geometry_study(root)) {
      const GeometryStudySettings settings = parse_geometry_study(root, path, 0, "");
      std::cout << path << ": ok (geometry study, " << settings.levels << " levels)\n";
      continue;
    }
    const std::vector<StudySettings> studies = parse_studies(root, path, 0, "");
    std::string spaces;
    for (const StudySettings& s : studies) spaces += (spaces.empty() ? "" : ", ") + s.space_label;
    std::cout << path << ": ok (" << spaces << "; " << to_string(studies.front().problem.pde) << ", "
              << studies.front().levels << (studies.front().levels == 1 ? " level" : " levels") << ")\n";
  }
  return 0;
}

/// Run the command; exceptions become messages and exit codes.
int guarded(const std::string& what, const std::function<int()>& body) {
  try {
    return body();
  } catch (const InputError& e) {
    return fail(2, e.what());
  } catch (const NumericalError& e) {
    return fail(1, std::string("numerical failure: ") + e.what());
  } catch (const std::bad_alloc&) {
    // The limits: section stops estimated sizes before allocation; what still runs out of memory
    // is a problem too large for this machine, i.e. an input problem.
    return fail(2, what + ": out of memory: the problem is too large for this machine (lower refinement.levels, "
                          "the mesh size or the limits: section)");
  } catch (const std::exception& e) {
    return fail(1, e.what());
  }
}

}  // namespace

namespace {
/// Threads of each process: --threads, else OMP_NUM_THREADS (OpenMP reads it), else under mpirun
/// the node's cores shared among the ranks on it — OpenMP's and OpenBLAS's default of one thread per
/// core in every rank would run ranks × cores threads on the cores.
void set_threads(const std::string& threads_text) {
  const int ranks_here = ranks_on_this_node();  // collective: every rank asks, whatever it decides
  int threads = 0;
  if (!threads_text.empty()) {
    threads = parse_count("--threads", threads_text, 1, 1024);
  } else if (ranks_here > 1 && !std::getenv("OMP_NUM_THREADS")) {
    const int cores = static_cast<int>(std::thread::hardware_concurrency());
    threads = std::max(1, std::min(omp_get_num_procs(), cores / ranks_here));  // omp_get_num_procs: this rank's binding
  }
  if (threads == 0) return;
  omp_set_num_threads(threads);
  if (ranks_here > 1) set_blas_threads(threads);
}
}  // namespace

int run_cli(int argc, char** argv) {
  CLI::App app{"iga-run: smooth spline spaces for Poisson and biharmonic problems, with convergence studies.\n"
               "  iga-run CONFIG.yaml              run a study (results/<config name>/ by default)\n"
               "  iga-run A.yaml B.yaml ...        run each and compare them (comparison.csv, comparison.svg)\n"
               "  iga-run check CONFIG.yaml ...    validate only (exit 0: valid, 2: not)\n"
               "  iga-run new SPACE [DOMAIN]       print a commented starting config (> my.yaml)\n"
               "  iga-run --list                   space types, domain types and built-in meshes"};
  std::vector<std::string> configs, check_list;
  std::string output, levels_text, threads_text;
  bool quiet = false, list = false;
  app.add_option("config", configs, "YAML config file(s) (see README); several: one comparison");
  app.add_option("-o,--output", output, "output directory (default: output.directory, else results/<config name>)")
      ->check([](const std::string& value) { return value.empty() ? std::string("must not be empty") : std::string(); });
  app.add_option("-l,--levels", levels_text, "number of refinement levels, 1..12 (overrides refinement.levels)");
  app.add_option("-t,--threads", threads_text, "number of threads (default: OpenMP's, e.g. OMP_NUM_THREADS)");
  app.add_flag("-q,--quiet", quiet, "no progress messages or progress bar on stderr");
  app.add_flag("--list", list, "list space types, domain types and built-in meshes, then exit");
  app.set_version_flag("--version", std::string("iga-run ") + IGA_RUN_VERSION);
  CLI::App* check = app.add_subcommand("check", "validate config file(s) without solving: exit 0 if valid, 2 if not");
  check->add_option("config", check_list, "YAML config file(s)")->required();
  std::string new_space, new_domain;
  CLI::App* starter = app.add_subcommand("new", "print a commented starting config that runs as it is (the "
                                                "starting configs of docs/configuration.md)");
  starter->add_option("space", new_space, "space type (iga-run --list)")->required();
  starter->add_option("domain", new_domain, "domain type (default: the space's first)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    std::cerr << "iga-run: error: " << e.what() << "\nRun with --help for more information.\n";
    return 2;
  }
  if (list) {
    std::cout << catalogue_text();
    return 0;
  }
  if (starter->parsed()) return guarded("new", [&] {
    std::cout << starter_config_text(new_space, new_domain);
    return 0;
  });
  if (check->parsed()) return guarded(check_list.front(), [&] { return check_configs(check_list); });
  if (configs.empty()) return fail(2, "a config file is required (iga-run CONFIG.yaml; see --help)");
  return guarded(configs.front(), [&] {
    const int levels = levels_text.empty() ? 0 : parse_count("--levels", levels_text, 1, 12);
    set_threads(threads_text);
    if (!quiet) set_progress_listener(terminal_progress_bar());
    return run_configs(configs, output, levels, quiet);
  });
}

}  // namespace iga
