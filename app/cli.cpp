#include "app/cli.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <new>
#include <optional>

#include "output/convergence_plot.hpp"
#include "config/errors.hpp"
#include "output/report.hpp"
#include "output/staged_directory.hpp"
#include "output/study_outputs.hpp"
#include "solver/petsc_session.hpp"
#include "solver/study.hpp"

namespace iga {

namespace {

int fail(int code, const std::string& message) {
  // Under mpirun an error all ranks share is printed once; one rank's own error ends every rank.
  if (is_root_rank() || !failure_shared_by_all_ranks()) std::cerr << "iga-run: error: " << message << '\n';
  return end_ranks_after_failure(code);
}

int run_config(const std::string& config_path, const std::string& output, int levels, bool quiet) {
  std::optional<ConfigNode> root_node;
  std::optional<StudySettings> parsed;
  on_every_rank([&] {  // under mpirun: every rank leaves together on bad input
    root_node.emplace(ConfigNode::load_file(config_path));
    parsed.emplace(parse_study(*root_node, config_path, levels, output));
  });
  const ConfigNode& root = *root_node;
  const StudySettings& settings = *parsed;
  const ProgressSink progress = [quiet](const std::string& msg) {
    if (!quiet && is_root_rank()) std::cerr << "iga-run: " << msg << std::endl;
  };

  // Checked before the study, not after it, and reported where the location came from. Under
  // mpirun only rank 0 writes; the other ranks hear of its error (solver/petsc_session.hpp).
  on_every_rank([&] {
    if (!is_root_rank()) return;
    try {
      check_output_location(settings.output_dir);
    } catch (const InputError& e) {
      std::string place = "the default output directory";
      if (!output.empty()) {
        place = "--output";
      } else if (const auto out = root.find("output")) {
        if (const auto dir = out->find("directory")) place = dir->where();
      }
      throw InputError(place + ": " + e.what());
    }
  });
  if (!is_root_rank()) {  // takes part in the distributed solves, writes nothing
    run_study(settings, progress);
    return 0;
  }
  StagedDirectory staged(settings.output_dir);
  const std::filesystem::path dir(staged.path());
  const StudyResult result = run_study_with_vtk(settings, staged.path(), progress);
  progress("writing tables and plot");
  write_convergence_csv(result.rows, (dir / "convergence.csv").string());
  write_summary_json(settings, result, (dir / "summary.json").string());
  if (settings.write_plot) {
    const std::string title = result.space_type + " " + to_string(settings.problem.pde);
    plot_convergence(result.rows, result.expected, title, (dir / "convergence.svg").string());
  }
  staged.commit();

  std::cout << result.space_type << " / " << to_string(settings.problem.pde) << " — " << config_path << '\n'
            << format_convergence_table(result.rows, result.adaptive);
  if (result.adaptive)  // optimal order k in h is k/2 in the number of DOFs N (2D)
    std::cout << "optimal rates against N: L2 " << result.expected.l2 / 2.0 << ", H1 " << result.expected.h1 / 2.0
              << ", H2 " << result.expected.h2 / 2.0;
  else
    std::cout << "expected rates: L2 " << result.expected.l2 << ", H1 " << result.expected.h1 << ", H2 "
              << result.expected.h2;
  std::cout << "   (H1, H2 are seminorms)\nresults: " << settings.output_dir << '\n';
  return 0;
}

}  // namespace

int run_cli(int argc, char** argv) {
  CLI::App app{"iga-run: smooth spline spaces for Poisson and biharmonic problems, with convergence studies"};
  std::string config, output;
  int levels = 0;
  bool quiet = false;
  app.add_option("config", config, "YAML config file (see README)")->required();
  app.add_option("-o,--output", output, "output directory (default: output.directory, else results/<config name>)")
      ->check([](const std::string& value) { return value.empty() ? std::string("must not be empty") : std::string(); });
  app.add_option("-l,--levels", levels, "number of refinement levels (overrides refinement.levels)")
      ->check(CLI::Range(1, 12));
  app.add_flag("-q,--quiet", quiet, "no progress messages on stderr");
  app.set_version_flag("--version", std::string("iga-run ") + IGA_RUN_VERSION);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  try {
    return run_config(config, output, levels, quiet);
  } catch (const InputError& e) {
    return fail(2, e.what());
  } catch (const NumericalError& e) {
    return fail(1, std::string("numerical failure: ") + e.what());
  } catch (const std::bad_alloc&) {
    // The limits: section stops estimated sizes before allocation; what still runs out of memory
    // is a problem too large for this machine, i.e. an input problem.
    return fail(2, config + ": out of memory: the problem is too large for this machine (lower refinement.levels, "
                            "the mesh size or the limits: section)");
  } catch (const std::exception& e) {
    return fail(1, e.what());
  }
}

}  // namespace iga
