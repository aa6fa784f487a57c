#pragma once
/// @file
/// SurfacePatchSpace: tensor-product B-splines of degree p on one NURBS patch in 3D
/// (NurbsSurfaceMap), with periodic directions (cylinders and tori close up) and open ones.
///
/// The functions are polynomial B-splines N_i(u) M_j(v) in the patch parameter composed with the
/// inverse of the exact map x(u, v): the geometry is exact at every level, so rates are not hidden
/// behind a geometric error. The space's breakpoints contain the map's (each geometry span split
/// into equal elements), and its continuity at a map breakpoint is min(r, the map's measured
/// continuity there) (NurbsSurfaceMap::measured_continuity): C1 at the joints of the exact circles,
/// C^r elsewhere — so the space is C1 on the surface whenever the map is C1, and a smooth u ∘ x
/// lies in it piece by piece (no second-derivative kink of the map inside a C² region).
///
/// Numbering as TensorBSplineSpace: elements ex + ey n_ex, global functions i + j n_u, active
/// functions a + b (p+1) (a along u), local basis the tensor Bernstein basis of the reference square
/// mapped affinely onto the element's parameter box. Evaluated by the generic ExtractedEvaluator on
/// a surface core (C_e = C_v ⊗ C_u, jets of the map). Boundary parts: left (u = 0), right (u = 1),
/// bottom (v = 0), top (v = 1), only for open directions.

#include <memory>
#include <vector>

#include <Eigen/SparseCore>

#include "spaces/gauss_rule_cache.hpp"
#include "spaces/lifted_space.hpp"
#include "spaces/space.hpp"
#include "spaces/surface_patch/nurbs_surface_map.hpp"
#include "spaces/surface_patch/spline_direction.hpp"

namespace iga {

class SurfacePatchSpace : public Space {
 public:
  /// Degree p ≥ 1, `elements` per direction (a multiple of the map's spans in that
  /// direction, each span split evenly), interior regularity r (0 ≤ r ≤ p − 1). Throws
  /// std::invalid_argument on inconsistent counts (the config reader says which key).
  SurfacePatchSpace(std::shared_ptr<const NurbsSurfaceMap> map, int degree, int regularity, std::array<int, 2> elements);

  std::unique_ptr<Evaluator> make_evaluator() const override;
  void element_dofs(int element, std::vector<int>& out) const override { out = dofs_[element]; }
  RulePtr quadrature(int, int degree) const override { return rules_.cell(degree); }
  RulePtr edge_quadrature(int, int edge, int degree) const override { return rules_.edge(edge, degree); }
  /// Every shared element edge once, the periodic seams included.
  std::vector<InteriorEdge> interior_edges() const override;

  const NurbsSurfaceMap& map() const { return *map_; }
  const SplineDirection& direction(int d) const { return dir_[d]; }
  int num_elements_u() const { return dir_[0].num_elements(); }
  /// The map's jets at the points of `rule` on element e (reference square → parameter box → x).
  void element_jets(int element, const QuadratureRule& rule, bool second, std::vector<SurfaceJet>& jets) const;
  /// Parameter point of reference point r on element e.
  Point2 parameter(int element, const Point2& r) const;

 private:
  struct Core;
  SpaceFacts make_facts(int regularity) const;

  std::shared_ptr<const NurbsSurfaceMap> map_;
  SplineDirection dir_[2];
  std::vector<int> geometry_span_[2];                 ///< the map's span of each element column / row
  std::vector<std::vector<int>> dofs_;
  std::vector<Eigen::SparseMatrix<double>> extraction_;  ///< local × active (column-major), per element
  GaussRuleCache rules_;
};

/// A patch with no periodic direction is the lift of its parameter square: it answers LiftedSpace
/// with the planar B-spline space on [0, 1]² with the same knots (same numbering and elements), so
/// that clamped conditions of fourth-order problems run through the planar boundary machinery with
/// the data pulled back through x (spaces/lifted_space.hpp).
class OpenSurfacePatchSpace final : public SurfacePatchSpace, public LiftedSpace {
 public:
  OpenSurfacePatchSpace(std::shared_ptr<const NurbsSurfaceMap> map, int degree, int regularity,
                        std::array<int, 2> elements);
  const Space& planar() const override { return *planar_; }
  Eigen::Vector3d lift(const Point2& p) const override { return map().point(p); }
  Eigen::Matrix<double, 3, 2> lift_jacobian(const Point2& p) const override;

 private:
  SpacePtr planar_;
};

/// The space for `map`: OpenSurfacePatchSpace when no direction is periodic.
SpacePtr make_surface_patch_space(std::shared_ptr<const NurbsSurfaceMap> map, int degree, int regularity,
                                  std::array<int, 2> elements);

}  // namespace iga
