#pragma once
// The user-facing Markdown pages (README.md and docs/**/*.md) for the tests that check them
// against the code and the tree.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace iga::test {

/// The whole text of a file (empty when it cannot be read).
inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// README.md and every .md file under docs/ of the source tree, sorted.
inline std::vector<std::filesystem::path> documentation_pages() {
  const std::filesystem::path root(IGA_SOURCE_DIR);
  std::vector<std::filesystem::path> pages{root / "README.md"};
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root / "docs"))
    if (entry.path().extension() == ".md") pages.push_back(entry.path());
  std::sort(pages.begin(), pages.end());
  return pages;
}

}  // namespace iga::test
