#pragma once
// Small input files written by tests into one folder per test program, removed when it ends.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace iga::test {

inline std::filesystem::path scratch_folder() {
  static const std::filesystem::path folder = [] {
    const auto f = std::filesystem::temp_directory_path() / ("iga-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(f);
    return f;
  }();
  return folder;
}

class ScratchFolderCleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(scratch_folder(), ec);
  }
};
inline const auto* const scratch_folder_cleanup = ::testing::AddGlobalTestEnvironment(new ScratchFolderCleanup);

/// Writes `text` to `name` in the scratch folder (overwriting) and returns the full path.
inline std::string scratch_file(const std::string& name, const std::string& text) {
  const auto path = scratch_folder() / name;
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace iga::test
