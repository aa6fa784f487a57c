#include "mesh/mesh_file_from_config.hpp"

#include <cctype>
#include <string>

#include "config/config_file_path.hpp"
#include "config/resource_limits.hpp"

namespace iga {

MeshLimits mesh_limits(const ConfigNode& node) {
  MeshLimits limits;
  limits.max_elements = parse_limits(node.root().find("limits")).max_elements;
  return limits;
}

MeshFileRequest mesh_file_request(const ConfigNode& domain) {
  MeshFileRequest request;
  const ConfigNode file = domain["file"];
  request.path = resolve_config_file(file);
  request.options.config_folder = config_folder(file).string();
  request.extension = request.path.extension().string();
  for (char& c : request.extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  // Named at the config key here; read_mesh_file would refuse them too, but at the file.
  for (const char* key : {"mesh_size", "recombine"})
    if (const auto n = domain.find(key); n && request.extension != ".geo")
      n->fail(std::string(key) + " applies to .geo files only (a mesh file is used as it is)");
  if (const auto n = domain.find("mesh_size")) {
    request.options.mesh_size = n->as_double();
    if (!(request.options.mesh_size > 0.0)) n->fail("mesh_size must be > 0");
  }
  if (const auto n = domain.find("recombine")) request.options.recombine = n->as_bool();
  request.options.limits = mesh_limits(domain);
  return request;
}

}  // namespace iga
