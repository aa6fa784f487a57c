// The iga-run program as a user runs it: every shipped config, its outputs read back with VTK's
// reader, and bad input ending in exit code 2 with a message and no output directory.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkCellData.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <vector>

#include "config/config_node.hpp"
#include "solver/linear_solver.hpp"
#include "tests/support/documentation_pages.hpp"
#include "tests/support/run_iga.hpp"
#include "tests/support/scratch_files.hpp"

namespace fs = std::filesystem;

namespace {

using iga::test::RunResult;
using iga::test::run_iga;
using iga::test::run_iga_in;
using iga::test::slurp;
using iga::test::write_config;

fs::path scratch_dir() { return iga::test::scratch_folder(); }  // removed when the program ends

const char* const kGood = iga::test::kSmallPoissonConfig;

/// `text` with the first `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return pos == std::string::npos ? text : text.replace(pos, from.size(), to);
}

/// The good config with one part replaced, for bad-input cases.
std::string with_replaced(const std::string& from, const std::string& to) { return replaced(kGood, from, to); }

/// Whether README.md or a Markdown page under docs/ mentions `word`.
bool documented(const std::string& word) {
  const std::vector<fs::path> pages = iga::test::documentation_pages();
  return std::any_of(pages.begin(), pages.end(),
                     [&](const fs::path& page) { return slurp(page).find(word) != std::string::npos; });
}

}  // namespace

/// Every configs/*.yaml, listed when the test program starts, so that each shipped config is its
/// own test case (ctest runs them in parallel; a failure names the config).
std::vector<std::string> shipped_configs() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(fs::path(IGA_SOURCE_DIR) / "configs"))
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

/// The files of an eigen study (problem.eigen) in `out`, run with --levels 2: eigenvalues.csv with
/// its rows and references, the eigenvalues in summary.json, one field per mode in the VTK files.
void check_eigen_study(const fs::path& out, const std::string& name) {
  const nlohmann::json summary = nlohmann::json::parse(slurp(out / "summary.json"));
  const int count = summary["problem"]["eigen"]["count"].get<int>();
  const std::string csv = slurp(out / "eigenvalues.csv");
  EXPECT_EQ(csv.rfind("level,h,dofs,index,eigenvalue,reference,relative_error,rate,rate_dofs\n", 0), 0u) << name;
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 2 * count) << name;
  ASSERT_EQ(summary["eigenvalues"].size(), 2u * count) << name;
  // Every shipped eigen config has a reference for λ₁, met to 5% on its level 1 (the L-shape's
  // singular λ₁: 4.5e-2; the smooth cases: below 1e-3).
  EXPECT_LT(summary["eigenvalues"][count]["relative_error"].get<double>(), 0.05) << name;
  EXPECT_GT(fs::file_size(out / "eigenvalues.svg"), 1000u) << name;
  if (summary["problem"]["eigen"].value("spectrum", false)) {  // every eigenvalue of both levels
    const std::string spectrum = slurp(out / "spectrum.csv");
    EXPECT_EQ(spectrum.rfind("level,n,N,eigenvalue,reference,ratio\n", 0), 0u) << name;
    EXPECT_EQ(std::count(spectrum.begin(), spectrum.end(), '\n'),
              1 + summary["levels"][0]["free_dofs"].get<int>() + summary["levels"][1]["free_dofs"].get<int>());
    EXPECT_GT(fs::file_size(out / "spectrum.svg"), 1000u) << name;
  }
  if (!fs::exists(out / "solution_1.vtu")) return;  // output.vtk: false
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName((out / "solution_1.vtu").c_str());
  reader->Update();
  vtkPointData* pd = reader->GetOutput()->GetPointData();
  for (int j = 1; j <= count; ++j) EXPECT_NE(pd->GetArray(("mode_" + std::to_string(j)).c_str()), nullptr) << j;
  EXPECT_NE(pd->GetArray("u"), nullptr);
}

