#pragma once
/// @file
/// A structural check of a Gmsh `.msh` file in our own code, before Gmsh reads it: Gmsh's reader
/// trusts the file (a node tag that no node has crashes it), so only files that pass are handed on.

#include <string>

#include "mesh/mesh_limits.hpp"

namespace iga {

/// Accepts ASCII MSH 2.x (2.0-2.2) and 4.1 only. Refuses, with an InputError "<path>:<line>: ...":
/// a binary file; a missing $MeshFormat (first), $Nodes or $Elements section, or a repeated one; a
/// section not closed by its $End line; counts that do not match the lines that follow (nodes,
/// elements, blocks, physical names, entities); node or element tags that are not integers in
/// [1, 2^31), repeated, or outside the declared [min, max] (4.1); non-finite coordinates; an element
/// type Gmsh does not define or a line with the wrong number of node tags for its type; elements
/// that use nodes the file does not define; 4.1 blocks on entities the $Entities section does not
/// define; partitioned meshes. Resource limits: more than 4 x limits.max_elements nodes or elements
/// (all dimensions) in a section header is refused before anything is read, more than
/// limits.max_elements 2D elements after the count.
void check_msh_structure(const std::string& path, const MeshLimits& limits = {});

}  // namespace iga
