#include "spaces/g1_4split/g1_4split_space.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "spaces/g1/boundary_parts.hpp"
#include "spaces/g1_4split/face_function.hpp"
#include "spaces/g1_4split/g1_4split_meshes.hpp"
#include "spaces/push_forward.hpp"

namespace iga {

class G14Space::G14Evaluator final : public Space::Evaluator {
 public:
  explicit G14Evaluator(const G14Space& s) : space_(s), tables_(s.basis_.bspline) {}

  void evaluate(int element, const QuadratureRule& rule, unsigned flags, PointValues& out) override {
    const TensorTableCache::SixTables& t = tables_.at(rule);
    extract_reference_derivatives(space_.basis_.extraction[element], t, flags, ref_);
    out.dofs = space_.basis_.face_dofs[element];
    map_points(element, t, rule.size());
    push_forward(jets_, ref_, flags, out);
  }

  /// u_h through the extraction once per element, not every active function at every point.
  void evaluate_function(int element, const QuadratureRule& rule, const Eigen::VectorXd& coefficients, unsigned flags,
                         PointValues& geometry, FunctionValues& out) override {
    if (flags & (update_laplacian_gradient | update_bilaplacian))
      throw std::logic_error("evaluate_function: this space provides derivatives up to order 2 only");
    const TensorTableCache::SixTables& t = tables_.at(rule);
    const std::vector<int>& dofs = space_.basis_.face_dofs[element];
    Eigen::VectorXd c(dofs.size());
    for (std::size_t i = 0; i < dofs.size(); ++i) c(i) = coefficients(dofs[i]);
    contract_reference_derivatives(space_.basis_.extraction[element], t, c, flags, one_);
    geometry.dofs = dofs;
    map_points(element, t, rule.size());
    push_forward(jets_, one_, flags | update_values, single_);
    take_single_function(single_, flags, geometry, out);
  }

  /// Points and Jacobians alone (VTK points, data checks; the load vector's integrate_values).
  void evaluate_geometry(int element, const QuadratureRule& rule, PointValues& out) override {
    map_points(element, tables_.at(rule), rule.size());
    out.dofs = space_.basis_.face_dofs[element];
    take_geometry(jets_, out);
  }

  void integrate_values(int element, const QuadratureRule& rule, const PointValues& /*geometry*/,
                        const Eigen::VectorXd& weights, Eigen::VectorXd& local) override {
    integrate_extracted(space_.basis_.extraction[element], tables_.at(rule)[0], weights, local);
  }

 private:
  /// jets_ at the q points of the tables t: the geometry's coefficients through the same tables.
  void map_points(int element, const TensorTableCache::SixTables& t, int q) {
    const Eigen::VectorXd& gx = space_.geometry_.x[element];
    const Eigen::VectorXd& gy = space_.geometry_.y[element];
    Eigen::Matrix<double, 6, Eigen::Dynamic> X(6, q), Y(6, q);
    for (int d = 0; d < 6; ++d) {
      X.row(d) = gx.transpose() * t[d];
      Y.row(d) = gy.transpose() * t[d];
    }
    jets_.resize(q);
    for (int p = 0; p < q; ++p) {
      GeometryJet& j = jets_[p];
      j.x = Point2(X(0, p), Y(0, p));
      j.jacobian << X(1, p), X(2, p), Y(1, p), Y(2, p);
      j.hessian_x << X(3, p), X(4, p), X(4, p), X(5, p);
      j.hessian_y << Y(3, p), Y(4, p), Y(4, p), Y(5, p);
    }
  }