/// The files of one study in `out`, run with --levels 2.
void check_study(const fs::path& out, const std::string& name) {
  if (fs::exists(out / "eigenvalues.csv")) return check_eigen_study(out, name);
  const std::string csv = slurp(out / "convergence.csv");
  EXPECT_EQ(csv.rfind("level,h,dofs,l2,h1,h2,rate_l2,rate_h1,rate_h2,t_assemble,t_solve", 0), 0u) << name;
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3) << name;  // header + 2 levels

  const nlohmann::json summary = nlohmann::json::parse(slurp(out / "summary.json"));
  EXPECT_EQ(summary["levels"].size(), 2u);
  EXPECT_TRUE(summary.contains("config"));
  EXPECT_TRUE(summary["space"].contains("type"));
  for (const auto& level : summary["levels"]) {  // the solver's iterative-refinement corrections
    const int steps = level["refinement_steps"].get<int>();
    const std::string solver = level["solver"].get<std::string>();
    if (solver.rfind("petsc", 0) == 0) {
      // PETSc refines in extended precision only where the space asks for it, and says so.
      static const std::regex count(", ([0-9]+) refinement steps");
      std::smatch m;
      EXPECT_EQ(steps, std::regex_search(solver, m, count) ? std::stoi(m[1]) : 0) << name << ": " << solver;
    } else {
      // The first correction of a nonzero solution is always smaller than the solution itself,
      // so a direct solve applies 1 .. max_refinement_steps of them (solver/linear_solver.cpp).
      EXPECT_GE(steps, 1) << name << ": " << solver;
    }
    EXPECT_LE(steps, iga::max_refinement_steps) << name;
  }

  if (summary.contains("surface")) {  // a PDE on a smooth surface: its files and report
    EXPECT_GT(fs::file_size(out / "surface.vtu"), 100u) << name;
    EXPECT_GT(fs::file_size(out / "surface_patches.txt"), 100u) << name;
    for (const char* key : {"patch_degree", "max_g1_residual", "max_fold_alpha", "min_regularity", "interpolation_residual"})
      EXPECT_TRUE(summary["surface"][key].is_number()) << name << ": " << key;
  }
  EXPECT_TRUE(fs::exists(out / "solution.pvd"));
  EXPECT_TRUE(fs::exists(out / "mesh.pvd"));
  EXPECT_GT(fs::file_size(out / "convergence.svg"), 1000u);
  const bool biharmonic = summary["problem"]["pde"] == "biharmonic";
  // problem.form is echoed as a config spells it: laplacian or hessian, and only for plates.
  if (biharmonic)
    EXPECT_TRUE(summary["problem"]["form"] == "laplacian" || summary["problem"]["form"] == "hessian") << name;
  else
    EXPECT_FALSE(summary["problem"].contains("form")) << name;
  for (int level = 0; level < 2; ++level) {
    // output.vtk.levels: last writes the last level only.
    if (level == 0 && !fs::exists(out / "solution_0.vtu")) continue;
    auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    reader->SetFileName((out / ("solution_" + std::to_string(level) + ".vtu")).c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    ASSERT_GT(grid->GetNumberOfPoints(), 0) << name;
    ASSERT_GT(grid->GetNumberOfCells(), 0) << name;
    vtkPointData* pd = grid->GetPointData();
    // Errors, the exact solution and the error fields where the study has an exact solution (the
    // Scordelis–Lo roof has a reference value instead: a functional).
    const bool exact = summary["levels"][0]["l2"].is_number();
    for (const char* field : {"u", "grad_u"}) EXPECT_NE(pd->GetArray(field), nullptr) << field;
    if (exact)
      for (const char* field : {"u_exact", "error"}) EXPECT_NE(pd->GetArray(field), nullptr) << field;
    EXPECT_EQ(pd->GetArray("grad_u")->GetNumberOfComponents(), 3);
    // The mesh outline: one closed poly-line per element of the solution file.
    auto mesh_reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    mesh_reader->SetFileName((out / ("mesh_" + std::to_string(level) + ".vtu")).c_str());
    mesh_reader->Update();
    vtkUnstructuredGrid* mesh = mesh_reader->GetOutput();
    ASSERT_GT(mesh->GetNumberOfCells(), 0) << name;
    EXPECT_EQ(mesh->GetCellType(0), VTK_POLY_LINE);
    EXPECT_EQ(mesh->GetNumberOfCells(), summary["levels"][level]["elements"].get<int>()) << name;
    if (biharmonic) EXPECT_NE(pd->GetArray("laplace_u"), nullptr);
    if (summary["problem"]["pde"] == "kirchhoff_love_shell") {  // the displacement, for Warp By Vector
      ASSERT_NE(pd->GetArray("displacement"), nullptr) << name;
      EXPECT_EQ(pd->GetArray("displacement")->GetNumberOfComponents(), 3) << name;
    }
    // Per-element errors, and for adaptive runs the indicator and the marked elements (of every
    // level but possibly the last, where refinement may have stopped).
    if (exact) EXPECT_NE(grid->GetCellData()->GetArray("error_l2"), nullptr) << name;
    if (summary["refinement"] == "adaptive" && level == 0) {
      EXPECT_NE(grid->GetCellData()->GetArray("estimator"), nullptr) << name;
      EXPECT_NE(grid->GetCellData()->GetArray("marked"), nullptr) << name;
    }
    if (!exact) continue;
    // The error field is small against the solution (the exact solutions are resolved).
    double range_u[2], range_e[2];
    pd->GetArray("u_exact")->GetRange(range_u);
    pd->GetArray("error")->GetRange(range_e);
    const double scale = std::max(std::abs(range_u[0]), std::abs(range_u[1]));
    EXPECT_LT(std::max(std::abs(range_e[0]), std::abs(range_e[1])), 0.2 * scale) << name;
  }
}

