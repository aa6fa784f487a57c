#include "solver/staged_directory.hpp"

#include <unistd.h>

#include <filesystem>
#include <random>
#include <stdexcept>
#include <system_error>

namespace iga {

namespace fs = std::filesystem;

namespace {
std::string unique_suffix() {
  std::random_device rd;
  return std::to_string(::getpid()) + "-" + std::to_string(rd() % 1000000);
}
}  // namespace

StagedDirectory::StagedDirectory(std::string final_path) : final_(std::move(final_path)) {
  // Staging lives in the system temp directory so that a failed run creates nothing beside the
  // final path (not even its parent folders).
  staging_ = (fs::temp_directory_path() / ("iga-run-" + unique_suffix())).string();
  fs::create_directories(staging_);
}

StagedDirectory::~StagedDirectory() {
  std::error_code ec;
  if (!committed_) fs::remove_all(staging_, ec);
}

void StagedDirectory::commit() {
  const fs::path target = fs::absolute(final_);
  if (target.has_parent_path()) fs::create_directories(target.parent_path());
  // Copy next to the target first (the temp dir may be on another file system), then swap by
  // renames, which are atomic within one file system.
  const fs::path incoming = target.parent_path() / ("." + target.filename().string() + ".incoming-" + unique_suffix());
  fs::copy(staging_, incoming, fs::copy_options::recursive);
  const fs::path old = target.parent_path() / ("." + target.filename().string() + ".old-" + unique_suffix());
  const bool replace = fs::exists(target);
  if (replace) fs::rename(target, old);
  fs::rename(incoming, target);
  std::error_code ec;
  if (replace) fs::remove_all(old, ec);
  fs::remove_all(staging_, ec);
  committed_ = true;
}

}  // namespace iga
