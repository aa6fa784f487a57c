#pragma once
/// @file
/// The G1 surface of polynomial triangle patches interpolating first-order data over a triangle
/// mesh in 3D (RSD construction; ../shared/notes/rsd-g1-surfaces.md): F = f − Z, f the linear
/// RSD interpolant (Π0 or Π1), Z the per-edge corrections solving the G1 equation
/// s(t)⟨z, w⟩ = Δ on every double edge. Patches live on the flat mesh triangles (barycentric
/// parameters in mesh vertex order); both neighbours of an edge parametrise it identically.

#include <string>
#include <vector>

#include "geometry/rsd/bezier_triangle.hpp"
#include "geometry/rsd/edge_curves.hpp"
#include "geometry/rsd/first_order_data.hpp"
#include "geometry/rsd/rsd_tuple.hpp"
#include "geometry/triangle_surface_mesh.hpp"

namespace iga::rsd {

/// How z is chosen on each double edge.
///  hermite: the §6.1 in-plane construction (default; degree 8 / 9 patches, fold-free under (12));
///  paper:   the paper's z = (δ/ρ)·q with low-degree GCD cofactors (Algorithm 2) in exact rational
///           arithmetic, for reproduction only: it depends on the coordinate frame, folds, and
///           blows up on quasi-uniform meshes (|z| ≈ 1e8 on the icosphere of level 2);
///  none:    no correction (the C0 RSD interpolant, G1 defect ~1e-2).
enum class RsdMethod { hermite, paper, none };

std::string method_name(RsdMethod method);

struct RsdOptions {
  RsdTuple tuple = RsdTuple::pi0;
  RsdMethod method = RsdMethod::hermite;
};

/// Per-surface quality report. Edge quantities are sampled at t = k/20, k = 1..19, on every
/// double edge: V = D_{u_m}F_n, V̄ = D_{ū_m}F_n̄, E = D_{p_j−p_i}F_n.
struct RsdReport {
  int patch_degree = 0;
  int interior_edges = 0, boundary_edges = 0;
  double max_g1_residual = 0;      ///< max |det[V, V̄, E]| / (|V||V̄||E|)
  double max_fold_alpha = 0;       ///< max α with V̄ = αV + βE; α < 0 is a proper join, α > 0 a fold
  double min_regularity = 0;       ///< min |V × E| / (|V||E|) (also over V̄); 0 is a singular point
  double interpolation_residual = 0;  ///< max relative |F(p_i) − f_i|, |D_{p_j−p_i}F(p_i) − g_ij|
  double max_z = 0;                ///< max |z(t)| over edges, t ∈ {0, 1/20, ..., 1}
};

struct RsdSurface {
  TriangleSurfaceMesh mesh;
  std::vector<SurfaceEdge> edges;
  FirstOrderData data;
  RsdOptions options;
  std::vector<BezierTriangle> patches;   ///< one per triangle, all of degree report.patch_degree
  std::vector<VecPoly<double>> z;        ///< per edge (zero on boundary and skipped edges)
  RsdReport report;

  /// Local position (0..2) of global vertex v in triangle n.
  int local_index(int n, int v) const;
};

/// The surface for projected-chord data (f = p, g = tangent-plane projection of the chords).
/// InputError when the data violate (11), (12) or (28), naming the vertex and edge.
RsdSurface build_rsd_surface(const TriangleSurfaceMesh& mesh, const RsdOptions& options = {});

/// The surface for given data (methods hermite and none only: the paper's method needs the exact
/// rational data it derives from the mesh itself).
RsdSurface build_rsd_surface(const TriangleSurfaceMesh& mesh, const FirstOrderData& data,
                             const RsdOptions& options);

/// The end data of double edge `e` as used by the per-edge solvers.
EdgeEndData<double> edge_end_data(const FirstOrderData& data, const SurfaceEdge& e);

}  // namespace iga::rsd
