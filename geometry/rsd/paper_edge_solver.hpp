#pragma once
/// @file
/// The paper's per-edge solution z = (δ/ρ)·q (note §3.4–3.6: ρ = gcd(w), q low-degree GCD
/// cofactors by Algorithm 2, corrected: column K, zero entries untouched), in exact rational
/// arithmetic (GiNaC numbers). For reproduction of its failure modes only (note §5.2–5.6).

#include <vector>

#include "geometry/rsd/edge_curves.hpp"
#include "geometry/rsd/exact_rational.hpp"
#include "geometry/rsd/first_order_data.hpp"
#include "geometry/triangle_surface_mesh.hpp"

namespace iga::rsd {

/// Result of Algorithm 2 on (a_1, ..., a_K): the monic gcd, cofactors with Σ q_k a_k = gcd, and
/// the number of elimination steps.
template <class T>
struct GcdCofactors {
  Poly<T> gcd;
  std::vector<Poly<T>> q;
  int steps = 0;
};

/// Algorithm 2 (paper Appendix A, made precise in note §3.6) over exact rationals.
GcdCofactors<GiNaC::numeric> gcd_cofactors(const std::vector<Poly<GiNaC::numeric>>& a);

/// The paper's z for one edge from exact end data; NumericalError if Δ is not divisible by
/// t²(1−t)² or δ not by ρ (impossible for exactly coplanar data).
VecPoly<GiNaC::numeric> solve_edge_paper(RsdTuple tuple, const EdgeEndData<GiNaC::numeric>& data);

/// The paper's z on every double edge of `mesh` (zero on boundary edges). The mesh points and
/// normals are rounded to multiples of 2^−30 and the projected chords computed exactly from them,
/// so that coplanarity (28) and the divisibility of Δ are exact; `data` receives those data in
/// double precision (the patches are built from them). The rounding keeps exact structure only
/// where the coordinates are dyadic: the octahedron and tetrahedron reproduce the note's degrees
/// 12 / 15 and folds, while the perturbed octahedron (coordinates like 11/10, normalised fan
/// normals) loses its exact valence-4 common factor ρ and blows up (|z| ≈ 1e12) instead of the
/// note's degree-12 surface with α = +111 computed from exact rational fan normals.
std::vector<VecPoly<double>> paper_corrections(RsdTuple tuple, const TriangleSurfaceMesh& mesh,
                                               const std::vector<SurfaceEdge>& edges, FirstOrderData& data);

}  // namespace iga::rsd
