#pragma once
/// @file
/// Whether a path can become a results directory, checked while the config is parsed, before any
/// space is built: an unusable output location is an input error found in milliseconds, not after
/// the study (or its level 0) has run.

#include <string>
#include <vector>

namespace iga {

/// Throw InputError "<place>: output directory '<path>' ..." unless `path` can become a results
/// directory: it is a directory or does not exist, and its nearest existing ancestor is a directory
/// in which a (probe) directory can be created. `place` names where the path came from
/// ("--output", "case.yaml:7:14: output.directory", "the default output directory").
/// Also refuses what check_output_not_above refuses for `config_paths`.
void check_output_directory(const std::string& path, const std::string& place,
                            const std::vector<std::string>& config_paths = {});

/// Throw InputError "<place>: output directory '<path>' is the working directory ..." (or "holds
/// the config FILE") when `path` is the working directory, the folder of one of `config_paths`, or
/// a folder above either: the results replace the output directory as a whole, so the run would
/// end by moving away (or failing to move) the folder it reads from. Paths are compared after
/// resolving symbolic links and "..", so a link to the config's folder is refused as well.
void check_output_not_above(const std::string& path, const std::string& place,
                            const std::vector<std::string>& config_paths);

}  // namespace iga
