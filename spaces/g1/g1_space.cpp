#include "spaces/g1/g1_space.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "config/errors.hpp"
#include "spaces/extracted_evaluator.hpp"
#include "spaces/g1/bernstein_face.hpp"
#include "spaces/g1/boundary_parts.hpp"

namespace iga {

namespace {

/// The explicit core (element_core.hpp): each face's Bernstein basis of its shape, the sparse
/// extraction of g1_basis.hpp and the face's bilinear or affine map.
struct G1Core {
  using Jet = GeometryJet;
  static constexpr bool identity = false;
  const PatchMesh& mesh;
  const G1Basis& basis;

  int kind(int e) const { return static_cast<int>(mesh.shape(e)); }
  int tabulate(int kind, const std::vector<Point2>& points, int /*order*/, LocalTables& t) const {
    bernstein_tables(static_cast<CellShape>(kind), basis.degree, points, t);
    return 2;
  }
  const std::vector<char>& built;

  const std::vector<int>& active(int e) const { return basis.face_dofs[e]; }
  Extraction extraction(int e) const {
    if (!built[e])
      throw std::logic_error("G1Space: element " + std::to_string(e) +
                             " was not built on (a space built on some elements is asked for another)");
    return extraction_view(basis.extraction[e]);
  }
  void map(int e, const QuadratureRule& rule, const LocalTables& /*t*/, int /*order*/, std::vector<Jet>& jets) const {
    jets.resize(rule.size());
    for (int p = 0; p < rule.size(); ++p) jets[p] = mesh.map(e, rule.points[p]);
  }
};

}  // namespace

G1Space::G1Space(std::shared_ptr<const PatchMesh> mesh, int k, SpaceExtent extent) : mesh_(std::move(mesh)) {
  gluing_ = std::make_shared<const std::vector<EdgeGluing>>(gluing_from_geometry(*mesh_));
  const std::vector<EdgeGluing>& gluing = *gluing_;
  try {
    basis_ = build_g1_basis(*mesh_, gluing, k);
  } catch (const IncompleteBasis& e) {
    // Find the smallest degree for which the local construction is complete (separability, §2.5).
    int works = -1;
    for (int trial = std::max(k + 1, 3); trial <= 10 && works < 0; ++trial) {
      try {
        build_g1_basis(*mesh_, gluing, trial);
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
  built_.assign(mesh_->num_faces(), extent == SpaceExtent::whole ? 1 : 0);
  if (extent == SpaceExtent::skeleton) {
    pending_ = std::move(basis_.extraction);
    basis_.extraction.assign(mesh_->num_faces(), {});
  }
}

G1Space::G1Space(const G1Space& skeleton, const std::vector<int>& elements,
                 std::vector<Eigen::SparseMatrix<double>> extraction)
    : mesh_(skeleton.mesh_), gluing_(skeleton.gluing_), built_(skeleton.mesh_->num_faces(), 0) {
  basis_.degree = skeleton.basis_.degree;
  basis_.info = skeleton.basis_.info;
  basis_.face_dofs = skeleton.basis_.face_dofs;
  basis_.extraction.resize(mesh_->num_faces());
  for (int e : elements) {
    basis_.extraction[e] = std::move(extraction[e]);
    built_[e] = 1;
  }
  set_facts(skeleton.facts());
}

SpacePtr G1Space::build_on(const std::vector<int>& elements) const {
  check_element_set(elements, mesh_->num_faces(), "G1Space::build_on");
  std::vector<Eigen::SparseMatrix<double>> extraction;
  {
    const std::lock_guard<std::mutex> lock(pending_mutex_);
    extraction = std::move(pending_);
    pending_.clear();
  }
  // The same local problems give the same extractions, bit for bit.
  if (extraction.empty()) extraction = build_g1_basis(*mesh_, *gluing_, basis_.degree).extraction;
  return std::shared_ptr<const G1Space>(new G1Space(*this, elements, std::move(extraction)));
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

std::unique_ptr<Space::Evaluator> G1Space::make_evaluator() const {
  return std::make_unique<ExtractedEvaluator<G1Core>>(*this, G1Core{*mesh_, basis_, built_});
}

RulePtr G1Space::quadrature(int element, int degree) const {
  // A quad rule exact per direction; a triangle rule exact for total degree `degree` covers the
  // same polynomials (total degree k on a triangle) and affine maps.
  return mesh_->shape(element) == CellShape::triangle ? rules_.triangle(degree) : rules_.cell(degree);
}

RulePtr G1Space::edge_quadrature(int element, int edge, int degree) const {
  return mesh_->shape(element) == CellShape::triangle ? rules_.triangle_edge(edge, degree) : rules_.edge(edge, degree);
}

}  // namespace iga
