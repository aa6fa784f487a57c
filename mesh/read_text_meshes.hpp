#pragma once
/// @file
/// Readers of the plain-text mesh formats (see read_mesh_file.hpp for what they accept).

#include <istream>
#include <string>

#include "mesh/planar_mesh.hpp"

namespace iga {

/// Wavefront OBJ from `in`; `source` names the file in messages ("<source>:<line>: ...").
PlanarMesh read_obj_mesh(std::istream& in, const std::string& source);

/// Object File Format (OFF) from `in`; `source` names the file in messages.
PlanarMesh read_off_mesh(std::istream& in, const std::string& source);

}  // namespace iga
