// README.md and docs/ against the tree: every relative link resolves (with its #anchor), every
// source path named in backticks exists, and no page refers to an issue number.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/documentation_pages.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot(IGA_SOURCE_DIR);

using iga::test::documentation_pages;
std::string slurp(const fs::path& p) { return iga::test::read_text(p); }

/// The page's lines outside fenced code blocks (links and paths in code are not checked).
std::vector<std::string> prose_lines(const fs::path& page) {
  std::vector<std::string> out;
  std::istringstream in(slurp(page));
  bool fenced = false;
  for (std::string line; std::getline(in, line);) {
    const auto first = line.find_first_not_of(' ');
    if (first != std::string::npos && line.compare(first, 3, "```") == 0) {
      fenced = !fenced;
      out.emplace_back();
      continue;
    }
    out.push_back(fenced ? std::string() : line);
  }
  return out;
}

/// GitHub's anchor of a heading: lower case, punctuation dropped, spaces to '-'.
std::string anchor_of(const std::string& heading) {
  std::string out;
  for (const unsigned char c : heading) {
    if (std::isalnum(c) || c == '_' || c == '-' || c >= 0x80) out += static_cast<char>(std::tolower(c));
    else if (c == ' ') out += '-';
  }
  return out;
}

std::set<std::string> anchors(const fs::path& page) {
  std::set<std::string> out;
  for (const std::string& line : prose_lines(page)) {
    if (line.empty() || line[0] != '#') continue;
    const auto text = line.find_first_not_of('#');
    if (text == std::string::npos || line[text] != ' ') continue;
    std::string heading = line.substr(text + 1);
    heading.erase(std::remove(heading.begin(), heading.end(), '`'), heading.end());
    out.insert(anchor_of(heading));
  }
  return out;
}

std::string where(const fs::path& page, size_t line) {
  return fs::relative(page, kRoot).string() + ":" + std::to_string(line + 1);
}

/// Calls `check(page, line, match)` for every match of `pattern` in the prose of every page.
template <class Check>
void for_each_prose_match(const std::regex& pattern, Check check) {
  for (const fs::path& page : documentation_pages()) {
    const std::vector<std::string> lines = prose_lines(page);
    for (size_t i = 0; i < lines.size(); ++i)
      for (auto it = std::sregex_iterator(lines[i].begin(), lines[i].end(), pattern); it != std::sregex_iterator(); ++it)
        check(page, i, *it);
  }
}

/// A placeholder rather than a path: `spaces/NAME/`, `results/<config name>`, `tests/**/*_test.cpp`.
bool placeholder(const std::string& path) {
  return std::any_of(path.begin(), path.end(), [](char c) {
    return std::isupper(static_cast<unsigned char>(c)) || c == '<' || c == '*' || c == '{';
  });
}

}  // namespace

TEST(Docs, RelativeLinksResolve) {
  static const std::regex link(R"(\]\(([^)\s]+)\))");
  int checked = 0;
  for_each_prose_match(link, [&](const fs::path& page, size_t line, const std::smatch& m) {
    const std::string target = m[1];
    if (target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0) return;
    ++checked;
    const auto hash = target.find('#');
    const std::string file = target.substr(0, hash);
    const fs::path resolved = file.empty() ? page : (page.parent_path() / file).lexically_normal();
    if (!fs::exists(resolved)) {
      ADD_FAILURE() << where(page, line) << ": link to a missing file: " << target;
      return;
    }
    if (hash != std::string::npos && resolved.extension() == ".md")
      EXPECT_TRUE(anchors(resolved).count(target.substr(hash + 1)))
          << where(page, line) << ": no heading for the anchor of " << target;
  });
  EXPECT_GT(checked, 20);
}

TEST(Docs, NamedSourcePathsExist) {
  // `folder/file` in prose, for the folders of the tree.
  static const std::regex code("`([^`\\s]+)`");
  static const std::set<std::string> folders{"config", "quadrature", "mesh",       "spaces",   "assembly",
                                             "solver", "output",     "app",        "tests",    "configs",
                                             "scripts", "benchmarks", "examples", "cmake",    "docs"};
  int checked = 0;
  for_each_prose_match(code, [&](const fs::path& page, size_t line, const std::smatch& m) {
    const std::string path = m[1];
    const auto slash = path.find('/');
    if (slash == std::string::npos || !folders.count(path.substr(0, slash)) || placeholder(path)) return;
    ++checked;
    EXPECT_TRUE(fs::exists(kRoot / path)) << where(page, line) << ": names `" << path << "`, which does not exist";
  });
  EXPECT_GT(checked, 30);
}

TEST(Docs, NoIssueNumbers) {
  // A reader cannot see the issue tracker: pages explain things themselves.
  static const std::regex issue(R"(\bissues? #?[0-9])", std::regex::icase);
  for (const fs::path& page : documentation_pages()) {
    std::istringstream in(slurp(page));
    size_t i = 0;
    for (std::string line; std::getline(in, line); ++i)
      EXPECT_FALSE(std::regex_search(line, issue)) << where(page, i) << ": " << line;
  }
}
