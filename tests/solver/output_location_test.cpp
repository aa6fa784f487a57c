// The output location refused before any work when the results would replace the working
// directory, a config's folder or a folder above them: with "..", trailing separators and
// symbolic links resolved; folders beside and below pass.

#include "solver/output_location.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "config/errors.hpp"
#include "tests/support/scratch_files.hpp"

namespace iga {
namespace {

namespace fs = std::filesystem;

/// The message of check_output_not_above for `path`, run from `cwd`, or "" when it passes.
std::string refusal(const fs::path& cwd, const std::string& path, const std::vector<std::string>& configs) {
  const fs::path before = fs::current_path();
  fs::current_path(cwd);
  std::string message;
  try {
    check_output_not_above(path, "--output", configs);
  } catch (const InputError& e) {
    message = e.what();
  }
  fs::current_path(before);
  return message;
}

TEST(OutputLocation, TheWorkingDirectoryAndFoldersAboveItAreRefused) {
  const fs::path run = test::scratch_folder() / "run";
  fs::create_directories(run / "sub");
  for (const char* path : {".", "./", "..", "sub/..", "/", "../run"})
    EXPECT_EQ(refusal(run, path, {}).rfind(std::string("--output: output directory '") + path +
                                               "' is the working directory or a folder above it",
                                           0),
              0u)
        << path << ": " << refusal(run, path, {});
  EXPECT_EQ(refusal(run, run.string(), {}).rfind("--output: output directory '" + run.string() + "' is the working directory",
                                                0),
            0u);
  for (const char* path : {"results", "sub", "results/x/y", "../other", "sub/../results"})
    EXPECT_EQ(refusal(run, path, {}), "") << path;
}

TEST(OutputLocation, TheConfigsFolderAndFoldersAboveItAreRefused) {
  const fs::path run = test::scratch_folder() / "run2";
  fs::create_directories(run / "configs" / "deep");
  const std::vector<std::string> configs = {"configs/deep/a.yaml"};
  EXPECT_EQ(refusal(run, "configs/deep", configs),
            "--output: output directory 'configs/deep' is the folder of the config 'configs/deep/a.yaml' or a folder "
            "above it: the results replace the output directory as a whole; give a folder of their own, such as "
            "results/NAME");
  EXPECT_NE(refusal(run, "configs", configs).find("is the folder of the config"), std::string::npos);
  EXPECT_NE(refusal(run, "configs/deep/", configs).find("is the folder of the config"), std::string::npos);
  EXPECT_EQ(refusal(run, "configs/deep/results", configs), "");
  EXPECT_EQ(refusal(run, "configs/other", configs), "");
}

TEST(OutputLocation, SymbolicLinksAreResolved) {
  const fs::path run = test::scratch_folder() / "run3";
  fs::create_directories(run / "configs");
  fs::remove(run / "to_configs");
  fs::remove(run / "to_here");
  fs::create_directory_symlink(run / "configs", run / "to_configs");
  fs::create_directory_symlink(run, run / "to_here");
  EXPECT_NE(refusal(run, "to_configs", {"configs/a.yaml"}).find("is the folder of the config"), std::string::npos);
  EXPECT_NE(refusal(run, "to_here", {}).find("is the working directory"), std::string::npos);
  // A config reached through a link: its real folder counts.
  EXPECT_NE(refusal(run, "configs", {"to_configs/a.yaml"}).find("is the folder of the config"), std::string::npos);
  EXPECT_EQ(refusal(run, "to_configs/results", {"configs/a.yaml"}), "");
}

}  // namespace
}  // namespace iga
