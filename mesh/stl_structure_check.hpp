#pragma once
/// @file
/// A structural check of an STL file in our own code, before the Gmsh worker reads it (Gmsh
/// trusts a file's counts and numbers).

#include <string>

#include "mesh/mesh_limits.hpp"

namespace iga {

/// Accepts binary STL (80-byte header, triangle count, 50 bytes per triangle: the file size must
/// match the count exactly) and ASCII STL (`solid` ... `facet normal` / `outer loop` / three
/// `vertex x y z` / `endloop` / `endfacet` ... `endsolid`, one or more solids). Refuses, with an
/// InputError "<path>: ..." (ASCII: "<path>:<line>: ..."), anything else: a truncated or padded
/// binary file, a missing or misplaced keyword, a facet without three vertices, a coordinate that
/// is not a finite number, an empty file, and more than limits.max_elements triangles.
void check_stl_structure(const std::string& path, const MeshLimits& limits = {});

}  // namespace iga
