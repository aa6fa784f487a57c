#pragma once
/// @file
/// SpacePart: a space restricted to some of its elements — what one rank of a distributed solve
/// works on, so that the rank's tables, vectors and solution are the size of its part, not of
/// the whole space. The elements are renumbered 0..n−1 in the order given, the functions active
/// on them 0..m−1 in increasing global order (global_dofs() maps back). Every query is asked of
/// the whole space's element; a part is a Space, so assembly, loads, boundary projections, error
/// norms and drawing run on it unchanged.

#include <cstdint>
#include <memory>
#include <vector>

#include "spaces/closed_forms.hpp"
#include "spaces/space.hpp"

namespace iga {

class SpacePart final : public Space {
 public:
  /// The part of `whole` on `elements` (element numbers of `whole`, increasing: the part then
  /// visits its elements, edges and functions in the whole's order, so that what it computes from
  /// them — a boundary projection, its pivoting — is what the whole computes), of which `own` (a
  /// subset, increasing; empty: all) are the ones its holder works on (a rank's own; the others are
  /// neighbours it only reads). Its boundary parts are the whole's boundary edges on these elements,
  /// in the whole's order; its interior edges the whole's with both elements in the part.
  SpacePart(std::shared_ptr<const Space> whole, std::vector<int> elements, const std::vector<int>& own = {});

  std::unique_ptr<Evaluator> make_evaluator() const override;
  void element_dofs(int element, std::vector<int>& out) const override;
  RulePtr quadrature(int element, int degree) const override;
  RulePtr edge_quadrature(int element, int edge, int degree) const override;
  const ClosedForms* closed_forms() const override { return whole_->closed_forms() ? &closed_forms_ : nullptr; }
  std::vector<InteriorEdge> interior_edges() const override;

  const Space& whole() const { return *whole_; }
  /// The holder's own elements (the part's numbers, increasing).
  const std::vector<int>& owned_elements() const { return owned_; }
  /// Element e of the part is element elements()[e] of the whole.
  const std::vector<int>& elements() const { return elements_; }
  /// Function i of the part is function global_dofs()[i] of the whole (increasing).
  const std::vector<int>& global_dofs() const { return global_dofs_; }
  /// The part's number of a function of the whole, or −1 when it is not active on the part.
  int local_dof(int global) const;
  /// The part's number of an element of the whole, or −1 when it is not in the part.
  int local_element(int global) const;

 private:
  class PartEvaluator;
  /// The whole's closed forms, asked for the whole's element.
  class PartClosedForms final : public ClosedForms {
   public:
    explicit PartClosedForms(const SpacePart& part) : part_(part) {}

   protected:
    bool rounded(int element, BilinearForm form, Eigen::MatrixXd& local) const override;
    bool extended(int element, BilinearForm form, LongDoubleMatrix& local) const override;
    bool double_double(int element, BilinearForm form, DoubleDoubleMatrix& local) const override;
    void prepare_double_double(BilinearForm form) const override;
    const DoubleDoubleMatrix* shared_double_double(int element, BilinearForm form) const override;

   private:
    const SpacePart& part_;
  };

  std::shared_ptr<const Space> whole_;
  std::vector<int> elements_;
  std::vector<int> owned_;
  std::vector<int> global_dofs_;
  std::vector<std::uint64_t> used_;  ///< bit d: function d of the whole is on the part
  std::vector<int> before_;          ///< functions on the part before each word of used_
  /// Active functions of each element in the part's numbering (CSR).
  std::vector<int> dof_offsets_, dofs_;
  PartClosedForms closed_forms_{*this};
};

}  // namespace iga