class ShippedConfig : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedConfig, RunsAndWritesReadableOutput) {
  const std::string name = GetParam();
  const fs::path config = fs::path(IGA_SOURCE_DIR) / "configs" / (name + ".yaml");
  const fs::path out = scratch_dir() / ("out-" + name);
  // A shipped config is a documented one: README.md or a page under docs/ names it.
  EXPECT_TRUE(documented(name + ".yaml")) << name << ".yaml is named neither in README.md nor in docs/";
  const RunResult r = run_iga(config.string() + " --levels 2 --quiet --output " + out.string());
  ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
  EXPECT_TRUE(r.err.empty()) << "--quiet still printed: " << r.err;
  EXPECT_NE(r.out.find("level"), std::string::npos);

  if (fs::exists(out / "geometry.csv")) {  // a geometry study: the surface itself, no PDE
    const nlohmann::json summary = nlohmann::json::parse(slurp(out / "summary.json"));
    EXPECT_EQ(summary["study"], "geometry");
    ASSERT_EQ(summary["levels"].size(), 2u);
    // Surface files (the .vtu and the Bernstein control points) up to study.surface_files_up_to_level.
    const iga::ConfigNode study = iga::ConfigNode::load_file(config.string())["study"];
    const int files_up_to = study.has("surface_files_up_to_level") ? study["surface_files_up_to_level"].as_int() : 2;
    for (const auto& level : summary["levels"]) {
      EXPECT_LT(level["surface"]["max_g1_residual"].get<double>(), 1e-12) << name;
      EXPECT_EQ(level["files"].size(), level["level"].get<int>() <= files_up_to ? 2u : 0u) << name;
      for (const auto& file : level["files"]) EXPECT_GT(fs::file_size(out / file.get<std::string>()), 100u) << file;
    }
    EXPECT_NEAR(summary["levels"][1]["rate_radial"].get<double>(), 2.0, 0.7) << name;
    return;
  }

  if (fs::exists(out / "comparison.csv")) {  // spaces: one study per subfolder, and the comparison
    const std::string comparison = slurp(out / "comparison.csv");
    EXPECT_EQ(comparison.rfind("space,level,h,dofs,l2,h1,h2,t_solution,t_errors", 0), 0u);
    EXPECT_GT(fs::file_size(out / "comparison.svg"), 1000u);
    EXPECT_TRUE(fs::exists(out / "comparison.txt"));
    // Eigenproblems with whole spectra: the spaces' normalized spectra in one figure.
    const iga::ConfigNode problem = iga::ConfigNode::load_file(config.string())["problem"];
    if (problem.has("eigen") && problem["eigen"].has("spectrum") && problem["eigen"]["spectrum"].as_bool())
      EXPECT_GT(fs::file_size(out / "spectrum_comparison.svg"), 1000u) << name;
    int studies = 0;
    for (const auto& entry : fs::directory_iterator(out))
      if (entry.is_directory()) ++studies, check_study(entry.path(), name + "/" + entry.path().filename().string());
    // One study per entry of the config's `spaces:` list.
    EXPECT_EQ(studies, std::ssize(iga::ConfigNode::load_file(config.string())["spaces"].items())) << name;
    EXPECT_EQ(std::count(comparison.begin(), comparison.end(), '\n'), 1 + 2 * studies) << name;
    return;
  }
  check_study(out, name);
  // summary.json echoes the config as written: a shell's `fixed: [y, z]` stays two words (yaml-cpp,
  // as YAML 1.1, also reads y, n, yes, no, on, off as booleans).
  const nlohmann::json echoed = nlohmann::json::parse(slurp(out / "summary.json"))["config"];
  if (echoed.contains("problem") && echoed["problem"].contains("boundary") && echoed["problem"]["boundary"].is_object())
    for (const auto& [part, support] : echoed["problem"]["boundary"].items())
      if (support.is_object() && support.contains("fixed"))
        for (const auto& c : support["fixed"]) EXPECT_TRUE(c.is_string()) << name << ": " << part << " " << c;
  // Each level says where the shell's point loads were placed (one note per load).
  if (echoed.contains("problem") && echoed["problem"].contains("point_loads"))
    for (const auto& level : nlohmann::json::parse(slurp(out / "summary.json"))["levels"]) {
      ASSERT_TRUE(level.contains("notes")) << name;
      std::size_t placed = 0;
      for (const auto& note : level["notes"]) placed += note.get<std::string>().rfind("point load ", 0) == 0;
      EXPECT_EQ(placed, echoed["problem"]["point_loads"].size()) << name;
    }
}

