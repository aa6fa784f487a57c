#include "solver/output_location.hpp"

#include <unistd.h>

#include <filesystem>
#include <random>
#include <system_error>

#include "config/config_file_path.hpp"
#include "config/errors.hpp"

namespace iga {

namespace fs = std::filesystem;

namespace {

/// Room the last name needs beyond its own length: the results are moved in beside it as
/// ".NAME.incoming-PID-RANDOM" (output/staged_directory.cpp), at most this many bytes more.
constexpr std::size_t sibling_room = 32;

/// Throw InputError "<place>: output directory '<path>' ..." when `path` cannot work whatever the
/// folders hold: longer than max_output_path_bytes as an absolute path, a name longer than
/// max_output_name_bytes (the last one shorter still: the results move in under a longer name),
/// or a symbolic link on its existing part whose target does not exist (or a loop of links).
/// Part of check_output_directory and check_config_output_directory, and checked before their
/// other reasons, which such a path would only confuse.
void check_output_path_form(const std::string& path, const std::string& place) {
  const auto fail = [&](const std::string& why) {
    throw InputError(place + ": output directory '" + (path.size() > 80 ? path.substr(0, 80) + "..." : path) + "' " +
                     why);
  };
  std::error_code ec;
  const fs::path target = fs::absolute(path, ec);
  if (ec) fail("cannot be resolved: " + ec.message());
  // Refused here, not by the system after the study: a result file inside needs room too.
  if (target.native().size() > max_output_path_bytes)
    fail("is too long: " + std::to_string(target.native().size()) + " bytes as an absolute path, at most " +
         std::to_string(max_output_path_bytes));
  const fs::path normal = target.lexically_normal();
  for (auto it = normal.begin(); it != normal.end(); ++it) {
    const std::size_t size = it->native().size();
    if (size > max_output_name_bytes)
      fail("has a name of " + std::to_string(size) + " bytes ('" + it->native().substr(0, 40) + "...'); a name has at most " +
           std::to_string(max_output_name_bytes));
  }
  const std::size_t last = normal.has_filename() ? normal.filename().native().size() : 0;
  if (last > max_output_name_bytes - sibling_room)
    fail("ends in a name of " + std::to_string(last) + " bytes; the output directory's own name has at most " +
         std::to_string(max_output_name_bytes - sibling_room) + " (the results move in under a longer one)");
  // A dangling link on the way would be taken for a folder still to be made, and fail (or lead
  // elsewhere) only when the results are moved in, after the study.
  fs::path prefix;
  for (const fs::path& part : target) {
    prefix /= part;
    const fs::file_status link = fs::symlink_status(prefix, ec);
    if (ec || !fs::exists(link)) break;  // the rest is still to be made
    if (!fs::is_symlink(link)) continue;
    if (!fs::exists(fs::status(prefix, ec))) {
      const fs::path to = fs::read_symlink(prefix, ec);
      fail("goes through the symbolic link '" + prefix.string() + "'" +
           (to.empty() ? std::string() : " (to '" + to.string() + "')") +
           ", which leads nowhere: its target does not exist (or the links loop)");
    }
  }
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
  check_output_path_form(path, place);
  std::error_code ec;
  const fs::path cwd = fs::weakly_canonical(fs::current_path(ec), ec);
  if (ec) return;  // an unusable working directory is reported by check_output_directory
  const fs::path target = fs::weakly_canonical(cwd / given, ec);
  if (ec || !path_within(target, cwd)) refuse("leads outside the working directory");
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
  if (const fs::path cwd = fs::current_path(ec); !ec && path_within(fs::weakly_canonical(cwd, ec), target))
    refuse("the working directory or a folder above it");
  for (const std::string& config : config_paths) {
    const fs::path folder = fs::weakly_canonical(fs::absolute(config, ec).parent_path(), ec);
    if (!ec && path_within(folder, target)) refuse("the folder of the config '" + config + "' or a folder above it");
  }
}

void check_output_directory(const std::string& path, const std::string& place,
                            const std::vector<std::string>& config_paths) {
  check_output_path_form(path, place);
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
