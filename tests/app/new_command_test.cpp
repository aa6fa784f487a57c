// `iga-run new SPACE [DOMAIN]`: every starting config is the docs/configuration.md block it comes
// from (read here from the page itself, not from the program), every space and domain type of the
// catalogue has one, and each printed config runs as it is: saved in an empty folder with a
// domains/ copy of configs/domains (as the config's comments tell a user to do), two levels, the
// second finer than the first and, with an exact solution, closer to it.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app/starter_configs.hpp"
#include "config/config_node.hpp"
#include "spaces/space_factory.hpp"
#include "tests/support/run_iga.hpp"

namespace fs = std::filesystem;

namespace {

using iga::test::RunResult;
using iga::test::run_iga;
using iga::test::run_iga_in;
using iga::test::slurp;

const fs::path kRoot(IGA_SOURCE_DIR);

/// The page as it is in the source tree now (the program carries the page it was built with).
std::string reference_page() { return slurp(kRoot / "docs" / "configuration.md"); }

/// "space domain" of every starter, for the parametrized cases (listed when the program starts).
std::vector<std::string> starter_names() {
  std::vector<std::string> names;
  for (const iga::StarterConfig& s : iga::starter_configs(reference_page())) names.push_back(s.space + " " + s.domain);
  return names;
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

}  // namespace

TEST(NewCommand, ProgramCarriesTheReferencePage) {
  // A build older than the page would print configs the page no longer shows.
  EXPECT_EQ(std::string(iga::configuration_reference_page()), reference_page())
      << "rebuild: the program's copy of docs/configuration.md differs from the page";
}

TEST(NewCommand, EveryCatalogueSpaceAndDomainTypeHasAStarter) {
  std::set<std::pair<std::string, std::string>> starters;
  for (const iga::StarterConfig& s : iga::starter_configs(reference_page())) {
    EXPECT_TRUE(starters.insert({s.space, s.domain}).second)
        << "docs/configuration.md:" << s.line << ": a second starter for " << s.space << " on " << s.domain
        << " (`iga-run new` would never print it)";
  }
  int pairs = 0;
  for (const iga::SpaceCatalogueEntry& space : iga::space_catalogue())
    for (const iga::DomainFamily& domain : space.domains) {
      ++pairs;
      EXPECT_TRUE(starters.count({space.type, domain.type}))
          << "docs/configuration.md has no ```yaml starter block for space " << space.type << " on domain type "
          << domain.type;
    }
  EXPECT_EQ(static_cast<int>(starters.size()), pairs) << "a starter for a pair the catalogue does not list";
}

TEST(NewCommand, WithoutADomainTypeTheSpacesFirstStarter) {
  std::map<std::string, std::string> first;  // space -> its first starter's YAML
  for (const iga::StarterConfig& s : iga::starter_configs(reference_page())) first.emplace(s.space, s.yaml);
  ASSERT_FALSE(first.empty());
  for (const auto& [space, yaml] : first) {
    const RunResult r = run_iga("new " + space);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out.substr(r.out.size() - std::min(r.out.size(), yaml.size())), yaml) << space;
  }
}

TEST(NewCommand, UnknownSpaceOrDomainTypeIsAnInputError) {
  const RunResult space = run_iga("new bsplin");
  EXPECT_EQ(space.exit_code, 2);
  EXPECT_NE(space.err.find("no space type 'bsplin' (did you mean 'bspline'?)"), std::string::npos) << space.err;
  EXPECT_TRUE(space.out.empty());
  const RunResult domain = run_iga("new tmesh polygon");
  EXPECT_EQ(domain.exit_code, 2);
  EXPECT_NE(domain.err.find("its domain types: rectangle, l_shape"), std::string::npos) << domain.err;
  const RunResult none = run_iga("new");
  EXPECT_EQ(none.exit_code, 2) << "the space type is required";
}

class Starter : public ::testing::TestWithParam<std::string> {};

TEST_P(Starter, IsTheReferenceBlockAndRunsAsItIs) {
  const std::string space = GetParam().substr(0, GetParam().find(' '));
  const std::string domain = GetParam().substr(GetParam().find(' ') + 1);
  std::string yaml;
  for (const iga::StarterConfig& s : iga::starter_configs(reference_page()))
    if (s.space == space && s.domain == domain) yaml = s.yaml;

  const RunResult printed = run_iga("new " + GetParam());
  ASSERT_EQ(printed.exit_code, 0) << printed.err;
  ASSERT_GE(printed.out.size(), yaml.size());
  EXPECT_EQ(printed.out.substr(printed.out.size() - yaml.size()), yaml)
      << "`iga-run new " << GetParam() << "` does not end with the page's block";
  const std::string header = printed.out.substr(0, printed.out.size() - yaml.size());
  std::istringstream lines(header);
  for (std::string line; std::getline(lines, line);) EXPECT_EQ(line.rfind("# ", 0), 0u) << "not a comment: " << line;

  // Saved where a user would save it, with the mesh files its comments point to.
  const fs::path folder = iga::test::scratch_folder() / test_name({GetParam(), 0});
  fs::create_directories(folder);
  fs::copy(kRoot / "configs" / "domains", folder / "domains", fs::copy_options::recursive);
  std::ofstream(folder / "starter.yaml") << printed.out;
  const RunResult run = run_iga_in(folder, "--quiet --levels 2 starter.yaml");
  ASSERT_EQ(run.exit_code, 0) << run.err;

  const nlohmann::json summary = nlohmann::json::parse(slurp(folder / "results" / "starter" / "summary.json"));
  const nlohmann::json& levels = summary["levels"];
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_GT(levels[1]["dofs"].get<double>(), levels[0]["dofs"].get<double>()) << "level 1 is no finer";
  const iga::ConfigNode root = iga::ConfigNode::load_string(yaml);
  if (root["problem"].has("exact")) {
    // Closer to the exact solution, or at round-off already (an exact solution inside the space).
    const double e0 = levels[0]["l2"].get<double>(), e1 = levels[1]["l2"].get<double>();
    EXPECT_TRUE(e1 < e0 || e1 < 1e-12) << "L2 errors " << e0 << " then " << e1;
  }
}

INSTANTIATE_TEST_SUITE_P(NewCommand, Starter, ::testing::ValuesIn(starter_names()), test_name);
