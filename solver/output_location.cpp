#include "solver/output_location.hpp"

#include <unistd.h>

#include <filesystem>
#include <random>
#include <system_error>

#include "config/errors.hpp"

namespace iga {

namespace fs = std::filesystem;

namespace {

/// Whether `outer` is `inner` or one of its ancestors (both absolute, links resolved).
bool encloses(const fs::path& outer, const fs::path& inner) {
  const auto trimmed = [](fs::path p) {  // "/a/b/" -> "/a/b": a trailing separator names the same folder
    p = p.lexically_normal();
    return !p.has_filename() && p.has_relative_path() ? p.parent_path() : p;
  };
  const fs::path rel = trimmed(inner).lexically_relative(trimmed(outer));
  return !rel.empty() && *rel.begin() != "..";
}

}  // namespace

bool replaceable_output_directory(const std::string& path) {
  std::error_code ec;
  const fs::path target = fs::absolute(path, ec);
  if (ec || !fs::is_directory(target, ec)) return true;  // nothing there (a file is refused elsewhere)
  if (fs::is_empty(target, ec) && !ec) return true;
  return fs::is_regular_file(target / "summary.json", ec) || fs::is_regular_file(target / "comparison.csv", ec);
}

void check_config_output_directory(const std::string& path, const std::string& place) {
  const auto refuse = [&](const std::string& why) {
    throw InputError(place + ": output directory '" + path + "' " + why +
                     ": a config writes only inside the working directory (give a relative path such as "
                     "results/NAME, or choose the place with --output)");
  };
  const fs::path given(path);
  if (given.is_absolute()) refuse("is an absolute path");
  std::error_code ec;
  const fs::path cwd = fs::weakly_canonical(fs::current_path(ec), ec);
  if (ec) return;  // an unusable working directory is reported by check_output_directory
  const fs::path target = fs::weakly_canonical(cwd / given, ec);
  const fs::path rel = target.lexically_relative(cwd);
  if (ec || rel.empty() || *rel.begin() == "..") refuse("leads outside the working directory");
}

void check_output_not_above(const std::string& path, const std::string& place,
                            const std::vector<std::string>& config_paths) {
  std::error_code ec;
  const fs::path target = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec || target.empty()) return;  // check_output_directory names an unresolvable path
  const auto refuse = [&](const std::string& what) {
    throw InputError(place + ": output directory '" + path + "' is " + what +
                     ": the results replace the output directory as a whole; give a folder of their own, such as "
                     "results/NAME");
  };
  if (const fs::path cwd = fs::current_path(ec); !ec && encloses(target, fs::weakly_canonical(cwd, ec)))
    refuse("the working directory or a folder above it");
  for (const std::string& config : config_paths) {
    const fs::path folder = fs::weakly_canonical(fs::absolute(config, ec).parent_path(), ec);
    if (!ec && encloses(target, folder)) refuse("the folder of the config '" + config + "' or a folder above it");
  }
}

void check_output_directory(const std::string& path, const std::string& place,
                            const std::vector<std::string>& config_paths) {
  check_output_not_above(path, place, config_paths);
  const auto fail = [&](const std::string& why) {
    throw InputError(place + ": output directory '" + path + "' " + why);
  };
  std::error_code ec;
  const fs::path target = fs::absolute(path, ec);
  if (ec) fail("cannot be resolved: " + ec.message());
  if (fs::exists(target, ec) && !fs::is_directory(target, ec)) fail("exists and is not a directory");
  if (!replaceable_output_directory(path))
    fail("exists and is not an earlier result of iga-run (no summary.json or comparison.csv in it): the results "
         "replace the directory as a whole and would delete its files; remove it or choose another");
  fs::path ancestor = target.parent_path();
  while (!ancestor.empty() && !fs::exists(ancestor, ec) && ancestor != ancestor.parent_path())
    ancestor = ancestor.parent_path();
  if (!fs::is_directory(ancestor, ec)) fail("cannot be created: '" + ancestor.string() + "' is not a directory");
  if (::access(ancestor.c_str(), W_OK) != 0) fail("cannot be created: '" + ancestor.string() + "' is not writable");
  // Permission bits do not tell everything (root passes access(), /proc refuses new entries, a
  // read-only mount, a full disk): create and remove a probe directory where the results will go.
  std::random_device rd;
  std::string name(".");  // appended, not "." + string: GCC 12 warns wrongly (-Wrestrict) about that
  name += target.filename().string();
  name += ".probe-" + std::to_string(::getpid()) + "-" + std::to_string(rd() % 1000000);
  const fs::path probe = ancestor / name;
  if (!fs::create_directory(probe, ec) || ec)
    fail("cannot be created: no directory can be made in '" + ancestor.string() + "'" +
         (ec ? ": " + ec.message() : std::string()));
  fs::remove(probe, ec);
}

}  // namespace iga
