#pragma once
/// @file
/// TMeshSpace: C^r generalized splines (polynomial / trigonometric / hyperbolic sections) over an
/// admissible T-mesh, as a finite-element space.
///
/// Elements are the mesh cells (in mesh order); the reference square maps affinely onto each cell.
/// Cells may carry different section spaces (mixed spaces of the paper, e.g. its S2).
/// Global functions are the Hermite-DOF basis of hermite_extraction.hpp (vertex jets, edge
/// derivatives, cell bubbles). The local basis of a cell is the tensor generalized Bernstein basis
/// of section_space.hpp; the active functions of a cell are E_c times it (E_c: n_active x (n+1)^2).
/// Each global function is the Hermite-dual function scaled to largest Bernstein coefficient 1.

#include <cstdint>
#include <map>
#include <memory>
#include <tuple>
#include <vector>

#include "spaces/element_core.hpp"
#include "spaces/gauss_rule_cache.hpp"
#include "spaces/space.hpp"
#include "spaces/tmesh/hermite_extraction.hpp"
#include "spaces/tmesh/tmesh.hpp"

namespace iga {

/// Degree a Gauss rule needs beyond the polynomial degree of the integrand for trigonometric or
/// hyperbolic sections with largest w h = `wh` to stay exact to round-off: the smallest even e >= 2
/// with (w h)^(e+1) / (e+1)! <= 1e-17, at most 16; 0 for wh = 0 (polynomial sections).
int non_polynomial_extra_degree(double wh);
/// Extra degree of the rules of trigonometric and hyperbolic sections on coarse cells.
inline constexpr int kFullExtraDegree = 16;

/// Its evaluator is a specialisation (element_core.hpp): evaluate_function sum-factorised over the
/// cell's diagonal map; make_generic_evaluator evaluates the explicit core through the generic path.
class TMeshSpace final : public Space, public LocallyRefinable, public FastEvaluator {
 public:
  /// C^r space on `mesh` (see hermite_extraction.hpp for the conditions on n). `rectangular` names the boundary parts
  /// left/right/bottom/top (otherwise only "all"). Throws std::invalid_argument when the mesh is
  /// not admissible or a trigonometric cell has w h >= pi.
  TMeshSpace(TMesh mesh, int regularity, bool rectangular, std::string domain_description);

  ~TMeshSpace() override;

  /// Facts: type "tmesh"; parameters section, regularity, cells, T-junctions, domain; C^r, affine
  /// cells, higher_derivatives (cells are tensor products of section spaces under a diagonal
  /// scaling: any derivative is exact); boundary parts left, right, bottom, top when rectangular.
  std::unique_ptr<Evaluator> make_evaluator() const override;
  /// The explicit core: tensor section Bernstein basis, Hermite extraction, diagonal affine map.
  std::unique_ptr<Evaluator> make_generic_evaluator() const override;
  void element_dofs(int element, std::vector<int>& out) const override { out = extraction_.dofs[element]; }

  /// Tensor Gauss rule exact for `degree`; for trigonometric / hyperbolic sections exact for a
  /// higher degree, since Gauss rules are not exact for those integrands (notes P6): as many more
  /// as make the rule exact to round-off for the largest w h of the mesh
  /// (non_polynomial_extra_degree), at most 16 (8 points per direction).
  RulePtr quadrature(int element, int degree) const override;
  RulePtr edge_quadrature(int element, int edge, int degree) const override;

  /// E_c K_c E_cᵀ from side integrals (tmesh_closed_forms.hpp).
  const ClosedForms* closed_forms() const override;

  /// One piece per pair of side neighbours, over their common segment: a T-junction edge of a large
  /// cell yields one piece per small cell along it.
  std::vector<InteriorEdge> interior_edges() const override;

  /// Split the marked cells dyadically, plus the cells refine_admissibly adds (2:1 balance, and a
  /// buffer when the result would not be regular and acyclic); same sections and regularity.
  SpacePtr refine(const std::vector<int>& marked_elements) const override;

  const TMesh& mesh() const { return mesh_; }
  const HermiteExtraction& extraction() const { return extraction_; }
  /// The section space of the first cell (all cells share its n).
  const SectionSpec& section() const { return mesh_.sections()[mesh_.cells()[0].section_s]; }
  /// Physical box of a cell.
  void cell_box(int cell, Point2& lo, Point2& hi) const;
  /// A cell side's one-dimensional basis (tmesh.hpp: CellSideKey).
  /// Bernstein basis of a cell side (shared, immutable after construction).
  const SectionBernstein& bernstein(const CellSideKey& side) const { return bernstein_.at(side); }
  /// Every cell side kind of the mesh with its Bernstein basis.
  const std::map<CellSideKey, SectionBernstein>& bernstein_bases() const { return bernstein_; }
  /// Degree every rule gets beyond the polynomial one (non_polynomial_extra_degree).
  int extra_degree() const { return extra_degree_; }

 private:
  struct Core;  // the explicit core and the evaluator specialisation (tmesh_evaluator.cpp)
  class TMeshEvaluator;
  /// Scale every global function to largest Bernstein coefficient 1 (the Hermite DOFs stay the
  /// construction; only the basis is rescaled, so dimension and span are unchanged).
  void normalize_basis();

  TMesh mesh_;
  int r_;
  bool rectangular_;
  std::string domain_;
  HermiteExtraction extraction_;
  std::map<CellSideKey, SectionBernstein> bernstein_;
  /// The local basis of every cell: an index into the distinct pairs (side x, side y) of kinds_.
  std::vector<int> cell_kind_;
  std::vector<std::pair<CellSideKey, CellSideKey>> kinds_;
  std::unique_ptr<const ClosedForms> closed_forms_;
  int extra_degree_ = 0;
  GaussRuleCache rules_;
};

}  // namespace iga
