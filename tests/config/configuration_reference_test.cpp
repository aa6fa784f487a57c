// docs/configuration.md against the parser. The parser declares its keys where it checks them
// (ConfigNode::check_keys) and its fixed value sets where it reads them (ConfigNode::as_choice);
// declared_config() collects both. Parsing every complete example of the reference fills that
// record, which must then equal the reference: no accepted key missing from its tables, no key in
// them that the parser rejects, the same value sets, and every check_keys call of the sources
// reached by some example (so that the record is complete).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "config/config_node.hpp"
#include "geometry/geometry_study.hpp"
#include "solver/study.hpp"
#include "spaces/space_factory.hpp"
#include "tests/support/documentation_pages.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot(IGA_SOURCE_DIR);
const fs::path kReference = kRoot / "docs" / "configuration.md";

using iga::test::documentation_pages;
std::string slurp(const fs::path& p) { return iga::test::read_text(p); }

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

/// Every `word` between backticks in `text`.
std::vector<std::string> backticked(const std::string& text) {
  static const std::regex code("`([^`]+)`");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), code); it != std::sregex_iterator(); ++it)
    out.push_back((*it)[1]);
  return out;
}

std::string joined(const std::set<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

/// A fenced ```yaml block that is not marked `fragment`: a complete config.
struct Example {
  fs::path page;
  int line;  ///< of the opening fence, 1-based
  std::string text;
};

std::vector<Example> complete_examples(const fs::path& page) {
  std::vector<Example> out;
  const std::vector<std::string> lines = lines_of(slurp(page));
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string fence = trim(lines[i]);
    if (fence.rfind("```", 0) != 0) continue;
    const std::string info = trim(fence.substr(3));
    size_t end = i + 1;
    while (end < lines.size() && trim(lines[end]).rfind("```", 0) != 0) ++end;
    if (info.rfind("yaml", 0) == 0 && info.find("fragment") == std::string::npos) {
      Example e{page, static_cast<int>(i + 1), {}};
      for (size_t k = i + 1; k < end; ++k) e.text += lines[k] + "\n";
      out.push_back(e);
    }
    i = end;
  }
  return out;
}

/// A row of a key table (a Markdown table whose header starts with the column `key`).
struct KeyRow {
  std::string key;     ///< full dotted path, e.g. "space.refine_near[].times"
  std::string values;  ///< the `values` column, when the table has one
  int line;
};

/// Key rows of `page`; a first cell that is not one `dotted.path` is reported in `malformed`.
std::vector<KeyRow> key_rows(const fs::path& page, std::vector<std::string>& malformed) {
  static const std::regex path_cell(R"(`([a-z0-9_]+(\[\])?(\.[a-z0-9_]+(\[\])?)*)`)");
  std::vector<KeyRow> rows;
  const std::vector<std::string> lines = lines_of(slurp(page));
  auto cells = [](const std::string& line) {
    std::vector<std::string> out;
    std::string cell;
    for (size_t i = 1; i < line.size(); ++i) {  // skip the leading '|'
      if (line[i] == '|') out.push_back(trim(cell)), cell.clear();
      else cell += line[i];
    }
    return out;
  };
  for (size_t i = 0; i + 1 < lines.size(); ++i) {
    if (lines[i].rfind("|", 0) != 0 || lines[i + 1].rfind("|---", 0) != 0) continue;
    const std::vector<std::string> header = cells(lines[i]);
    size_t k = i + 2;
    if (!header.empty() && header[0] == "key") {
      const auto values_column = std::find(header.begin(), header.end(), "values") - header.begin();
      for (; k < lines.size() && lines[k].rfind("|", 0) == 0; ++k) {
        const std::vector<std::string> row = cells(lines[k]);
        std::smatch m;
        if (row.empty() || !std::regex_match(row[0], m, path_cell)) {
          malformed.push_back(page.filename().string() + ":" + std::to_string(k + 1) + ": " + lines[k]);
          continue;
        }
        rows.push_back({m[1], static_cast<size_t>(values_column) < row.size() ? row[values_column] : "",
                        static_cast<int>(k + 1)});
      }
    }
    i = k - 1;
  }
  return rows;
}

