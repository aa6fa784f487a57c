#include "output/staged_directory.hpp"

#include <unistd.h>

#include "config/errors.hpp"
#include "solver/output_location.hpp"

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
/// ".NAME<tag><unique>": a hidden sibling of `target`. Built by appending (GCC 12 warns, wrongly,
/// about `"." + std::string` with -Wrestrict).
std::string hidden_sibling(const fs::path& target, const char* tag) {
  std::string name(".");
  name += target.filename().string();
  name += tag;
  name += unique_suffix();
  return name;
}

}  // namespace

StagedDirectory::StagedDirectory(std::string final_path) : final_(std::move(final_path)) {
  // Staging lives in the system temp directory so that a failed run creates nothing beside the
  // final path (not even its parent folders).
  std::error_code ec;
  const fs::path temp = fs::temp_directory_path(ec);
  if (ec) throw InputError("cannot stage the outputs: no usable temporary directory (TMPDIR): " + ec.message());
  staging_ = (temp / ("iga-run-" + unique_suffix())).string();
  if (!fs::create_directories(staging_, ec) || ec)
    throw InputError("cannot stage the outputs in '" + temp.string() + "' (TMPDIR)" +
                     (ec ? ": " + ec.message() : std::string()));
}

StagedDirectory::~StagedDirectory() {
  std::error_code ec;
  if (!committed_) fs::remove_all(staging_, ec);
}

void StagedDirectory::commit() {
  const fs::path target = fs::absolute(final_);
  // Checked before the study too; again here, since the folder may have changed during the run.
  if (!replaceable_output_directory(final_))
    throw std::runtime_error("output directory '" + final_ + "' is no longer empty or an earlier result of iga-run; "
                             "it was left untouched (the results are not written)");
  if (target.has_parent_path()) fs::create_directories(target.parent_path());
  // Move next to the target first (a rename when the temp dir is on the same file system, else a
  // copy: hundreds of MB of VTK files are not copied for nothing), then swap by renames, which are
  // atomic within one file system.
  const fs::path incoming = target.parent_path() / hidden_sibling(target, ".incoming-");
  const fs::path old = target.parent_path() / hidden_sibling(target, ".old-");
  std::error_code ec;
  bool replaced = false;
  try {
    fs::rename(staging_, incoming, ec);
    if (ec) fs::copy(staging_, incoming, fs::copy_options::recursive);
    replaced = fs::exists(target);
    if (replaced) fs::rename(target, old);
    fs::rename(incoming, target);
  } catch (...) {
    // Roll back: no half-copied result, and an earlier result back in its place.
    fs::remove_all(incoming, ec);
    if (replaced && !fs::exists(target, ec)) fs::rename(old, target, ec);
    throw;
  }
  if (replaced) fs::remove_all(old, ec);
  fs::remove_all(staging_, ec);
  committed_ = true;
}

}  // namespace iga
