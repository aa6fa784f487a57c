// The output location refused before any work when the results would replace the working
// directory, a config's folder or a folder above them: with "..", trailing separators and
// symbolic links resolved; folders beside and below pass.

#include "solver/output_location.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "config/errors.hpp"
#include "tests/support/scratch_files.hpp"

namespace iga {
namespace {

namespace fs = std::filesystem;

std::string config_refusal(const fs::path& cwd, const std::string& path);

/// The message of `check()` run from `cwd`, or "" when it passes.
template <class Check>
std::string message_from(const fs::path& cwd, Check check) {
  const fs::path before = fs::current_path();
  fs::current_path(cwd);
  std::string message;
  try {
    check();
  } catch (const InputError& e) {
    message = e.what();
  }
  fs::current_path(before);
  return message;
}

/// The message of check_output_not_above for `path`, run from `cwd`, or "" when it passes.
std::string refusal(const fs::path& cwd, const std::string& path, const std::vector<std::string>& configs) {
  return message_from(cwd, [&] { check_output_not_above(path, "--output", configs); });
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

/// The message of check_config_output_directory for `path`, run from `cwd`, or "" when it passes.
std::string config_refusal(const fs::path& cwd, const std::string& path) {
  return message_from(cwd, [&] { check_config_output_directory(path, "c.yaml:9:22: output.directory"); });
}

TEST(OutputLocation, AConfigWritesOnlyInsideTheWorkingDirectory) {
  const fs::path run = test::scratch_folder() / "run4";
  fs::create_directories(run / "sub");
  fs::remove(run / "out_link");
  fs::remove(run / "in_link");
  fs::create_directory_symlink(run.parent_path(), run / "out_link");
  fs::create_directory_symlink(run / "sub", run / "in_link");
  EXPECT_EQ(config_refusal(run, "/tmp/results"),
            "c.yaml:9:22: output.directory: output directory '/tmp/results' is an absolute path: a config writes "
            "only inside the working directory (give a relative path such as results/NAME, or choose the place with "
            "--output)");
  for (const char* path : {"../results", "results/../../x", "sub/../../x", "out_link/results", "out_link"})
    EXPECT_NE(config_refusal(run, path).find("' leads outside the working directory"), std::string::npos) << path;
  for (const char* path : {"results", "results/a/b", "sub/../results", "in_link/results", "./results"})
    EXPECT_EQ(config_refusal(run, path), "") << path;
}

TEST(OutputLocation, OnlyEmptyFoldersAndEarlierResultsAreReplaced) {
  const fs::path run = test::scratch_folder() / "run5";
  fs::remove_all(run);
  fs::create_directories(run / "empty");
  fs::create_directories(run / "theirs");
  std::ofstream(run / "theirs" / "thesis.tex") << "x";
  fs::create_directories(run / "study");
  std::ofstream(run / "study" / "summary.json") << "{}";
  fs::create_directories(run / "comparison");
  std::ofstream(run / "comparison" / "comparison.csv") << "";
  EXPECT_TRUE(replaceable_output_directory((run / "missing").string()));
  EXPECT_TRUE(replaceable_output_directory((run / "empty").string()));
  EXPECT_TRUE(replaceable_output_directory((run / "study").string()));
  EXPECT_TRUE(replaceable_output_directory((run / "comparison").string()));
  EXPECT_FALSE(replaceable_output_directory((run / "theirs").string()));
  try {
    check_output_directory((run / "theirs").string(), "--output");
    ADD_FAILURE() << "a folder that is not a result was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("exists and is not an earlier result of iga-run"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(run / "theirs" / "thesis.tex"));
}

/// The message of check_output_directory for `path`, run from `cwd`, or "" when it passes.
std::string output_refusal(const fs::path& cwd, const std::string& path) {
  return message_from(cwd, [&] { check_output_directory(path, "--output"); });
}

TEST(OutputLocation, DanglingLinksOnTheWayAreRefused) {
  const fs::path run = test::scratch_folder() / "run6";
  fs::remove_all(run);
  fs::create_directories(run / "real");
  fs::create_directory_symlink("../outside/new", run / "out");
  fs::create_directory_symlink("missing", run / "lnk");
  fs::create_directory_symlink("loop_b", run / "loop_a");
  fs::create_directory_symlink("loop_a", run / "loop_b");
  fs::create_directory_symlink("real", run / "good");
  EXPECT_EQ(output_refusal(run, "out"), "--output: output directory 'out' goes through the symbolic link '" +
                                            (run / "out").string() +
                                            "' (to '../outside/new'), which leads nowhere: its target does not "
                                            "exist (or the links loop)");
  for (const char* path : {"lnk/res", "lnk/../res", "loop_a", "loop_b/x"})
    EXPECT_NE(output_refusal(run, path).find("which leads nowhere"), std::string::npos) << path;
  // From a config too, before the question whether it leads outside.
  EXPECT_NE(config_refusal(run, "out").find("c.yaml:9:22: output.directory: output directory 'out' goes through the "
                                            "symbolic link"),
            std::string::npos);
  for (const char* path : {"good", "good/res", "real/a/b", "new"}) EXPECT_EQ(output_refusal(run, path), "") << path;
  EXPECT_FALSE(fs::exists(run / "outside"));
}

TEST(OutputLocation, OverlongPathsAndNamesAreRefusedForWhatTheyAre) {
  const fs::path run = test::scratch_folder() / "run7";
  fs::create_directories(run);
  std::string deep;
  while (deep.size() < 3900) deep += "abcdefghij/";
  EXPECT_NE(output_refusal(run, deep).find("--output: output directory 'abcdefghij/abcdefghij/"), std::string::npos);
  EXPECT_NE(output_refusal(run, deep).find("...' is too long: "), std::string::npos) << output_refusal(run, deep);
  EXPECT_NE(output_refusal(run, deep).find(" bytes as an absolute path, at most 2048"), std::string::npos);
  EXPECT_NE(config_refusal(run, deep).find("is too long"), std::string::npos);
  EXPECT_FALSE(fs::exists(run / "abcdefghij"));  // nothing made on the way

  const std::string long_name(300, 'n');
  EXPECT_NE(config_refusal(run, long_name).find("c.yaml:9:22: output.directory: output directory 'nnn"),
            std::string::npos);
  EXPECT_NE(config_refusal(run, long_name + "/x").find("has a name of 300 bytes ('nnnn"), std::string::npos);
  EXPECT_NE(config_refusal(run, long_name + "/x").find("'); a name has at most 255"), std::string::npos);
  EXPECT_EQ(config_refusal(run, long_name).find("leads outside"), std::string::npos);
  // The output directory's own name leaves room for the name it moves in under.
  EXPECT_NE(output_refusal(run, std::string(230, 'n')).find("ends in a name of 230 bytes; the output directory's own "
                                                            "name has at most 223"),
            std::string::npos);
  EXPECT_EQ(output_refusal(run, std::string(223, 'n')), "");
  EXPECT_EQ(output_refusal(run, std::string(255, 'n') + "/results"), "");
}

}  // namespace
}  // namespace iga
