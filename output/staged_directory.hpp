#pragma once
/// @file
/// A results directory that appears only when complete. Outputs are written into a private
/// temporary directory; commit() moves it into place (replacing an older result). If commit() is
/// never called — a failed run — the temporary directory is removed and nothing is left behind.

#include <string>

namespace iga {

class StagedDirectory {
 public:
  /// Creates the private staging directory; InputError if the temporary directory is unusable.
  explicit StagedDirectory(std::string final_path);
  ~StagedDirectory();
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;

  /// Where to write now.
  const std::string& path() const { return staging_; }
  /// Move the staged outputs to the final path, replacing an earlier result there (never a folder
  /// that is not one: solver/output_location.hpp). Throws std::runtime_error on failure.
  void commit();

 private:
  std::string final_;
  std::string staging_;
  bool committed_ = false;
};

}  // namespace iga
