#include "spaces/g1/g1_space.hpp"

#include <algorithm>
#include <stdexcept>

#include "config/errors.hpp"
#include "spaces/g1/bernstein_face.hpp"
#include "spaces/g1/boundary_parts.hpp"
#include "spaces/push_forward.hpp"

namespace iga {

// Evaluator: Bernstein tables per (rule, face shape), then per element extraction^T * tables +
// push-forward.
class G1Space::G1Evaluator final : public Space::Evaluator {
 public:
  explicit G1Evaluator(const G1Space& space) : space_(space) {}
  void evaluate(int element, const QuadratureRule& rule, unsigned flags, PointValues& out) override;
  /// u_h through the extraction once per element, not every active function at every point.
  void evaluate_function(int element, const QuadratureRule& rule, const Eigen::VectorXd& coefficients, unsigned flags,
                         PointValues& geometry, FunctionValues& out) override;
  /// Points and Jacobians alone (VTK points, data checks; the load vector's integrate_values).
  void evaluate_geometry(int element, const QuadratureRule& rule, PointValues& out) override;
  void integrate_values(int element, const QuadratureRule& rule, const PointValues& geometry,
                        const Eigen::VectorXd& weights, Eigen::VectorXd& local) override;

 private:
  /// bernstein_count x q tables of value, d/du, d/dv, d2/du2, d2/dudv, d2/dv2.
  struct Tables {
    std::vector<Point2> points;
    Eigen::MatrixXd t[6];
  };
  const Tables& tables(const QuadratureRule& rule, CellShape shape);

  /// jets_ at the rule's points.
  void map_points(int element, const QuadratureRule& rule);

