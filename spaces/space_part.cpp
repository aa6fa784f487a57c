#include "spaces/space_part.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <numeric>
#include <stdexcept>

namespace iga {

/// Asks the whole space's evaluator for the whole's element and renumbers the functions (the
/// element's coefficients are in the same order for both).
class SpacePart::PartEvaluator final : public Space::Evaluator {
 public:
  explicit PartEvaluator(const SpacePart& part)
      : Space::Evaluator(part), part_(part), inner_(part.whole().make_evaluator()) {}

  void evaluate(int e, const QuadratureRule& points, unsigned flags, PointValues& out) override {
    inner_->evaluate(part_.elements_[e], points, flags, out);
    renumber(e, out);
  }
  void evaluate_element_function(int e, const QuadratureRule& points, const Eigen::VectorXd& element_coefficients,
                                 unsigned flags, PointValues& geometry, FunctionValues& out) override {
    inner_->evaluate_element_function(part_.elements_[e], points, element_coefficients, flags, geometry, out);
    renumber(e, geometry);
  }
  void evaluate_geometry(int e, const QuadratureRule& points, PointValues& out) override {
    inner_->evaluate_geometry(part_.elements_[e], points, out);
    renumber(e, out);
  }
  void integrate_values(int e, const QuadratureRule& points, const PointValues& geometry,
                        const Eigen::VectorXd& weights, Eigen::VectorXd& local) override {
    inner_->integrate_values(part_.elements_[e], points, geometry, weights, local);
  }

 private:
  void renumber(int e, PointValues& out) const {
    const int* d = part_.dofs_.data() + part_.dof_offsets_[e];
    out.dofs.assign(d, part_.dofs_.data() + part_.dof_offsets_[e + 1]);
  }
  const SpacePart& part_;
  std::unique_ptr<Space::Evaluator> inner_;
};

SpacePart::SpacePart(std::shared_ptr<const Space> whole, std::vector<int> elements, const std::vector<int>& own)
    : whole_(std::move(whole)), elements_(std::move(elements)) {
  if (!std::is_sorted(elements_.begin(), elements_.end()) ||
      std::adjacent_find(elements_.begin(), elements_.end()) != elements_.end())
    throw std::invalid_argument("SpacePart: the elements must be increasing");
  if (own.empty()) {
    owned_.resize(elements_.size());
    std::iota(owned_.begin(), owned_.end(), 0);
  } else {
    for (int e : own) {
      owned_.push_back(local_element(e));
      if (owned_.back() < 0) throw std::invalid_argument("SpacePart: an own element outside the part");
    }
  }
  const Space& w = *whole_;
  // The functions on the part as a bitmap of the whole's (a bit per function, not a sort of every
  // element's list), numbered by counting the bits before them.
  used_.assign(static_cast<std::size_t>(w.dimension()) / 64 + 1, 0);
  std::vector<int> dofs;
  for (int e : elements_) {
    w.element_dofs(e, dofs);
    for (int d : dofs) used_[static_cast<std::size_t>(d) >> 6] |= std::uint64_t{1} << (d & 63);
  }
  before_.resize(used_.size());
  int count = 0;
  for (std::size_t word = 0; word < used_.size(); ++word) {
    before_[word] = count;
    for (std::uint64_t bits = used_[word]; bits; bits &= bits - 1)
      global_dofs_.push_back(static_cast<int>(word * 64) + std::countr_zero(bits));
    count += std::popcount(used_[word]);
  }
  dof_offsets_.reserve(elements_.size() + 1);
  dof_offsets_.push_back(0);
  for (int e : elements_) {
    w.element_dofs(e, dofs);
    for (int d : dofs) dofs_.push_back(local_dof(d));
    dof_offsets_.push_back(static_cast<int>(dofs_.size()));
  }

  const auto restrict_edges = [&](const std::vector<BoundaryEdge>& edges) {
    std::vector<BoundaryEdge> kept;
    for (const BoundaryEdge& b : edges)
      if (const int e = local_element(b.element); e >= 0) kept.push_back({e, b.local_edge});
    return kept;
  };
  SpaceFacts facts = w.facts();
  facts.dimension = static_cast<int>(global_dofs_.size());
  facts.num_elements = static_cast<int>(elements_.size());
  if (w.facts().cell_shapes.size() > 1) {
    facts.cell_shapes.clear();
    for (int e : elements_) facts.cell_shapes.push_back(w.cell_shape(e));
  }
  for (auto& part : facts.boundary_parts) part.second = restrict_edges(part.second);
  facts.all_boundary_edges = restrict_edges(facts.all_boundary_edges);
  set_facts(std::move(facts));
}

int SpacePart::local_element(int global) const {
  const auto it = std::lower_bound(elements_.begin(), elements_.end(), global);
  return it != elements_.end() && *it == global ? static_cast<int>(it - elements_.begin()) : -1;
}

int SpacePart::local_dof(int global) const {
  if (global < 0 || global >= whole_->dimension()) return -1;
  const std::uint64_t word = used_[static_cast<std::size_t>(global) >> 6], bit = std::uint64_t{1} << (global & 63);
  return (word & bit) ? before_[static_cast<std::size_t>(global) >> 6] + std::popcount(word & (bit - 1)) : -1;
}

std::unique_ptr<Space::Evaluator> SpacePart::make_evaluator() const { return std::make_unique<PartEvaluator>(*this); }

void SpacePart::element_dofs(int element, std::vector<int>& out) const {
  out.assign(dofs_.begin() + dof_offsets_[element], dofs_.begin() + dof_offsets_[element + 1]);
}

RulePtr SpacePart::quadrature(int element, int degree) const { return whole_->quadrature(elements_[element], degree); }

RulePtr SpacePart::edge_quadrature(int element, int edge, int degree) const {
  return whole_->edge_quadrature(elements_[element], edge, degree);
}

std::vector<InteriorEdge> SpacePart::interior_edges() const {
  std::vector<InteriorEdge> edges;
  for (InteriorEdge edge : whole_->interior_edges()) {
    const int a = local_element(edge.element_a), b = local_element(edge.element_b);
    if (a < 0 || b < 0) continue;
    edge.element_a = a;
    edge.element_b = b;
    edges.push_back(edge);
  }
  return edges;
}

bool SpacePart::PartClosedForms::rounded(int element, BilinearForm form, Eigen::MatrixXd& local) const {
  return part_.whole_->closed_forms()->element_matrix(part_.elements_[element], form, local);
}

bool SpacePart::PartClosedForms::extended(int element, BilinearForm form, LongDoubleMatrix& local) const {
  return part_.whole_->closed_forms()->element_matrix(part_.elements_[element], form, local);
}

bool SpacePart::PartClosedForms::double_double(int element, BilinearForm form, DoubleDoubleMatrix& local) const {
  return part_.whole_->closed_forms()->element_matrix(part_.elements_[element], form, local);
}

void SpacePart::PartClosedForms::prepare_double_double(BilinearForm form) const {
  part_.whole_->closed_forms()->prepare<DoubleDoubleMatrix>(form);
}

const DoubleDoubleMatrix* SpacePart::PartClosedForms::shared_double_double(int element, BilinearForm form) const {
  return part_.whole_->closed_forms()->shared<DoubleDoubleMatrix>(part_.elements_[element], form);
}

}  // namespace iga
