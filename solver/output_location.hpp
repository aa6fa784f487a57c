#pragma once
/// @file
/// Whether a path can become a results directory, checked while the config is parsed, before any
/// space is built: an unusable output location is an input error found in milliseconds, not after
/// the study (or its level 0) has run.

#include <cstddef>
#include <string>
#include <vector>

namespace iga {

/// Longest output directory accepted, in bytes of its absolute path: half of Linux's PATH_MAX,
/// leaving room for the result files inside.
inline constexpr std::size_t max_output_path_bytes = 2048;
/// Longest name of one folder on the way (NAME_MAX of Linux file systems).
inline constexpr std::size_t max_output_name_bytes = 255;

/// Throw InputError "<place>: output directory '<path>' ..." unless `path` can become a results
/// directory: it is a directory or does not exist, and its nearest existing ancestor is a directory
/// in which a (probe) directory can be created, and what is there may be replaced
/// (replaceable_output_directory). `place` names where the path came from
/// ("--output", "case.yaml:7:14: output.directory", "the default output directory").
/// Also refuses what check_output_path_form refuses, and what check_output_not_above refuses for
/// `config_paths`.
void check_output_directory(const std::string& path, const std::string& place,
                            const std::vector<std::string>& config_paths = {});

/// Whether results may replace what is at `path`: nothing, an empty folder, or an earlier result of
/// iga-run (a folder holding summary.json or comparison.csv). Anything else is somebody's folder,
/// and replacing it as a whole would delete their files.
bool replaceable_output_directory(const std::string& path);

/// Throw InputError "<place>: output directory '<path>' ..." unless `path`, taken from a config's
/// `output.directory`, is a relative path that stays inside the working directory (links of its
/// existing part resolved). A config comes from other people and writes only below the folder the
/// user runs in; the command line's --output is the user's own and may go anywhere.
void check_config_output_directory(const std::string& path, const std::string& place);

/// Throw InputError "<place>: output directory '<path>' is the working directory ..." (or "holds
/// the config FILE") when `path` is the working directory, the folder of one of `config_paths`, or
/// a folder above either: the results replace the output directory as a whole, so the run would
/// end by moving away (or failing to move) the folder it reads from. Paths are compared after
/// resolving symbolic links and "..", so a link to the config's folder is refused as well.
void check_output_not_above(const std::string& path, const std::string& place,
                            const std::vector<std::string>& config_paths);

}  // namespace iga
