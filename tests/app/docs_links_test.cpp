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

namespace fs = std::filesystem;

namespace {

const fs::path kRoot(IGA_SOURCE_DIR);

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<fs::path> markdown_pages() {
  std::vector<fs::path> pages{kRoot / "README.md"};
  for (const auto& entry : fs::recursive_directory_iterator(kRoot / "docs"))
    if (entry.path().extension() == ".md") pages.push_back(entry.path());
  std::sort(pages.begin(), pages.end());
  return pages;
}

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

}  // namespace

TEST(Docs, RelativeLinksResolve) {
  static const std::regex link(R"(\]\(([^)\s]+)\))");
  int checked = 0;
  for (const fs::path& page : markdown_pages()) {
    const std::vector<std::string> lines = prose_lines(page);
    for (size_t i = 0; i < lines.size(); ++i) {
      for (auto it = std::sregex_iterator(lines[i].begin(), lines[i].end(), link); it != std::sregex_iterator(); ++it) {
        const std::string target = (*it)[1];
        if (target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0) continue;
        ++checked;
        const auto hash = target.find('#');
        const std::string file = target.substr(0, hash);
        const fs::path resolved = file.empty() ? page : (page.parent_path() / file).lexically_normal();
        if (!fs::exists(resolved)) {
          ADD_FAILURE() << where(page, i) << ": link to a missing file: " << target;
          continue;
        }
        if (hash != std::string::npos && resolved.extension() == ".md")
          EXPECT_TRUE(anchors(resolved).count(target.substr(hash + 1)))
              << where(page, i) << ": no heading for the anchor of " << target;
      }
    }
  }
  EXPECT_GT(checked, 20);
}

TEST(Docs, NamedSourcePathsExist) {
  // `folder/file` in prose, for the folders of the tree; placeholders (NAME, <...>, *) are skipped.
  static const std::regex code("`([^`\\s]+)`");
  static const std::set<std::string> folders{"config",   "quadrature", "mesh",    "spaces",     "assembly",
                                             "solver",   "output",     "app",     "tests",      "configs",
                                             "scripts",  "benchmarks", "examples", "cmake",     "docs"};
  int checked = 0;
  for (const fs::path& page : markdown_pages()) {
    const std::vector<std::string> lines = prose_lines(page);
    for (size_t i = 0; i < lines.size(); ++i) {
      for (auto it = std::sregex_iterator(lines[i].begin(), lines[i].end(), code); it != std::sregex_iterator(); ++it) {
        const std::string path = (*it)[1];
        const auto slash = path.find('/');
        if (slash == std::string::npos || !folders.count(path.substr(0, slash))) continue;
        if (std::any_of(path.begin(), path.end(), [](char c) { return std::isupper(static_cast<unsigned char>(c)) || c == '<' || c == '*' || c == '{'; }))
          continue;
        ++checked;
        EXPECT_TRUE(fs::exists(kRoot / path)) << where(page, i) << ": names `" << path << "`, which does not exist";
      }
    }
  }
  EXPECT_GT(checked, 30);
}

TEST(Docs, NoIssueNumbers) {
  // A reader cannot see the issue tracker: pages explain things themselves.
  static const std::regex issue(R"(\bissues? #?[0-9])", std::regex::icase);
  for (const fs::path& page : markdown_pages()) {
    std::istringstream in(slurp(page));
    size_t i = 0;
    for (std::string line; std::getline(in, line); ++i)
      EXPECT_FALSE(std::regex_search(line, issue)) << where(page, i) << ": " << line;
  }
}
