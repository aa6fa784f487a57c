#pragma once
/// @file
/// Where a file that a config names (a mesh, a geometry) is read from. A config file comes from
/// other people: what it names may be read only inside its own folder, never "../x", "/etc/x" or a
/// link beside it that points out. A config built from text (load_string: library calls from C++
/// or Python, tests) is the caller's own and has no folder to be confined to.

#include <filesystem>

#include "config/config_node.hpp"

namespace iga {

/// The file named by the scalar `key` (e.g. domain.file), as the path to open.
/// From a config file (ConfigNode::load_file): a relative name is taken in the config file's
/// folder, and the file, links resolved, must lie inside that folder (canonical), or InputError at
/// `key` "'NAME' is outside the config's folder ..." before anything is opened; an absolute name
/// is refused the same way. A link that points nowhere is refused too (where it would point cannot
/// be checked). A file that does not exist is returned as named: its reader says it cannot read it.
/// From load_string: a relative name is taken in the folder of the config's name (the working
/// directory for the default "<string>"), and nothing is confined.
std::filesystem::path resolve_config_file(const ConfigNode& key);

/// Whether `inner` is `outer` or lies below it, compared by components after lexical normalisation
/// ("/a/bc" is not below "/a/b"; a trailing separator names the same folder). Both should be
/// absolute with links resolved (fs::canonical / weakly_canonical): this looks at names only.
bool path_within(const std::filesystem::path& inner, const std::filesystem::path& outer);

/// path_within, and not `outer` itself.
bool path_strictly_within(const std::filesystem::path& inner, const std::filesystem::path& outer);

/// The folder that files named in `node`'s config are taken relative to: the config file's
/// folder, or the folder of the name given to load_string ("." when it has none).
std::filesystem::path config_folder(const ConfigNode& node);

}  // namespace iga
