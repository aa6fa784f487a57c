#pragma once
/// @file
/// The mesh fuzz targets: read a text mesh and validate it as every space would.

#include <sstream>
#include <string>

#include "fuzz/fuzz_support.hpp"
#include "mesh/planar_mesh.hpp"
#include "mesh/validate_planar_mesh.hpp"

namespace iga::fuzz {

/// Reads `text` with `read` (read_obj_mesh or read_off_mesh), then validates the mesh for spaces
/// taking triangles and quadrilaterals, and for triangles only (WS4).
template <class Reader>
void read_and_validate(const std::string& text, Reader read, const char* source) {
  expect_input_error([&] {
    std::istringstream in(text);
    const PlanarMesh mesh = read(in, source);
    expect_input_error([&] { validate_planar_mesh(mesh); });
    expect_input_error([&] { validate_planar_mesh(mesh, {true, false, "ws4"}); });
  });
}

}  // namespace iga::fuzz