// Test names may hold only letters, digits and underscores.
INSTANTIATE_TEST_SUITE_P(EndToEnd, ShippedConfig, ::testing::ValuesIn(shipped_configs()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(EndToEnd, GoodConfigWritesToConfiguredDirectory) {
  // A config's output.directory is relative to the working directory (and stays inside it).
  const fs::path out = scratch_dir() / "good-out";
  const fs::path cfg = write_config("good.yaml", std::string(kGood) + "output: {directory: good-out}\n");
  const RunResult r = run_iga_in(scratch_dir(), cfg.string() + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "convergence.csv"));
  // A second run replaces the results in place.
  ASSERT_EQ(run_iga_in(scratch_dir(), cfg.string() + " --quiet --levels 1").exit_code, 0);
  const std::string csv = slurp(out / "convergence.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 2);
}

struct BadCase {
  const char* name;
  std::string config;      // empty: use a missing file
  const char* message;     // must appear on stderr
};

class BadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadInput, ExitsWithCode2AndLeavesNoOutput) {
  const BadCase& c = GetParam();
  const fs::path out = scratch_dir() / (std::string("bad-") + c.name);
  const fs::path cfg = c.config.empty() ? scratch_dir() / "does-not-exist.yaml"
                                        : write_config(std::string(c.name) + ".yaml", c.config);
  const RunResult r = run_iga(cfg.string() + " --quiet --output " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(c.message), std::string::npos) << "stderr: " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
  EXPECT_FALSE(fs::exists(out));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadInput,
    ::testing::Values(
        BadCase{"typo_key", with_replaced("degree: 2", "degre: 2"), "did you mean 'degree'"},
        BadCase{"typo_top_level", with_replaced("refinement:", "refinment:"), "did you mean 'refinement'"},
        BadCase{"bad_expression", with_replaced("x*y + sin(x)", "x*y + sin(x"), "cannot parse"},
        BadCase{"unknown_symbol", with_replaced("x*y + sin(x)", "x*z"), "cannot parse"},
        BadCase{"not_finite_data", with_replaced("x*y + sin(x)", "sqrt(x - 2)"), "not finite"},
        BadCase{"folded_patch",
                with_replaced("{type: rectangle, min: [0, 0], max: [1, 1]}",
                              "{type: patch, degree: [1, 1], knots_u: [0, 0, 1, 1], knots_v: [0, 0, 1, 1], "
                              "control_points: [[0, 0], [1, 0], [1, 1], [0, 1]]}"),
                "folds over itself"},
        BadCase{"regularity_too_high", with_replaced("degree: 2", "degree: 2, regularity: 2"), "regularity"},
        BadCase{"unknown_space", with_replaced("type: bspline", "type: bsplin"), "bspline"},
        BadCase{"biharmonic_needs_c1",
                replaced(replaced(with_replaced("pde: poisson", "pde: biharmonic"), "{all: dirichlet}", "{all: clamped}"),
                         "degree: 2", "degree: 2, regularity: 0"),
                "needs a C1"},
        BadCase{"duplicate_boundary_part", with_replaced("{all: dirichlet}", "{left: dirichlet, left: neumann}"),
                "duplicate key 'left'"},
        BadCase{"degree_zero", with_replaced("degree: 2", "degree: 0"), "degree"},
        BadCase{"unknown_boundary_part", with_replaced("{all: dirichlet}", "{lft: dirichlet}"), "did you mean 'left'"},
        BadCase{"wrong_condition", with_replaced("{all: dirichlet}", "{all: clamped}"), "dirichlet"},
        BadCase{"yaml_syntax", with_replaced("pde: poisson", "pde: [poisson"), "yaml_syntax.yaml:"},
        BadCase{"missing_file", "", "does-not-exist.yaml"},
        BadCase{"function_without_arguments", with_replaced("x*y + sin(x)", "cos()"), "called with no arguments"},
        BadCase{"pole_on_a_mesh_line", with_replaced("x*y + sin(x)", "1/(x-0.5)"),
                "problem.exact: the exact solution is not finite at (0.5, 0)"},
        BadCase{"degree_over_the_limit", with_replaced("degree: 2", "degree: 100"), "limits.max_degree"},
        BadCase{"a_billion_elements", with_replaced("elements: [2, 2]", "elements: [40000, 40000]"),
                "space.elements: about 1.6e+09 elements exceed limits.max_elements"},
        BadCase{"levels_over_the_memory_limit", with_replaced("levels: 2", "levels: 9") + "limits: {max_memory_gb: 0.5}\n",
                "limits.max_memory_gb"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(EndToEnd, UnusableOutputLocationFailsBeforeTheStudy) {
  const fs::path file = scratch_dir() / "a-file";
  std::ofstream(file) << "x";
  const fs::path cfg = write_config("good2.yaml", kGood);
  const RunResult r = run_iga(cfg.string() + " --quiet --output " + (file / "sub").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("is not a directory"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << "no study output expected: " << r.out;
}

TEST(EndToEnd, OutputLocationThatCannotBeCreatedFailsBeforeTheStudy) {
  // /proc passes a permission test (as root) but refuses new entries: the probe finds out.
  const fs::path cfg = write_config("good3.yaml", kGood);
  const RunResult r = run_iga(cfg.string() + " --quiet --output /proc/iga-run-test-output");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("output directory '/proc/iga-run-test-output'"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << "no study output expected: " << r.out;
}

TEST(EndToEnd, ConfigThatIsNotARegularFileIsRefusedAtOnce) {
  const fs::path out = scratch_dir() / "dev-zero-out";
  const RunResult r = run_iga("/dev/zero --quiet --output " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("/dev/zero: not a regular file"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(EndToEnd, RepeatedRunsAreBitwiseIdentical) {
  // Separate processes, so address randomisation differs between them (it once changed the order
  // in which the source term was evaluated, and the last bits of every error). Same binary, same
  // machine, same thread count: the numbers and the written solution must agree bit for bit.
  const fs::path config = fs::path(IGA_SOURCE_DIR) / "configs" / "g1-biharmonic-gmsh-lshape.yaml";
  auto levels_of = [](const fs::path& dir) {
    nlohmann::json levels = nlohmann::json::parse(slurp(dir / "summary.json"))["levels"];
    for (auto& level : levels) level.erase("timings");
    return levels;
  };
  const fs::path first = scratch_dir() / "repeat-0";
  ASSERT_EQ(run_iga(config.string() + " --levels 2 --quiet --output " + first.string()).exit_code, 0);
  const nlohmann::json reference = levels_of(first);
  ASSERT_EQ(reference.size(), 2u);
  for (int run = 1; run < 4; ++run) {
    const fs::path dir = scratch_dir() / ("repeat-" + std::to_string(run));
    ASSERT_EQ(run_iga(config.string() + " --levels 2 --quiet --output " + dir.string()).exit_code, 0);
    EXPECT_EQ(levels_of(dir), reference) << "run " << run;  // doubles compared exactly
    for (const char* file : {"solution_0.vtu", "solution_1.vtu"})
      EXPECT_EQ(slurp(dir / file), slurp(first / file)) << file << ", run " << run;
  }
}

TEST(EndToEnd, VersionHelpAndUsage) {
  RunResult r = run_iga("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("iga-run"), std::string::npos);
  EXPECT_EQ(run_iga("--help").exit_code, 0);
  EXPECT_EQ(run_iga("").exit_code, 2);
  EXPECT_EQ(run_iga("a.yaml --levels abc").exit_code, 2);
}
