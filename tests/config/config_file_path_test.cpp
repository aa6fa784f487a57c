// Files a config names: inside a config file's folder only (links resolved), refused at the key
// before anything is opened; a config from text is the caller's own and not confined.

#include "config/config_file_path.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "config/errors.hpp"
#include "tests/support/scratch_files.hpp"

namespace iga {
namespace {

namespace fs = std::filesystem;

/// A folder "<name>/cfg" with c.yaml naming `file` as `domain.file`, and a secret beside the folder.
fs::path config_folder_naming(const std::string& name, const std::string& file) {
  const fs::path base = test::scratch_folder() / name;
  fs::remove_all(base);
  fs::create_directories(base / "cfg" / "sub");
  std::ofstream(base / "secret.txt") << "secret-token-123\n";
  std::ofstream(base / "cfg" / "mesh.obj") << "v 0 0 0\n";
  std::ofstream(base / "cfg" / "sub" / "deep.obj") << "v 0 0 0\n";
  std::ofstream(base / "cfg" / "c.yaml") << "domain:\n  file: \"" << file << "\"\n";
  return base / "cfg";
}

ConfigNode file_key(const fs::path& folder) { return ConfigNode::load_file((folder / "c.yaml").string())["domain"]["file"]; }

/// The message resolve_config_file throws for the key, or "" when it accepts it.
std::string refusal(const ConfigNode& key) {
  try {
    resolve_config_file(key);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ConfigFilePath, NamesInsideTheFolderAreTakenThere) {
  const fs::path folder = config_folder_naming("inside", "sub/deep.obj");
  const ConfigNode key = file_key(folder);
  EXPECT_TRUE(key.from_file());
  EXPECT_EQ(resolve_config_file(key), folder / "sub" / "deep.obj");
  // Leaving the folder and coming back is still inside it.
  const fs::path again = config_folder_naming("again", "../cfg/mesh.obj");
  EXPECT_EQ(refusal(file_key(again)), "");
  // A link inside the folder to a file inside it is fine.
  fs::create_symlink("sub/deep.obj", again / "link.obj");
  std::ofstream(again / "c.yaml") << "domain:\n  file: link.obj\n";
  EXPECT_EQ(refusal(file_key(again)), "");
}

TEST(ConfigFilePath, ParentFolderAbsolutePathsAndLinksOutAreRefusedAtTheKey) {
  const fs::path folder = config_folder_naming("parent", "../secret.txt");
  std::string message = refusal(file_key(folder));
  EXPECT_NE(message.find("c.yaml:2:"), std::string::npos) << message;
  EXPECT_NE(message.find("domain.file: '../secret.txt' is outside the config's folder"), std::string::npos) << message;

  const fs::path absolute = config_folder_naming("absolute", (test::scratch_folder() / "absolute" / "cfg" / "mesh.obj").string());
  message = refusal(file_key(absolute));  // even an absolute name of a file inside: the config is portable only relative
  EXPECT_NE(message.find("outside the config's folder"), std::string::npos) << message;
  EXPECT_NE(message.find("relative path"), std::string::npos) << message;

  const fs::path linked = config_folder_naming("linked", "l.obj");
  fs::create_symlink(linked.parent_path() / "secret.txt", linked / "l.obj");
  message = refusal(file_key(linked));
  EXPECT_NE(message.find("'l.obj' is outside the config's folder"), std::string::npos) << message;
  EXPECT_EQ(message.find("secret-token"), std::string::npos) << message;

  // A folder beside the config that links out.
  const fs::path via_folder = config_folder_naming("via_folder", "out/secret.txt");
  fs::create_symlink(via_folder.parent_path(), via_folder / "out");
  EXPECT_NE(refusal(file_key(via_folder)).find("outside the config's folder"), std::string::npos);

  // The folder itself is not a file inside it.
  EXPECT_NE(refusal(file_key(config_folder_naming("itself", "."))).find("outside"), std::string::npos);
}

TEST(ConfigFilePath, DanglingLinksAndEmptyNamesAreRefused) {
  const fs::path folder = config_folder_naming("dangling", "d.obj");
  fs::create_symlink("/nonexistent/iga-test/secret", folder / "d.obj");
  EXPECT_NE(refusal(file_key(folder)).find("'d.obj' is a link to a file that does not exist"), std::string::npos);
  EXPECT_NE(refusal(file_key(config_folder_naming("empty", ""))).find("domain.file: is empty"), std::string::npos);
}

TEST(ConfigFilePath, AMissingFileInsideIsLeftToItsReader) {
  const fs::path folder = config_folder_naming("missing", "missing.obj");
  EXPECT_EQ(resolve_config_file(file_key(folder)), folder / "missing.obj");
}

TEST(ConfigFilePath, ConfigsFromTextAreTheCallersOwnAndNotConfined) {
  const ConfigNode text = ConfigNode::load_string("file: /etc/hostname\nrel: ../x.obj\n");
  EXPECT_FALSE(text.from_file());
  EXPECT_EQ(resolve_config_file(text["file"]), fs::path("/etc/hostname"));
  EXPECT_EQ(resolve_config_file(text["rel"]), fs::path("./../x.obj"));  // the working directory
  const ConfigNode named = ConfigNode::load_string("rel: m.obj\n", "some/dir/c.yaml");
  EXPECT_EQ(resolve_config_file(named["rel"]), fs::path("some/dir/m.obj"));  // the folder of its name
}

}  // namespace
}  // namespace iga
