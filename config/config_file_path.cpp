#include "config/config_file_path.hpp"

#include <system_error>

namespace iga {

namespace fs = std::filesystem;

namespace {

/// Whether `inner` lies strictly below `outer` (both canonical): compared component by component,
/// so "/a/bc" is not below "/a/b".
bool strictly_below(const fs::path& inner, const fs::path& outer) {
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i) {
    if (o->empty()) continue;  // a trailing separator of the folder
    if (i == inner.end() || *i != *o) return false;
  }
  for (; i != inner.end(); ++i)
    if (!i->empty()) return true;
  return false;
}

}  // namespace

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
  if (!strictly_below(real, root)) key.fail(outside + ")");
  // weakly_canonical leaves a dangling link unresolved; what it would point to is unknown.
  if (fs::is_symlink(fs::symlink_status(path, ec)) && !fs::exists(path, ec))
    key.fail("'" + name + "' is a link to a file that does not exist");
  return path;
}

}  // namespace iga
