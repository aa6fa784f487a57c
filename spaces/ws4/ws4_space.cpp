#include "spaces/ws4/ws4_space.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "spaces/extracted_evaluator.hpp"
#include "spaces/ws4/ws4_basis.hpp"
#include "spaces/ws4/ws4_closed_forms.hpp"
#include "spaces/ws4/ws4_dof_layout.hpp"
#include "spaces/ws4/ws4_evaluator.hpp"
#include "spaces/ws4/ws4_hermite_transform.hpp"
#include "spaces/ws4/ws4_reference_matrices.hpp"
#include "spaces/ws4/ws4_split.hpp"

namespace iga::ws4 {

namespace {

using namespace dof_layout;

/// D_{v_1} ... D_{v_k} f from the Cartesian derivatives of f (order <= 3, vertex-DOF order).
double directional_from_jet(const std::array<double, 10>& d, const std::vector<Point2>& dirs) {
    const int k = static_cast<int>(dirs.size());
  double sum = 0.0;
  for (int choice = 0; choice < (1 << k); ++choice) {  // bit m set: direction m contributes its y part
    double w = 1.0;
    int nx = 0, ny = 0;
    for (int m = 0; m < k; ++m) {
      const bool y = (choice >> m) & 1;
      w *= y ? dirs[m].y() : dirs[m].x();
      (y ? ny : nx)++;
    }
    sum += w * d[vertex_index[nx][ny]];
  }
  return sum;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// The explicit core (element_core.hpp): the 51 reference simplex splines B_i (one kind), C_K of
// the element's shape class (stored local × active: active m = Σ_i C_K(i, m) B_i), the affine map
// onto the triangle. The evaluator is a specialisation (ws4_evaluator.hpp).

struct Ws4Space::Core {
  using Jet = GeometryJet;
  static constexpr bool identity = false;
  const Ws4Space& space;
  mutable Eigen::SparseMatrix<double> c_k;  ///< C_K compressed, per core (one core per thread)

  int kind(int /*e*/) const { return 0; }
  int tabulate(int /*kind*/, const std::vector<Point2>& points, int /*order*/, LocalTables& t) const {
    ReferenceDerivatives r;
    Ws4Basis::reference().tabulate(points, r);
    Eigen::MatrixXd* arrays[6] = {&r.value, &r.dxi, &r.deta, &r.dxixi, &r.dxieta, &r.detaeta};
    for (int d = 0; d < 6; ++d) t[d] = std::move(*arrays[d]);
    return 2;
  }
  std::vector<int> active(int e) const {
    std::vector<int> dofs;
    space.element_dofs(e, dofs);
    return dofs;
  }
  Extraction extraction(int e) const {
    c_k = space.extraction(e).sparseView();
    c_k.makeCompressed();
    return extraction_view(c_k);
  }
  void map(int e, const QuadratureRule& rule, const LocalTables& /*t*/, int /*order*/, std::vector<Jet>& jets) const {
    const Eigen::Matrix2d j = space.jacobian(e);
    const Point2 p0 = space.mesh_->vertices()[space.mesh_->triangle(e)[0]];
    jets.resize(rule.size());
    for (int k = 0; k < rule.size(); ++k) {
      jets[k].x = p0 + j * rule.points[k];
      jets[k].jacobian = j;
      jets[k].hessian_x.setZero();
      jets[k].hessian_y.setZero();
    }
  }
};

// ---------------------------------------------------------------------------------------------

Ws4Space::Ws4Space(Triangulation triangulation, std::string description, SpaceExtent extent)
    : mesh_(std::make_shared<const Triangulation>(std::move(triangulation))), description_(std::move(description)) {
  const Triangulation& mesh = *mesh_;
  for (int t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const auto& e = mesh.edge(mesh.triangle_edge(t, k));
      mesh_size_ = std::max(mesh_size_, (mesh.vertices()[e[0]] - mesh.vertices()[e[1]]).norm());
    }
  compute_vertex_frames();
  std::vector<int> elements;
  if (extent == SpaceExtent::whole) {
    elements.resize(mesh.num_triangles());
    std::iota(elements.begin(), elements.end(), 0);
  }
  build_extractions(elements);

  SpaceFacts facts;
  facts.type = "ws4";
  facts.parameters = {{"triangles", std::to_string(mesh_->num_triangles())},
                      {"vertices", std::to_string(mesh_->num_vertices())},
                      {"edges", std::to_string(mesh_->num_edges())},
                      {"domain", description_}};
  facts.dimension = dofs_per_vertex * mesh_->num_vertices() + dofs_per_edge * mesh_->num_edges() +
                    dofs_per_triangle * mesh_->num_triangles();
  facts.num_elements = mesh_->num_triangles();
  facts.cell_shapes = {CellShape::triangle};
  facts.mesh_size = mesh_size_;
  facts.degree = 4;
  facts.continuity = 3;  // C3 across macro-edges (note §2.3)
  facts.affine_elements = true;
  // One rule per polynomial piece (the 342 fan sub-triangles of the split, each about 1/18 of the
  // element's diameter) of degree 2p: exact for u_h² on every piece, and on pieces that small it
  // resolves the smooth data too. Against the composite rule of degree 2p + 2 (25 points per piece
  // instead of 16), the errors of a sine on the unit square move by < 1e-4 (L2), 2e-6 (H1) and
  // 1e-9 (H2) relative, at 32 x 32 squares.
  facts.error_quadrature_degree = 2 * 4;
  for (std::size_t part = 0; part < mesh_->part_names().size(); ++part)
    facts.boundary_parts.emplace_back(mesh_->part_names()[part], part_edges(static_cast<int>(part)));
  facts.all_boundary_edges = part_edges(-1);
  // The 342 fan triangles over the 178 split vertices: Space::sample_cell subdivides them.
  const Ws4Split& split = Ws4Split::reference();
  for (int v = 0; v < static_cast<int>(split.vertices().size()); ++v) facts.pieces.points.push_back(split.vertex_point(v));
  for (const auto& t : split.fan_triangles()) facts.pieces.cells.push_back({t[0], t[1], t[2]});
  facts.pieces_across = 8;
  set_facts(std::move(facts));
}

Ws4Space::Ws4Space(const Ws4Space& skeleton, const std::vector<int>& elements)
    : mesh_(skeleton.mesh_),
      description_(skeleton.description_),
      mesh_size_(skeleton.mesh_size_),
      vertex_frame_(skeleton.vertex_frame_) {
  check_element_set(elements, mesh_->num_triangles(), "Ws4Space::build_on");
  build_extractions(elements);
  set_facts(skeleton.facts());
}

Ws4Space::~Ws4Space() = default;

void Ws4Space::build_extractions(const std::vector<int>& elements) {
  // The classes of the built elements (indices into `elements`), then in element numbers. Every
  // element of a class has bit for bit the same extraction whichever element represents it, so a
  // space built on some elements evaluates them exactly as the whole space does.
  std::vector<ElementDofGeometry> translated(elements.size());
  for (std::size_t i = 0; i < elements.size(); ++i) translated[i] = translated_to_origin(dof_geometry(elements[i]));
  const ShapeClasses local = group_by_shape(translated);
  classes_.of_element.assign(mesh_->num_triangles(), -1);
  for (std::size_t i = 0; i < elements.size(); ++i) classes_.of_element[elements[i]] = local.of_element[i];
  classes_.representative.clear();
  for (int i : local.representative) classes_.representative.push_back(elements[i]);
  classes_.count = local.count;
  class_extraction_.resize(classes_.size());
#pragma omp parallel for schedule(dynamic, 4) if (classes_.size() > 8)
  for (int c = 0; c < classes_.size(); ++c)
    class_extraction_[c] = ws4_exact_extraction(translated[local.representative[c]]);
  closed_forms_ = std::make_unique<const Ws4ClosedForms>(*this);
}

SpacePtr Ws4Space::build_on(const std::vector<int>& elements) const {
  return std::shared_ptr<const Ws4Space>(new Ws4Space(*this, elements));
}

void Ws4Space::not_built(int element) const {
  throw std::logic_error("Ws4Space: element " + std::to_string(element) +
                         " was not built on (a space built on some elements is asked for another)");
}

const ClosedForms* Ws4Space::closed_forms() const { return closed_forms_.get(); }

void Ws4Space::compute_vertex_frames() {
  std::vector<Eigen::Matrix2d> frames(mesh_->num_vertices(), Eigen::Matrix2d::Identity());
  // Unit directions of the boundary edges leaving each boundary vertex.
  std::vector<std::vector<Point2>> out(mesh_->num_vertices());
  const auto& x = mesh_->vertices();
  for (int e = 0; e < mesh_->num_edges(); ++e) {
    if (!mesh_->is_boundary_edge(e)) continue;
    const int a = mesh_->edge(e)[0], b = mesh_->edge(e)[1];
    out[a].push_back((x[b] - x[a]).normalized());
    out[b].push_back((x[a] - x[b]).normalized());
  }
  for (int v = 0; v < mesh_->num_vertices(); ++v) {
    if (out[v].empty()) continue;
    const Point2 t1 = out[v][0];
    Point2 t2(-t1.y(), t1.x());  // straight boundary (or a non-manifold vertex): tangent and normal
    if (out[v].size() == 2 && std::abs(t1.x() * out[v][1].y() - t1.y() * out[v][1].x()) > 1e-8) t2 = out[v][1];
    frames[v].col(0) = t1;
    frames[v].col(1) = t2;
  }
  vertex_frame_ = std::make_shared<const std::vector<Eigen::Matrix2d>>(std::move(frames));
}

std::unique_ptr<Space::Evaluator> Ws4Space::make_evaluator() const { return std::make_unique<Ws4Evaluator>(*this); }

std::unique_ptr<Space::Evaluator> Ws4Space::make_generic_evaluator() const {
  return std::make_unique<ExtractedEvaluator<Core>>(*this, Core{*this, {}});
}

void Ws4Space::element_dofs(int element, std::vector<int>& out) const {
  out.resize(dofs_per_element);
  const auto& v = mesh_->triangle(element);
  int m = 0;
  for (int a = 0; a < 3; ++a)
    for (int k = 0; k < dofs_per_vertex; ++k) out[m++] = dofs_per_vertex * v[a] + k;
  const int edge0 = dofs_per_vertex * mesh_->num_vertices();
  for (int a = 0; a < 3; ++a)
    for (int k = 0; k < dofs_per_edge; ++k) out[m++] = edge0 + dofs_per_edge * mesh_->triangle_edge(element, a) + k;
  const int tri0 = edge0 + dofs_per_edge * mesh_->num_edges();
  for (int k = 0; k < dofs_per_triangle; ++k) out[m++] = tri0 + dofs_per_triangle * element + k;
}

Eigen::Matrix2d Ws4Space::jacobian(int element) const {
  const auto& v = mesh_->triangle(element);
  const auto& x = mesh_->vertices();
  Eigen::Matrix2d j;
  j.col(0) = x[v[1]] - x[v[0]];
  j.col(1) = x[v[2]] - x[v[0]];
  return j;
}

ElementDofGeometry Ws4Space::dof_geometry(int element) const {
  ElementDofGeometry g;
  const auto& tri = mesh_->triangle(element);
  for (int a = 0; a < 3; ++a) {
    g.corner[a] = mesh_->vertices()[tri[a]];
    g.frame[a] = (*vertex_frame_)[tri[a]];
    g.vertex_scale[a] = mesh_size_;
    g.edge_reversed[a] = mesh_->edge(mesh_->triangle_edge(element, a))[0] != tri[a];
    g.edge_scale[a] = mesh_size_;
  }
  return g;
}

Eigen::MatrixXd Ws4Space::element_functionals(int element) const {
  const Ws4Basis& basis = Ws4Basis::reference();
  const Eigen::Matrix2d jinv = jacobian(element).inverse();
  // A physical direction d differentiates the reference pieces along J^{-1} d.
  Eigen::MatrixXd g(dofs_per_element, dofs_per_element);
  double row[Ws4Basis::size];
  int m = 0;
  auto put = [&](const Point2& xi, const std::vector<Point2>& dirs) {
    basis.directional_derivatives(xi, dirs, row);
    const double scale = std::pow(mesh_size_, static_cast<int>(dirs.size()));
    for (int i = 0; i < Ws4Basis::size; ++i) g(m, i) = scale * row[i];
    ++m;
  };
  const auto& tri = mesh_->triangle(element);
  for (int a = 0; a < 3; ++a) {
    const Eigen::Matrix2d& f = (*vertex_frame_)[tri[a]];
    const Point2 w1 = jinv * f.col(0), w2 = jinv * f.col(1);
    for (int k = 0; k < dofs_per_vertex; ++k) {
      std::vector<Point2> dirs(vertex_dx[k], w1);
      dirs.insert(dirs.end(), vertex_dy[k], w2);
      put(corner[a], dirs);
    }
  }
  for (int k = 0; k < 3; ++k) {
    const auto& e = mesh_->edge(mesh_->triangle_edge(element, k));
    // Local corners of the edge's global start a and end b.
    const int a = tri[k] == e[0] ? k : (k + 1) % 3, b = tri[k] == e[0] ? (k + 1) % 3 : k;
    const Point2 t = (mesh_->vertices()[e[1]] - mesh_->vertices()[e[0]]).normalized();
    const Point2 wn = jinv * Point2(-t.y(), t.x());
    for (int d = 0; d < dofs_per_edge; ++d)
      put(corner[a] + edge_s[d] * (corner[b] - corner[a]), std::vector<Point2>(edge_order[d], wn));
  }
  for (const Point2& xi : interior_point) put(xi, {});
  return g;
}

Eigen::VectorXd Ws4Space::interpolate(const Jet3& f) const {
  Eigen::VectorXd u(dimension());
  const auto& x = mesh_->vertices();
  for (int v = 0; v < mesh_->num_vertices(); ++v) {
    const std::array<double, 10> d = f(x[v]);
    for (int k = 0; k < dofs_per_vertex; ++k) {
      std::vector<Point2> dirs(vertex_dx[k], Point2((*vertex_frame_)[v].col(0)));
      dirs.insert(dirs.end(), vertex_dy[k], Point2((*vertex_frame_)[v].col(1)));
      u(dofs_per_vertex * v + k) = std::pow(mesh_size_, vertex_dx[k] + vertex_dy[k]) * directional_from_jet(d, dirs);
    }
  }
  const int edge0 = dofs_per_vertex * mesh_->num_vertices();
  for (int e = 0; e < mesh_->num_edges(); ++e) {
    const Point2 xa = x[mesh_->edge(e)[0]], xb = x[mesh_->edge(e)[1]];
    const Point2 t = (xb - xa).normalized();
    const double nx = -t.y(), ny = t.x();
    for (int k = 0; k < dofs_per_edge; ++k) {
      const std::array<double, 10> d = f(xa + edge_s[k] * (xb - xa));
      double dn = 0.0;
      switch (edge_order[k]) {
        case 1: dn = nx * d[1] + ny * d[2]; break;
        case 2: dn = nx * nx * d[3] + 2 * nx * ny * d[4] + ny * ny * d[5]; break;
        default: dn = nx * nx * nx * d[6] + 3 * nx * nx * ny * d[7] + 3 * nx * ny * ny * d[8] + ny * ny * ny * d[9];
      }
      u(edge0 + dofs_per_edge * e + k) = std::pow(mesh_size_, edge_order[k]) * dn;
    }
  }
  const int tri0 = edge0 + dofs_per_edge * mesh_->num_edges();
  for (int t = 0; t < mesh_->num_triangles(); ++t) {
    const Eigen::Matrix2d j = jacobian(t);
    const Point2 p0 = x[mesh_->triangle(t)[0]];
    for (int k = 0; k < dofs_per_triangle; ++k) u(tri0 + dofs_per_triangle * t + k) = f(p0 + j * interior_point[k])[0];
  }
  return u;
}

RulePtr Ws4Space::quadrature(int, int degree) const {
  return rules_.made(degree, [&] { return Ws4Split::reference().composite_rule(std::max(degree, 0)); });
}

RulePtr Ws4Space::edge_quadrature(int, int edge, int degree) const { return rules_.triangle_edge(edge, degree); }

std::vector<BoundaryEdge> Ws4Space::part_edges(int part) const {
  std::vector<BoundaryEdge> out;
  for (int e = 0; e < mesh_->num_edges(); ++e) {
    if (!mesh_->is_boundary_edge(e) || (part >= 0 && mesh_->edge_part(e) != part)) continue;
    const int t = mesh_->edge_triangles(e)[0];
    for (int k = 0; k < 3; ++k)
      if (mesh_->triangle_edge(t, k) == e) out.push_back({t, k});
  }
  return out;
}

}  // namespace iga::ws4
