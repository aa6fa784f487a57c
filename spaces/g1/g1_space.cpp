#include "spaces/g1/g1_space.hpp"

#include <algorithm>
#include <numeric>
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
  const std::vector<int>& slot;

  /// None for an element not built on (its geometry may still be evaluated; its functions not).
  const std::vector<int>& active(int e) const {
    static const std::vector<int> none;
    return slot[e] < 0 ? none : basis.face_dofs[slot[e]];
  }
  Extraction extraction(int e) const { return extraction_view(basis.extraction[checked(e)]); }
  int checked(int e) const {
    if (slot[e] < 0)
      throw std::logic_error("G1Space: element " + std::to_string(e) +
                             " was not built on (a space built on some elements is asked for another)");
    return slot[e];
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
  // The whole basis, or the skeleton's numbering: both throw the same IncompleteBasis.
  auto construct = [&](int degree) {
    if (extent == SpaceExtent::whole) basis_ = build_g1_basis(*mesh_, gluing, degree);
    else numbering_ = std::make_shared<const G1Numbering>(number_g1_basis(*mesh_, gluing, degree));
  };
  try {
    construct(k);
  } catch (const IncompleteBasis& e) {
    // Find the smallest degree for which the local construction is complete (separability, §2.5).
    int works = -1;
    for (int trial = std::max(k + 1, 3); trial <= 10 && works < 0; ++trial) {
      try {
        construct(trial);
        works = trial;
      } catch (const IncompleteBasis&) {
      }
    }
    throw InputError("G1 space of degree " + std::to_string(k) + " on '" + mesh_->name() +
                     "': degree below the separability degree of this mesh (" + e.what() + "); use degree >= " +
                     (works > 0 ? std::to_string(works) : std::string("11")));
  }
  const int dimension = numbering_ ? numbering_->dimension() : basis_.dimension();
  basis_.degree = k;
  SpaceFacts facts;
  facts.type = "g1";
  facts.parameters = {{"degree", std::to_string(basis_.degree)},
                      {"patches", std::to_string(mesh_->num_faces())},
                      {"domain", mesh_->name()}};
  facts.dimension = dimension;
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
  slot_.assign(mesh_->num_faces(), -1);
  if (extent == SpaceExtent::whole) std::iota(slot_.begin(), slot_.end(), 0);
  else gluing_.reset();  // build_on computes it again
}

G1Space::G1Space(const G1Space& from, const std::vector<int>& elements)
    : mesh_(from.mesh_), numbering_(from.numbering_), slot_(mesh_->num_faces(), -1) {
  // The gluing of every edge again (a skeleton does not keep it: 80 bytes per edge), for the
  // time of this construction only.
  basis_ = build_g1_basis_on(*mesh_, gluing_from_geometry(*mesh_), *numbering_, elements);
  for (size_t s = 0; s < elements.size(); ++s) slot_[elements[s]] = static_cast<int>(s);
  set_facts(from.facts());
}

SpacePtr G1Space::build_on(const std::vector<int>& elements) const {
  check_element_set(elements, mesh_->num_faces(), "G1Space::build_on");
  if (!numbering_) return shared_from_this();  // a whole space is built on every element
  return std::shared_ptr<const G1Space>(new G1Space(*this, elements));
}

const std::vector<EdgeGluing>& G1Space::gluing() const {
  if (!gluing_) throw std::logic_error("G1Space: a skeleton and its parts keep no gluing data");
  return *gluing_;
}

void G1Space::element_dofs(int element, std::vector<int>& out) const {
  if (slot_[element] >= 0) out = basis_.face_dofs[slot_[element]];
  else numbering_->face_dofs(*mesh_, element, out);
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
  return std::make_unique<ExtractedEvaluator<G1Core>>(*this, G1Core{*mesh_, basis_, slot_});
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