/// Parses `example` as a whole config, as iga-run would from configs/ (relative mesh files are found
/// in configs/domains/). Returns the InputError's message, empty when accepted.
std::string parse_error(const Example& example) {
  const std::string name = (kRoot / "configs" / "reference-example.yaml").string();
  try {
    const iga::ConfigNode root = iga::ConfigNode::load_string(example.text, name);
    if (iga::is_geometry_study(root))
      iga::parse_geometry_study(root, name, 0, "");
    else
      iga::parse_study(root, name, 0, "");
  } catch (const iga::InputError& e) {
    return e.what();
  }
  return {};
}

/// The reference's examples parsed once per process (ctest runs every test case in its own process,
/// and the declarations they leave behind are what the key and value checks compare).
const std::vector<Example>& parsed_reference_examples() {
  static const std::vector<Example> examples = [] {
    std::vector<Example> all = complete_examples(kReference);
    for (const Example& e : all) parse_error(e);
    return all;
  }();
  return examples;
}

/// Every key the parser declared, as a full dotted path ("space.refine_near[].curve.samples").
std::set<std::string> declared_keys(const iga::DeclaredConfig& declared) {
  std::set<std::string> out;
  for (const auto& [path, keys] : declared.keys)
    for (const std::string& key : keys) out.insert(path.empty() ? key : path + "." + key);
  return out;
}

}  // namespace

TEST(ConfigurationReference, CompleteExamplesAreAccepted) {
  // The reference's examples, and any other complete config shown in README.md or docs/.
  int count = 0;
  for (const fs::path& page : documentation_pages())
    for (const Example& example : complete_examples(page)) {
      ++count;
      const std::string error = parse_error(example);
      EXPECT_TRUE(error.empty()) << fs::relative(page, kRoot).string() << ":" << example.line
                                 << ": this example config is rejected: " << error;
    }
  EXPECT_GE(count, 10) << "the reference's complete examples are ```yaml blocks not marked `fragment`";
}

TEST(ConfigurationReference, ExamplesCoverEverySpaceAndDomainType) {
  // Which domain types each space takes, from the reference's table "| space | `domain.type` ... |".
  parsed_reference_examples();
  const std::set<std::string> domain_types = iga::declared_config().choices["domain.type"];
  std::map<std::string, std::set<std::string>> documented;  // space -> domain types
  for (const std::string& line : lines_of(slurp(kReference))) {
    const std::vector<std::string> words = backticked(line);
    const std::vector<std::string> spaces = iga::space_types();
    if (line.rfind("| `", 0) != 0 || words.empty() ||
        std::find(spaces.begin(), spaces.end(), words[0]) == spaces.end() || words.size() < 2)
      continue;
    for (size_t i = 1; i < words.size(); ++i)
      if (domain_types.count(words[i])) documented[words[0]].insert(words[i]);
  }
  std::set<std::pair<std::string, std::string>> covered;
  for (const Example& example : parsed_reference_examples()) {
    const iga::ConfigNode root = iga::ConfigNode::load_string(example.text);
    if (!root.has("space")) continue;  // a geometry study (no space) or a comparison (spaces:)
    covered.insert({root["space"]["type"].as_string(), root["domain"]["type"].as_string()});
  }
  std::set<std::string> documented_types;
  for (const std::string& space : iga::space_types()) {
    EXPECT_FALSE(documented[space].empty()) << "the domain table of docs/configuration.md has no row for " << space;
    for (const std::string& type : documented[space]) {
      documented_types.insert(type);
      EXPECT_TRUE(covered.count({space, type}))
          << "docs/configuration.md has no complete example of space " << space << " on domain type " << type;
    }
  }
  EXPECT_EQ(documented_types, domain_types) << "the domain table must name every domain type the parser accepts";
}

TEST(ConfigurationReference, DocumentsExactlyTheAcceptedKeys) {
  parsed_reference_examples();
  const std::set<std::string> accepted = declared_keys(iga::declared_config());
  std::vector<std::string> malformed;
  std::set<std::string> documented;
  for (const KeyRow& row : key_rows(kReference, malformed)) documented.insert(row.key);
  EXPECT_TRUE(malformed.empty()) << "key table rows must start with one `full.dotted.key`:\n"
                                 << [&] { std::string s; for (auto& m : malformed) s += m + "\n"; return s; }();

  std::set<std::string> missing, extra;
  std::set_difference(accepted.begin(), accepted.end(), documented.begin(), documented.end(),
                      std::inserter(missing, missing.end()));
  std::set_difference(documented.begin(), documented.end(), accepted.begin(), accepted.end(),
                      std::inserter(extra, extra.end()));
  EXPECT_TRUE(missing.empty()) << "keys the parser accepts but docs/configuration.md does not document: "
                               << joined(missing);
  EXPECT_TRUE(extra.empty()) << "keys docs/configuration.md documents but the parser does not declare (misspelt, "
                                "removed, or in a section no example reaches): " << joined(extra);

  // Key tables on other pages (the spaces' pages) may show fewer keys, but only accepted ones.
  for (const fs::path& page : documentation_pages()) {
    if (page == kReference) continue;
    for (const KeyRow& row : key_rows(page, malformed))
      EXPECT_TRUE(accepted.count(row.key)) << fs::relative(page, kRoot).string() << ":" << row.line << ": key `"
                                           << row.key << "` is not accepted by the parser";
  }
}

