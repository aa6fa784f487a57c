// The bad-input catalogue: every case of tests/app/bad_inputs/*.yaml runs the iga-run program on
// hostile or broken input (configs, expressions, mesh files, Gmsh scripts, command lines) and checks
// what a user relies on: the process ends by itself (no signal, no hang), with the expected exit
// code, a message naming the place (file and line, key path or option), no output directory and no
// staging left behind, and no effect of a malicious script (marker files stay absent).
// tests/app/bad_inputs/README.md describes the case format.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <chrono>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <thread>
#include <vector>

#include "solver/petsc_settings.hpp"
#include "solver/petsc_settings.hpp"
#include "tests/support/scratch_files.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kCatalogue = fs::path(IGA_SOURCE_DIR) / "tests/app/bad_inputs";

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;  // iga-run is instrumented too: slower, and ASan reserves huge address space
#else
constexpr bool kSanitized = false;
#endif

/// Seconds a case may run before it counts as a hang, unless the case gives its own `timeout`;
/// sanitized Debug code runs far slower.
constexpr int kTimeoutSeconds = 60;
constexpr int kSlowdown = kSanitized ? 5 : 1;
/// Address space of the program under test: a run that would allocate without bound fails here
/// (bad_alloc) instead of taking the machine's memory.
constexpr rlim_t kAddressSpaceBytes = rlim_t{4} << 30;

