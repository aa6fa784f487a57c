#pragma once
/// @file
/// The surface of a space on a surface in 3D (ambient_dimension() == 3) as a shaded triangle mesh
/// with point normals, through write_surface_vtu: every element sampled like the solution, its
/// unit normals taken from the element map's Jacobian (x_ξ × x_η), so ParaView shades the surface
/// the way its tangent planes lie.

#include <string>

#include "spaces/space.hpp"

namespace iga {

/// Writes `filename` (.vtu): `samples` intervals per element edge, quads split into triangles,
/// point field `Normals` (oriented away from the centroid of the sampled surface, element by
/// element, since faces need not be consistently oriented) and cell field `patch` (the element).
/// std::invalid_argument for a planar space; std::runtime_error if writing fails.
void write_surface_geometry_vtu(const Space& space, int samples, const std::string& filename);

}  // namespace iga