TEST(ConfigurationReference, ListsExactlyTheAcceptedValues) {
  parsed_reference_examples();
  const iga::DeclaredConfig declared = iga::declared_config();
  std::vector<std::string> malformed;
  std::map<std::string, KeyRow> rows;
  for (const KeyRow& row : key_rows(kReference, malformed)) rows.emplace(row.key, row);

  // A value set belongs to its key; one read from a list ("space.section[]") to the list's key; one
  // under a map of free names (problem.boundary.left) to that map's key.
  std::map<std::string, std::set<std::string>> accepted;
  for (const auto& [declared_path, values] : declared.choices) {
    std::string path = declared_path;
    while (path.size() > 2 && path.compare(path.size() - 2, 2, "[]") == 0) path.resize(path.size() - 2);
    if (!rows.count(path)) {
      const std::string parent = path.substr(0, path.rfind('.'));
      if (path.find('.') != std::string::npos && rows.count(parent) && !declared.keys.count(parent)) path = parent;
    }
    EXPECT_TRUE(rows.count(path)) << "the parser offers fixed values at " << path << " (" << joined(values)
                                  << "), which docs/configuration.md has no row for";
    accepted[path].insert(values.begin(), values.end());
  }
  for (const auto& [key, values] : accepted) {
    if (!rows.count(key)) continue;
    const std::vector<std::string> words = backticked(rows.at(key).values);
    const std::set<std::string> documented(words.begin(), words.end());
    EXPECT_EQ(documented, values) << "docs/configuration.md:" << rows.at(key).line << ": the values column of `" << key
                                  << "` lists " << joined(documented) << "; the parser accepts " << joined(values);
  }
}

TEST(ConfigurationReference, ExamplesReachEveryKeyCheck) {
  // Every key named in a check_keys({...}) call of the sources is declared once the examples are
  // parsed; otherwise some section is never reached by them and the key comparison would not see it.
  parsed_reference_examples();
  std::set<std::string> reached;
  for (const std::string& key : declared_keys(iga::declared_config()))
    reached.insert(key.substr(key.rfind('.') == std::string::npos ? 0 : key.rfind('.') + 1));
  static const std::regex call(R"(check_keys\(\{([^}]*)\}\))"), literal("\"([^\"]+)\"");
  int calls = 0;
  for (const char* layer : {"config", "mesh", "geometry", "spaces", "assembly", "solver", "output", "app"}) {
    for (const auto& entry : fs::recursive_directory_iterator(kRoot / layer)) {
      if (entry.path().extension() != ".cpp") continue;
      const std::string text = slurp(entry.path());
      for (auto it = std::sregex_iterator(text.begin(), text.end(), call); it != std::sregex_iterator(); ++it) {
        ++calls;
        const std::string list = (*it)[1];
        for (auto w = std::sregex_iterator(list.begin(), list.end(), literal); w != std::sregex_iterator(); ++w)
          EXPECT_TRUE(reached.count((*w)[1])) << fs::relative(entry.path(), kRoot).string() << " declares key '"
                                              << (*w)[1] << "', which no example in docs/configuration.md reaches";
      }
    }
  }
  EXPECT_GT(calls, 10);
}

TEST(ConfigurationReference, ReadmeFirstConfigIsTheQuickstart) {
  // README explains configs/quickstart.yaml line by line: the same YAML apart from the comments.
  const std::vector<Example> readme = complete_examples(kRoot / "README.md");
  ASSERT_FALSE(readme.empty()) << "README.md shows no complete config";
  EXPECT_EQ(YAML::Dump(YAML::Load(readme.front().text)),
            YAML::Dump(YAML::LoadFile((kRoot / "configs" / "quickstart.yaml").string())))
      << "README.md:" << readme.front().line << " differs from configs/quickstart.yaml";
}
