#pragma once
/// @file
/// The config side of mesh files, shared by every space that reads them:
/// `domain: {type: mesh_file, file: PATH, mesh_size: h, recombine: true}`. The caller checks which
/// keys its space allows (e.g. no `recombine` for triangle-only spaces).

#include <filesystem>
#include <string>

#include "config/config_node.hpp"
#include "mesh/read_mesh_file.hpp"

namespace iga {

struct MeshFileRequest {
  std::filesystem::path path;  ///< resolve_config_file of `file`: inside the config file's folder
  std::string extension;       ///< path's extension in lower case (".geo", ".xml", ...)
  MeshFileOptions options;
};

/// Reads `file`, `mesh_size` and `recombine` from `domain` (path: resolve_config_file, so a file
/// outside a config file's folder is refused at `file`; options.config_folder: the config file's
/// folder, where a .geo's Includes may also read); `mesh_size` and `recombine` on a file
/// that is not `.geo` (case-insensitive) are rejected at their key, as is mesh_size <= 0.
/// options.limits as mesh_limits(domain).
MeshFileRequest mesh_file_request(const ConfigNode& domain);

/// The mesh limits of the config that `node` belongs to: max_elements from its `limits:` section
/// (limits.max_elements, the same number the study checks each level against), the rest defaults.
MeshLimits mesh_limits(const ConfigNode& node);

}  // namespace iga
