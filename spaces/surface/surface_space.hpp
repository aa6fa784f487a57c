#pragma once
/// @file
/// C0 Bernstein elements of degree p on a G1 surface in 3D (an RSD surface, geometry/rsd/):
/// every patch's parameter triangle is split into m² congruent sub-triangles (m = 2^level), and
/// each sub-triangle, composed with the patch map, is one element. Refinement splits the
/// sub-triangles of the *fixed* surface, so the spaces are nested and the surface stays the exact
/// geometry at every level (re-running the construction on a finer mesh would change the surface).
///
/// Degrees of freedom are the points of the (m·p)-lattice of every patch, shared across patch
/// edges: both neighbours of an edge parametrise it identically (λ_i along the edge), so equal
/// lattice positions are equal surface points and C0 holds with ordinary sharing.

#include <array>
#include <memory>
#include <vector>

#include "geometry/rsd/rsd_surface.hpp"
#include "geometry/surface_patches.hpp"
#include "spaces/gauss_rule_cache.hpp"
#include "spaces/space.hpp"

namespace iga {

class SurfaceBernsteinSpace : public Space {
 public:
  /// Degree 1..8 Bernstein triangles on `subdivisions`² sub-triangles of every patch. `patches`:
  /// the surface's SurfacePatches when another space already made them (else made here).
  SurfaceBernsteinSpace(std::shared_ptr<const rsd::RsdSurface> surface, int degree, int subdivisions,
                        std::shared_ptr<const SurfacePatches> patches = nullptr);

  std::unique_ptr<Evaluator> make_evaluator() const override;
  void element_dofs(int element, std::vector<int>& out) const override { out = dofs_[element]; }
  RulePtr quadrature(int, int degree) const override { return rules_.triangle(degree); }
  RulePtr edge_quadrature(int, int edge, int degree) const override { return rules_.triangle_edge(edge, degree); }
  /// Every edge shared by two elements, within a patch and across patch edges (the C0 interior
  /// penalty form of the surface biharmonic integrates over them).
  std::vector<InteriorEdge> interior_edges() const override { return interior_; }

  const std::shared_ptr<const rsd::RsdSurface>& shared_surface() const { return surface_; }

 private:
  struct Core;  // the explicit core of the generic evaluator (surface_space.cpp)
  /// One element: its patch and the patch barycentrics of its three corners (counterclockwise).
  struct Element {
    int patch = 0;
    std::array<Eigen::Vector3d, 3> corner;
  };

  std::shared_ptr<const rsd::RsdSurface> surface_;
  int degree_;
  std::vector<Element> elements_;
  std::vector<std::vector<int>> dofs_;   ///< per element, local Bernstein order (bezier_index)
  std::vector<InteriorEdge> interior_;   ///< element edges shared by two elements
  GaussRuleCache rules_;
};

}  // namespace iga