  const G14Space& space_;
  TensorTableCache tables_;
  ReferenceDerivatives ref_, one_;
  PointValues single_;
  std::vector<GeometryJet> jets_;
};

G14Space::G14Space(const PatchMesh& coarse, const G14Options& options) : options_(options) {
  PatchMesh mesh = coarse;
  QuadTopology topology = quad_topology(mesh);
  gluing_ = symmetric_gluing(topology, options.blending, vertex_angles(mesh));
  basis_ = build_g14_basis(topology, gluing_, options.degree, options.regularity);
  geometry_ = project_geometry(basis_, bilinear_geometry(mesh, basis_.bspline));
  for (int l = 0; l < options.level; ++l) {
    PatchMesh finer = mesh.refined();
    QuadTopology fine = quad_topology(finer);
    if (options.nested) {
      gluing_ = inherited_gluing(topology, gluing_, fine);
      geometry_ = subdivide_geometry(basis_.bspline, geometry_);
      basis_ = build_g14_basis(fine, gluing_, options.degree, options.regularity);
    } else {
      gluing_ = symmetric_gluing(fine, options.blending, vertex_angles(finer));
      basis_ = build_g14_basis(fine, gluing_, options.degree, options.regularity);
      geometry_ = project_geometry(basis_, bilinear_geometry(finer, basis_.bspline));
    }
    mesh = std::move(finer);
    topology = std::move(fine);
  }
  check_geometry(basis_.bspline, geometry_, mesh.name());
  mesh_ = std::make_shared<const PatchMesh>(std::move(mesh));
  topology_ = std::make_shared<const QuadTopology>(std::move(topology));
  SpaceFacts facts;
  facts.type = "g1_4split";
  facts.parameters = {{"degree", std::to_string(options_.degree)},
                      {"regularity", std::to_string(options_.regularity)},
                      {"blending", blending_name(options_.blending)},
                      {"refinement", options_.nested ? "nested" : "rebuild"},
                      {"faces", std::to_string(topology_->num_faces())},
                      {"domain", mesh_->name()}};
  facts.dimension = basis_.dimension();
  facts.num_elements = topology_->num_faces();
  facts.cell_shapes = {CellShape::quadrilateral};
  facts.degree = options_.degree;
  facts.continuity = 1;
  facts.gradient_jump_samples = 4 * options_.degree + 8;
  set_boundary_parts(*mesh_, facts);
  // Diameter: largest distance between samples of the face boundary.
  for (int f = 0; f < topology_->num_faces(); ++f) {
    std::vector<Point2> pts;
    for (int j = 0; j < 4; ++j)
      for (int s = 0; s < 4; ++s) {
        const Point2 uv = reference_edge_point(CellShape::quadrilateral, j, s / 4.0);
        pts.emplace_back(face_jet(basis_.bspline, geometry_.x[f], uv)(0), face_jet(basis_.bspline, geometry_.y[f], uv)(0));
      }
    for (const Point2& a : pts)
      for (const Point2& b : pts) facts.mesh_size = std::max(facts.mesh_size, (a - b).norm());
  }
  set_facts(std::move(facts));
}

std::unique_ptr<Space::Evaluator> G14Space::make_evaluator() const { return std::make_unique<G14Evaluator>(*this); }

RulePtr SplitRuleCache::cell(int degree) const {
  degree = std::max(degree, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  RulePtr& r = cells_[degree];
  if (!r) {
    const QuadratureRule ref = tensor_gauss(degree);
    std::vector<QuadratureRule> parts;
    for (int hv = 0; hv < 2; ++hv)
      for (int hu = 0; hu < 2; ++hu) parts.push_back(map_to_box(ref, Point2(0.5 * hu, 0.5 * hv), Point2(0.5 * hu + 0.5, 0.5 * hv + 0.5)));
    r = std::make_shared<const QuadratureRule>(concatenate(parts));
  }
  return r;
}

RulePtr SplitRuleCache::edge(int edge, int degree) const {
  degree = std::max(degree, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  RulePtr& r = edges_[{edge, degree}];
  if (!r) {
    const QuadratureRule g = gauss_legendre_for_degree(degree);
    QuadratureRule line;
    line.degree = g.degree;
    for (int h = 0; h < 2; ++h)
      for (int q = 0; q < g.size(); ++q) {
        line.points.emplace_back(0.5 * (h + g.points[q].x()), 0.0);
        line.weights.push_back(0.5 * g.weights[q]);
      }
    r = std::make_shared<const QuadratureRule>(edge_rule(CellShape::quadrilateral, edge, line));
  }
  return r;
}

std::vector<InteriorEdge> quad_interior_edges(const QuadTopology& t) {
  std::vector<InteriorEdge> out;
  for (int e = 0; e < t.num_edges(); ++e) {
    const QuadEdge& edge = t.edge(e);
    if (edge.boundary()) continue;
    InteriorEdge ie;
    const QuadSide a = edge.sides[0], b = edge.sides[1];
    const bool same = t.face(a.face)[a.local_edge] == t.face(b.face)[b.local_edge];
    ie.element_a = a.face;
    ie.edge_a = a.local_edge;
    ie.a0 = 0.0;
    ie.a1 = 1.0;
    ie.element_b = b.face;
    ie.edge_b = b.local_edge;
    ie.b0 = same ? 0.0 : 1.0;
    ie.b1 = same ? 1.0 : 0.0;
    out.push_back(ie);
  }
  return out;
}

}  // namespace iga
