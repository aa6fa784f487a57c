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
#include <mutex>
#include <vector>

#include "spaces/space.hpp"
#include "spaces/tmesh/hermite_extraction.hpp"
#include "spaces/tmesh/tmesh.hpp"

namespace iga {

/// Degree a Gauss rule needs beyond the polynomial degree of the integrand for trigonometric or
/// hyperbolic sections with largest w h = `wh` to stay exact to round-off: the smallest even e >= 2
/// with (w h)^(e+1) / (e+1)! <= 1e-17, at most 16; 0 for wh = 0 (polynomial sections).
int non_polynomial_extra_degree(double wh);

class TMeshSpace final : public Space {
 public:
  /// C^r space on `mesh` (see hermite_extraction.hpp for the conditions on n). `rectangular` names the boundary parts
  /// left/right/bottom/top (otherwise only "all"). Throws std::invalid_argument when the mesh is
  /// not admissible or a trigonometric cell has w h >= pi.
  TMeshSpace(TMesh mesh, int regularity, bool rectangular, std::string domain_description);

  std::unique_ptr<Evaluator> make_evaluator() const override;
  std::string type() const override { return "tmesh"; }
  /// section, regularity, cells, T-junctions, domain.
  std::vector<std::pair<std::string, std::string>> parameters() const override;

  int dimension() const override { return extraction_.dimension; }
  void element_dofs(int element, std::vector<int>& out) const override { out = extraction_.dofs[element]; }
  int num_elements() const override { return mesh_.num_cells(); }
  CellShape cell_shape(int) const override { return CellShape::quadrilateral; }
  double mesh_size() const override { return mesh_size_; }
  int degree() const override { return section().n; }
  int continuity() const override { return r_; }
  bool affine_elements() const override { return true; }
  /// Cells are tensor products of section spaces under a diagonal scaling: any derivative is exact.
  bool higher_derivatives() const override { return true; }

  /// Tensor Gauss rule exact for `degree`; for trigonometric / hyperbolic sections exact for a
  /// higher degree, since Gauss rules are not exact for those integrands (notes P6): as many more
  /// as make the rule exact to round-off for the largest w h of the mesh
  /// (non_polynomial_extra_degree), at most 16 (8 points per direction).
  RulePtr quadrature(int element, int degree) const override;
  RulePtr edge_quadrature(int element, int edge, int degree) const override;

  /// The cell map is a diagonal scaling and the local basis a tensor product, so every form is a
  /// sum of Kronecker products of 1D integrals ∫ B_i^(a) B_k^(b) over the cell's sides: E_c K_c E_cᵀ
  /// with K_c from side integrals computed once per (section, side length) with the Gauss rule of
  /// assembly (2n + 1, plus 16 for non-polynomial sections: the coarse-cell rule, i.e. the tensor
  /// rule's sums, separated; finer than quadrature() on fine cells). Accumulated in long double.
  bool closed_form_element_matrix(int element, BilinearForm form, Eigen::MatrixXd& local) const override;
  bool closed_form_element_matrix_extended(int element, BilinearForm form,
                                           Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>& local) const override;
  /// The same closed form in double-double, for the solver's residuals (the long double sums would
  /// bring back the plates' round-off floor): side integrals summed from exact products, K_c per
  /// (form, sections, side lengths) computed once per thread, then E_c K_c E_cᵀ skipping the zeros
  /// of E_c and filling one triangle; cells with the same K_c and E_c reuse the result.
  bool closed_form_element_matrix_double_double(int element, BilinearForm form, DoubleDoubleMatrix& local) const override;

  std::vector<std::string> boundary_names() const override;
  std::vector<BoundaryEdge> boundary_edges(const std::string& name) const override;

  /// One piece per pair of side neighbours, over their common segment: a T-junction edge of a large
  /// cell yields one piece per small cell along it.
  std::vector<InteriorEdge> interior_edges() const override;

  /// Split the marked cells dyadically, plus the cells refine_admissibly adds (2:1 balance, and a
  /// buffer when the result would not be regular and acyclic); same sections and regularity.
  SpacePtr refined(const std::vector<int>& marked_elements) const override;

  const TMesh& mesh() const { return mesh_; }
  const HermiteExtraction& extraction() const { return extraction_; }
  /// The section space of the first cell (all cells share its n).
  const SectionSpec& section() const { return mesh_.sections()[mesh_.cells()[0].section_s]; }
  int regularity() const { return r_; }
  /// Physical box of a cell.
  void cell_box(int cell, Point2& lo, Point2& hi) const;
  /// Bernstein basis of section `section` on a cell side of that lattice length (shared, immutable
  /// after construction).
  const SectionBernstein& bernstein(int section, std::int64_t length) const { return bernstein_.at({section, length}); }

 private:
  class TMeshEvaluator;
  /// Scale every global function to largest Bernstein coefficient 1 (the Hermite DOFs stay the
  /// construction; only the basis is rescaled, so dimension and span are unchanged).
  void normalize_basis();

  TMesh mesh_;
  int r_;
  bool rectangular_;
  std::string domain_;
  HermiteExtraction extraction_;
  std::map<std::pair<int, std::int64_t>, SectionBernstein> bernstein_;
  /// Per (section, side length): side(a, b)(i, k) = ∫_0^1 ∂^a B_i ∂^b B_k in reference coordinates
  /// (a, b <= 2, index 3 a + b).
  struct SideIntegrals {
    Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic> m[9];
  };
  std::map<std::pair<int, std::int64_t>, SideIntegrals> side_integrals_;
  /// The same side integrals in double-double ((n+1)^2 entries each, column-major).
  struct SideIntegralsDD {
    int size = 0;
    std::vector<DoubleDouble> m[9];
  };
  std::map<std::pair<int, std::int64_t>, SideIntegralsDD> side_integrals_dd_;
  /// Distinguishes spaces in the per-thread cache of double-double cell matrices.
  std::uint64_t instance_id_ = 0;
  double mesh_size_ = 0.0;
  int extra_degree_ = 0;

  mutable std::mutex rule_mutex_;
  mutable std::map<int, RulePtr> cell_rules_;
  mutable std::map<std::pair<int, int>, RulePtr> edge_rules_;
};

}  // namespace iga