  const G1Space& space_;
  std::map<std::pair<const QuadratureRule*, CellShape>, Tables> cache_;
  ReferenceDerivatives ref_, one_;
  PointValues single_;
  std::vector<GeometryJet> jets_;
};

const G1Space::G1Evaluator::Tables& G1Space::G1Evaluator::tables(const QuadratureRule& rule, CellShape shape) {
  const auto key = std::make_pair(&rule, shape);
  auto it = cache_.find(key);
  if (it != cache_.end() && it->second.points == rule.points) return it->second;
  if (it == cache_.end() && cache_.size() >= 64) cache_.clear();
  Tables& t = cache_[key];
  t.points = rule.points;
  bernstein_tables(shape, space_.degree(), rule.points, t.t);
  return t;
}

void G1Space::G1Evaluator::evaluate(int element, const QuadratureRule& rule, unsigned flags, PointValues& out) {
  const Tables& t = tables(rule, space_.mesh_->shape(element));
  extract_reference_derivatives(space_.basis_.extraction[element], t.t, flags, ref_);
  out.dofs = space_.basis_.face_dofs[element];
  map_points(element, rule);
  push_forward(jets_, ref_, flags, out);
}

void G1Space::G1Evaluator::map_points(int element, const QuadratureRule& rule) {
  jets_.resize(rule.size());
  for (int p = 0; p < rule.size(); ++p) jets_[p] = space_.mesh_->map(element, rule.points[p]);
}

void G1Space::G1Evaluator::evaluate_function(int element, const QuadratureRule& rule,
                                             const Eigen::VectorXd& coefficients, unsigned flags,
                                             PointValues& geometry, FunctionValues& out) {
  if (flags & (update_laplacian_gradient | update_bilaplacian))
    throw std::logic_error("evaluate_function: this space provides derivatives up to order 2 only");
  const Tables& t = tables(rule, space_.mesh_->shape(element));
  const std::vector<int>& dofs = space_.basis_.face_dofs[element];
  Eigen::VectorXd c(dofs.size());
  for (std::size_t i = 0; i < dofs.size(); ++i) c(i) = coefficients(dofs[i]);
  contract_reference_derivatives(space_.basis_.extraction[element], t.t, c, flags, one_);
  geometry.dofs = dofs;
  map_points(element, rule);
  push_forward(jets_, one_, flags | update_values, single_);
  take_single_function(single_, flags, geometry, out);
}

void G1Space::G1Evaluator::evaluate_geometry(int element, const QuadratureRule& rule, PointValues& out) {
  map_points(element, rule);
  out.dofs = space_.basis_.face_dofs[element];
  take_geometry(jets_, out);
}

void G1Space::G1Evaluator::integrate_values(int element, const QuadratureRule& rule, const PointValues& /*geometry*/,
                                            const Eigen::VectorXd& weights, Eigen::VectorXd& local) {
  const Tables& t = tables(rule, space_.mesh_->shape(element));
  integrate_extracted(space_.basis_.extraction[element], t.t[0], weights, local);
}

G1Space::G1Space(std::shared_ptr<const PatchMesh> mesh, int k) : mesh_(std::move(mesh)) {
  gluing_ = gluing_from_geometry(*mesh_);
  try {
    basis_ = build_g1_basis(*mesh_, gluing_, k);
  } catch (const IncompleteBasis& e) {
    // Find the smallest degree for which the local construction is complete (separability, §2.5).
    int works = -1;
    for (int trial = std::max(k + 1, 3); trial <= 10 && works < 0; ++trial) {
      try {
        build_g1_basis(*mesh_, gluing_, trial);
        works = trial;
      } catch (const IncompleteBasis&) {
      }
    }
    throw InputError("G1 space of degree " + std::to_string(k) + " on '" + mesh_->name() +
                     "': degree below the separability degree of this mesh (" + e.what() + "); use degree >= " +
                     (works > 0 ? std::to_string(works) : std::string("11")));
  }
  SpaceFacts facts;
  facts.type = "g1";
  facts.parameters = {{"degree", std::to_string(basis_.degree)},
                      {"patches", std::to_string(mesh_->num_faces())},
                      {"domain", mesh_->name()}};
  facts.dimension = basis_.dimension();
  facts.num_elements = mesh_->num_faces();
  facts.affine_elements = true;
  for (int f = 0; f < mesh_->num_faces(); ++f) {
    facts.cell_shapes.push_back(mesh_->shape(f));
    facts.mesh_size = std::max(facts.mesh_size, mesh_->diameter(f));
    facts.affine_elements = facts.affine_elements && mesh_->is_affine(f);
  }
  facts.degree = basis_.degree;
  facts.continuity = 1;
  set_boundary_parts(*mesh_, facts);
  facts.gradient_jump_samples = 2 * basis_.degree + 4;
  set_facts(std::move(facts));
}

std::vector<InteriorEdge> G1Space::interior_edges() const {
  std::vector<InteriorEdge> out;
  for (int e = 0; e < mesh_->num_edges(); ++e) {
    const MeshEdge& edge = mesh_->edge(e);
    if (edge.boundary()) continue;
    // `second` traverses the edge in the opposite direction: its parameter runs from 1 to 0.
    out.push_back({edge.first.face, edge.first.local_edge, 0.0, 1.0, edge.second.face, edge.second.local_edge, 1.0, 0.0});
  }
  return out;
}

std::unique_ptr<Space::Evaluator> G1Space::make_evaluator() const { return std::make_unique<G1Evaluator>(*this); }

RulePtr G1Space::quadrature(int element, int degree) const {
  // A quad rule exact per direction; a triangle rule exact for total degree `degree` covers the
  // same polynomials (total degree k on a triangle) and affine maps.
  return mesh_->shape(element) == CellShape::triangle ? rules_.triangle(degree) : rules_.cell(degree);
}

RulePtr G1Space::edge_quadrature(int element, int edge, int degree) const {
  return mesh_->shape(element) == CellShape::triangle ? rules_.triangle_edge(edge, degree) : rules_.edge(edge, degree);
}

}  // namespace iga
