#pragma once
/// @file
/// Files that belong to the program, found where it runs: next to the executable (the build tree),
/// else at paths compiled in (an installed tree). Never a folder a config names.
#include <filesystem>
#include <string>
#include <vector>

namespace iga {

/// The first regular file among `name` beside the running executable, then `relative` paths
/// (resolved from the executable's folder), then `absolute` ones. Throws std::runtime_error
/// naming what was looked for (`what`) and every place looked in.
std::filesystem::path find_companion_file(const std::string& what, const std::string& name,
                                          const std::vector<std::string>& relative,
                                          const std::vector<std::string>& absolute);

}  // namespace iga
