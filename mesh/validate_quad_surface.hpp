#pragma once
/// @file
/// Geometric checks of a quad surface file (read_quad_surface_mesh.hpp) before a space is built
/// on it: what the topology (the space's QuadTopology) cannot see. Every failure is an InputError
/// naming the file and the faces (with their file lines) or vertices.

#include "mesh/read_quad_surface_mesh.hpp"

namespace iga {

/// Rejects, in this order: a face that repeats a vertex; two faces on the same four vertices
/// (a repeated face, either way round); two vertices used by faces closer than tol x (mesh
/// diameter); a degenerate face (vector area <= tol x longest edge², tol = mesh_tolerance of
/// validate_planar_mesh.hpp); a face folded or not convex (a corner whose cross product, along the
/// face's normal, is <= tol x longest edge²); an edge of more than two faces. The tolerances are
/// relative, so the checks do not depend on the mesh's scale. Nearly degenerate faces are left to
/// the space, which certifies the regularity of the surface it fits.
void validate_quad_surface(const QuadSurfaceFile& mesh);

}  // namespace iga
