#include "config/config_file_path.hpp"

#include <system_error>

namespace iga {

namespace fs = std::filesystem;

namespace {

/// `inner` relative to `outer`, both normalised and without a trailing separator.
fs::path relative_to(const fs::path& inner, const fs::path& outer) {
  const auto trimmed = [](fs::path p) {  // "/a/b/" -> "/a/b"
    p = p.lexically_normal();
    return !p.has_filename() && p.has_relative_path() ? p.parent_path() : p;
  };
  return trimmed(inner).lexically_relative(trimmed(outer));
}

}  // namespace

bool path_within(const fs::path& inner, const fs::path& outer) {
  const fs::path rel = relative_to(inner, outer);
  return !rel.empty() && *rel.begin() != "..";
}

bool path_strictly_within(const fs::path& inner, const fs::path& outer) {
  return path_within(inner, outer) && relative_to(inner, outer) != ".";
}

fs::path config_folder(const ConfigNode& node) {
  const fs::path folder = fs::path(node.file()).parent_path();
  return folder.empty() ? fs::path(".") : folder;
}

fs::path resolve_config_file(const ConfigNode& key) {
  const std::string name = key.as_string();
  if (name.empty()) key.fail("is empty (expected the name of a file beside the config)");
  const fs::path named(name);
  const fs::path folder = config_folder(key);
  const fs::path path = named.is_relative() ? folder / named : named;
  if (!key.from_file()) return path;

  const std::string outside =
      "'" + name + "' is outside the config's folder (a config may read only files in its own folder or below it";
  if (named.is_absolute()) key.fail(outside + "; give a relative path)");
  std::error_code ec;
  const fs::path root = fs::canonical(folder, ec);
  if (ec) key.fail("the config's folder cannot be resolved: " + ec.message());
  // Links resolved: a name inside the folder that is a link pointing out is outside too.
  const fs::path real = fs::weakly_canonical(path, ec);
  if (ec) key.fail("'" + name + "' cannot be resolved: " + ec.message());
  if (!path_strictly_within(real, root)) key.fail(outside + ")");
  // weakly_canonical leaves a dangling link unresolved; what it would point to is unknown.
  if (fs::is_symlink(fs::symlink_status(path, ec)) && !fs::exists(path, ec))
    key.fail("'" + name + "' is a link to a file that does not exist");
  return path;
}

}  // namespace iga