/// One input file of a case: its text, assembled from parts (repeated text, raw bytes) or copied.
std::string file_content(const YAML::Node& spec) {
  if (spec.IsScalar()) return spec.as<std::string>();
  if (spec["from"]) {
    std::ifstream in(kCatalogue / spec["from"].as<std::string>(), std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::string out;
  for (const auto& part : spec["parts"]) {
    if (part["hex"]) {  // raw bytes, e.g. invalid UTF-8 that YAML text cannot carry
      std::istringstream hex(part["hex"].as<std::string>());
      for (std::string byte; hex >> byte;) out += static_cast<char>(std::stoi(byte, nullptr, 16));
      continue;
    }
    const std::string text = part["text"].as<std::string>();
    const long times = part["times"] ? part["times"].as<long>() : 1;
    for (long i = 0; i < times; ++i) out += text;
  }
  return out;
}

struct Case {
  std::string group, name, what;
  std::map<std::string, std::string> files;  ///< file name (relative to the case folder) -> content
  std::map<std::string, std::string> links;  ///< symbolic link (relative to the case folder) -> its target
  std::vector<std::string> args;             ///< command line after the program name
  int exit_code = 2;
  int timeout_seconds = kTimeoutSeconds;
  bool needs_petsc = false;                  ///< skipped (and reported so) in a build without PETSc
  bool needs_slepc = false;                  ///< skipped in a build without SLEPc (eigenproblems under PETSc)
  bool needs_no_slepc = false;               ///< skipped in a build with SLEPc (its absence is the error)
  std::vector<std::string> stderr_patterns;  ///< ECMAScript regexes, each must match somewhere
  std::vector<std::string> stderr_absent;    ///< regexes that must match nowhere (leaked file contents)
  std::vector<std::string> absent;           ///< paths a malicious input tries to create
};

/// gtest prints a case by its name (also in the test list ctest reads), not as raw bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.group << "/" << c.name; }

std::vector<std::string> strings(const YAML::Node& list) {
  std::vector<std::string> out;
  if (list)
    for (const auto& item : list) out.push_back(item.as<std::string>());
  return out;
}

const std::set<std::string> kCaseKeys = {"name", "what", "config", "files", "args", "output_option",
                                         "exit", "stderr", "stderr_absent", "absent", "timeout", "requires"};

std::vector<Case> load_catalogue() {
  std::vector<Case> cases;
  std::set<std::string> names;
  std::vector<fs::path> manifests;
  for (const auto& entry : fs::directory_iterator(kCatalogue))
    if (entry.path().extension() == ".yaml") manifests.push_back(entry.path());
  std::sort(manifests.begin(), manifests.end());
  for (const auto& manifest : manifests) {
    const YAML::Node list = YAML::LoadFile(manifest.string());
    for (const auto& node : list) {
      Case c;
      c.group = manifest.stem().string();
      c.name = node["name"].as<std::string>();
      for (const auto& kv : node)  // a misspelt key would silently drop a check
        if (!kCaseKeys.count(kv.first.as<std::string>()))
          throw std::runtime_error(manifest.string() + ": case " + c.name + ": unknown key " + kv.first.as<std::string>());
      if (!names.insert(c.group + "_" + c.name).second)
        throw std::runtime_error(manifest.string() + ": case name repeated: " + c.name);
      c.what = node["what"] ? node["what"].as<std::string>() : "";
      if (node["config"]) c.files["case.yaml"] = file_content(node["config"]);
      if (node["files"])
        for (const auto& kv : node["files"]) {
          if (kv.second.IsMap() && kv.second["link"])  // a symbolic link beside the config
            c.links[kv.first.as<std::string>()] = kv.second["link"].as<std::string>();
          else
            c.files[kv.first.as<std::string>()] = file_content(kv.second);
        }
      c.args = {"--quiet"};  // first, so that no option of the case can take it as its value
      const auto args = node["args"] ? strings(node["args"]) : std::vector<std::string>{"case.yaml"};
      c.args.insert(c.args.end(), args.begin(), args.end());
      const bool output_option = !node["output_option"] || node["output_option"].as<bool>();
      if (output_option && std::find(c.args.begin(), c.args.end(), "--output") == c.args.end() &&
          std::find(c.args.begin(), c.args.end(), "-o") == c.args.end()) {
        c.args.push_back("--output");
        c.args.push_back("{out}");
      }
      if (node["exit"]) c.exit_code = node["exit"].as<int>();
      if (node["timeout"]) c.timeout_seconds = node["timeout"].as<int>();
      c.stderr_patterns = strings(node["stderr"]);
      c.stderr_absent = strings(node["stderr_absent"]);
      c.absent = strings(node["absent"]);
      for (const std::string& feature : strings(node["requires"])) {
        if (feature == "petsc") c.needs_petsc = true;
        else if (feature == "slepc") c.needs_slepc = true;
        else if (feature == "no_slepc") c.needs_no_slepc = true;
        else throw std::runtime_error(manifest.string() + ": case " + c.name + ": unknown requirement " + feature);
      }
      cases.push_back(std::move(c));
    }
  }
  return cases;
}

std::string substituted(std::string text, const std::map<std::string, std::string>& values) {
  for (const auto& [key, value] : values)
    for (auto pos = text.find(key); pos != std::string::npos; pos = text.find(key, pos + value.size()))
      text.replace(pos, key.size(), value);
  return text;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::set<std::string> entries_under(const fs::path& dir) {
  std::set<std::string> out;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec))
    out.insert(fs::relative(it->path(), dir).string());
  return out;
}

struct Outcome {
  bool timed_out = false;
  int status = 0;  ///< as from waitpid
  double seconds = 0;
};

/// Runs iga-run with `args` in `dir` (its own process group, so a helper process it starts is
/// stopped with it), stdout and stderr to files, TMPDIR set to `tmp`; kills the group after the
/// time limit.
Outcome run_program(const std::vector<std::string>& args, const fs::path& dir, const fs::path& out_file,
                    const fs::path& err_file, const fs::path& tmp, int timeout_seconds) {
  std::vector<std::string> argv_strings{IGA_RUN_BINARY};
  argv_strings.insert(argv_strings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& s : argv_strings) argv.push_back(s.data());
  argv.push_back(nullptr);
  // The environment, with TMPDIR pointing at the case's own folder (staging and helper files
  // land there, so whatever a failed run leaves behind is seen).
  // Under AddressSanitizer (no address-space limit) its allocator enforces the memory bound.
  std::vector<std::string> env_strings{"TMPDIR=" + tmp.string()};
  std::string asan_options = "ASAN_OPTIONS=";
  for (char** e = environ; *e; ++e) {
    const std::string var(*e);
    if (var.rfind("ASAN_OPTIONS=", 0) == 0)
      asan_options = var + ":";
    else if (var.rfind("TMPDIR=", 0) != 0)
      env_strings.push_back(var);
  }
  if (kSanitized) asan_options += "hard_rss_limit_mb=4096:max_allocation_size_mb=4096";
  env_strings.push_back(asan_options);
  std::vector<char*> envp;
  for (auto& s : env_strings) envp.push_back(s.data());
  envp.push_back(nullptr);

  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {  // child: only async-signal-safe calls until exec
    ::setpgid(0, 0);
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    const int out = ::open(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0) ::_exit(127);
    ::dup2(out, 1);
    ::dup2(err, 2);
    const int null = ::open("/dev/null", O_RDONLY);
    if (null >= 0) ::dup2(null, 0);
    const rlimit no_core{0, 0};
    ::setrlimit(RLIMIT_CORE, &no_core);
    const rlimit files{rlim_t{1} << 30, rlim_t{1} << 30};  // no case may write a gigabyte
    ::setrlimit(RLIMIT_FSIZE, &files);
    if (!kSanitized) {
      // The soft limit only: a helper process (the Gmsh worker) may set its own, larger limit.
      rlimit memory{};
      ::getrlimit(RLIMIT_AS, &memory);
      memory.rlim_cur = std::min(kAddressSpaceBytes, memory.rlim_max);
      ::setrlimit(RLIMIT_AS, &memory);
    }
    ::execve(argv[0], argv.data(), envp.data());
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // also here, so the group exists before any kill below
  Outcome outcome;
  const auto deadline = start + std::chrono::seconds(timeout_seconds);
  for (;;) {
    const pid_t done = ::waitpid(pid, &outcome.status, WNOHANG);
    if (done == pid) break;
    if (std::chrono::steady_clock::now() > deadline) {
      outcome.timed_out = true;
      ::kill(-pid, SIGKILL);
      ::waitpid(pid, &outcome.status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(-pid, SIGKILL);  // anything the program left running in its group
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

constexpr auto kRegexFlags = std::regex::ECMAScript | std::regex::icase;

class BadInput : public ::testing::TestWithParam<Case> {};

TEST_P(BadInput, Run) {
  const Case& c = GetParam();
  // Without PETSc, `solver.type: petsc` itself is the input error, before what the case is about.
  if (c.needs_petsc && !iga::petsc_available()) GTEST_SKIP() << "built without PETSc";
  if (c.needs_slepc && !iga::slepc_available()) GTEST_SKIP() << "built without SLEPc";
  if (c.needs_no_slepc && iga::slepc_available()) GTEST_SKIP() << "built with SLEPc (the case is its absence)";
  const fs::path root = iga::test::scratch_folder() / (c.group + "_" + c.name);
  const fs::path dir = root / "case", tmp = root / "tmp";
  fs::remove_all(root);
  fs::create_directories(dir);
  fs::create_directories(tmp);
  const std::map<std::string, std::string> values = {
      {"{dir}", dir.string()}, {"{out}", (dir / "case_out").string()}, {"{source}", IGA_SOURCE_DIR}};
  for (const auto& [name, content] : c.files) {
    fs::create_directories((dir / name).parent_path());
    std::ofstream(dir / name, std::ios::binary) << substituted(content, values);
  }
  for (const auto& [name, target] : c.links) {
    fs::create_directories((dir / name).parent_path());
    fs::create_symlink(substituted(target, values), dir / name);
  }
  std::vector<std::string> args;
  for (const auto& a : c.args) args.push_back(substituted(a, values));
  const std::set<std::string> before = entries_under(dir);

  const int timeout = c.timeout_seconds * kSlowdown;
  const Outcome run = run_program(args, dir, root / "stdout.txt", root / "stderr.txt", tmp, timeout);
  const std::string err = slurp(root / "stderr.txt");
  SCOPED_TRACE(c.group + "/" + c.name + (c.what.empty() ? "" : " (" + c.what + ")") + "\nstderr:\n" +
               err.substr(0, 4000) + "\nstdout:\n" + slurp(root / "stdout.txt").substr(0, 2000));
  std::printf("%s: %.2f s\n", c.name.c_str(), run.seconds);

  ASSERT_FALSE(run.timed_out) << "no end after " << timeout << " s";
  ASSERT_FALSE(WIFSIGNALED(run.status)) << "ended by signal " << WTERMSIG(run.status) << " ("
                                         << ::strsignal(WTERMSIG(run.status)) << ")";
  ASSERT_TRUE(WIFEXITED(run.status));
  EXPECT_EQ(WEXITSTATUS(run.status), c.exit_code) << "exit code";
  EXPECT_NE(err.find_first_not_of(" \n"), std::string::npos) << "no message on stderr";
  for (const auto& pattern : c.stderr_patterns)
    EXPECT_TRUE(std::regex_search(err, std::regex(substituted(pattern, values), kRegexFlags)))
        << "stderr does not name: " << pattern;
  // Under the 4 GB limit a memory bomb still ends as an input error ("out of memory", exit 2): it
  // must be refused by an estimate first, unless the case is about that limit and says so.
  const auto expects_out_of_memory = [&] {
    return std::any_of(c.stderr_patterns.begin(), c.stderr_patterns.end(), [](std::string p) {
      std::transform(p.begin(), p.end(), p.begin(), [](unsigned char ch) { return std::tolower(ch); });
      return p.find("out of memory") != std::string::npos;
    });
  };
  EXPECT_FALSE(std::regex_search(err, std::regex("out of memory", kRegexFlags)) && !expects_out_of_memory())
      << "ran out of memory: an estimate must refuse this input before it allocates (or, for a case about the "
         "memory limit, a stderr pattern says 'out of memory')";
  for (const auto& pattern : c.stderr_absent)
    EXPECT_FALSE(std::regex_search(err, std::regex(substituted(pattern, values), kRegexFlags)))
        << "stderr shows what it must not: " << pattern;

  EXPECT_FALSE(fs::exists(dir / "case_out")) << "output directory left behind";
  const std::set<std::string> after = entries_under(dir);
  for (const auto& entry : after)
    EXPECT_TRUE(before.count(entry)) << "left in the case folder: " << entry;
  // Open MPI's helper daemon of a PETSc run (in a session of its own, so not stopped with the
  // group) removes its session directory from TMPDIR just after the program ends: a few seconds'
  // grace before anything still there counts as left behind.
  for (int wait = 0; wait < 50 && !entries_under(tmp).empty(); ++wait)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  for (const auto& entry : entries_under(tmp)) ADD_FAILURE() << "left in TMPDIR: " << entry;
  for (const auto& path : c.absent)
    EXPECT_FALSE(fs::exists(substituted(path, values))) << "a malicious input took effect: " << path << " exists";
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) { return info.param.group + "_" + info.param.name; }

INSTANTIATE_TEST_SUITE_P(Catalogue, BadInput, ::testing::ValuesIn(load_catalogue()), case_name);

/// The catalogue keeps its promised breadth.
TEST(BadInputCatalogue, HasAtLeastEightyCasesAndEightInEachGroup) {
  const std::vector<Case> cases = load_catalogue();
  EXPECT_GE(cases.size(), 80u);
  std::map<std::string, int> per_group;
  for (const auto& c : cases) ++per_group[c.group];
  for (const char* group : {"command_line", "expressions", "geo_scripts", "mesh_files", "petsc_options", "yaml"})
    EXPECT_GE(per_group[group], 8) << group;
}

}  // namespace
