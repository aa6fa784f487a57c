#pragma once
/// @file
/// Whether a path can become a results directory, checked while the config is parsed, before any
/// space is built: an unusable output location is an input error found in milliseconds, not after
/// the study (or its level 0) has run.

#include <string>

namespace iga {

/// Throw InputError "<place>: output directory '<path>' ..." unless `path` can become a results
/// directory: it is a directory or does not exist, and its nearest existing ancestor is a directory
/// in which a (probe) directory can be created. `place` names where the path came from
/// ("--output", "case.yaml:7:14: output.directory", "the default output directory").
void check_output_directory(const std::string& path, const std::string& place);

}  // namespace iga
