#pragma once
/// @file
/// Gluing values at the vertices of a planar quad mesh taken from the mesh's own edge directions
/// (the fan-vector construction of the note, §3.2, restricted to b ≡ −1).
///
/// Why: the symmetric values 2cos(2π/n) ask the geometry to look like an affine image of the
/// regular n-fan at every vertex; the least-squares fit of a mesh whose fans are far from regular
/// (a Gmsh recombination) is then strongly distorted and the error constants grow by orders of
/// magnitude. With b ≡ −1 a fan u₁..u_n is admissible iff consecutive sectors have equal area,
/// det(u_{i−1}, u_i) = c (then a_i = det(u_{i−1}, u_{i+1}) / c and Condition 1 holds). Taking
/// u_i = λ_i d_i along the mesh's edge directions d_i, the areas give λ_{i−1} λ_i det(d_{i−1}, d_i) = c:
/// in logarithms a cyclic system l_{i−1} + l_i = −log s_i, uniquely solvable for odd n, solvable for
/// even n only if Π s_odd = Π s_even; at a boundary vertex (F sectors, F + 1 edges) one equation
/// short (the minimum-norm solution is taken). The fitted geometry then keeps the mesh's edge
/// directions at those vertices and only reparametrizes the edges.
/// Where no such fan exists (even valence with unequal products, a sector ≥ π, valence 4 inside,
/// which line_gluing handles), the symmetric value is kept.

#include <map>
#include <vector>

#include "spaces/g1/patch_mesh.hpp"
#include "spaces/g1_4split/line_gluing.hpp"
#include "spaces/g1_4split/quad_topology.hpp"

namespace iga {

/// Per vertex, the outward gluing value of each of its interior edges (edge id -> A); empty for
/// vertices that keep the symmetric value. `topology` = quad_topology(mesh).
std::vector<std::map<int, double>> fan_gluing_values(const PatchMesh& mesh, const QuadTopology& topology);

/// The default (`lines`) gluing of a planar mesh: vertexwise_gluing of the fan values (the symmetric
/// value where a vertex has none); line_gluing of the symmetric values where that fails.
std::vector<SplitGluing> planar_line_gluing(const PatchMesh& mesh, const QuadTopology& topology,
                                            LineGluingReport* report = nullptr);

}  // namespace iga
