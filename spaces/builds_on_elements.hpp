#pragma once
/// @file
/// Spaces built on some of their elements: a rank of a distributed solve builds the heavy
/// per-element data (dense extractions) of its part only, not of the whole space
/// (docs/parallel.md, "What is still replicated").
///
/// Such a space is first built as its *skeleton* (make_space with SpaceExtent::skeleton): the mesh,
/// the numbering of elements and functions by the same rule on every rank, the element geometry
/// (what the partition's element centres and the mesh outlines read), the boundary and interior
/// edges — everything but the per-element data. on_elements then adds the data of the elements a
/// rank works on. A capability kept off Space, like LocallyRefinable: Space's interface lists only
/// what every space answers.

#include <memory>
#include <vector>

#include "spaces/space.hpp"

namespace iga {

/// What a space builds of its per-element data: all of it, or its skeleton (spaces without
/// BuildsOnElements build the whole either way).
enum class SpaceExtent { whole, skeleton };

class BuildsOnElements {
 public:
  virtual ~BuildsOnElements() = default;
  /// This space with its per-element data on `elements` (increasing) only: the same elements,
  /// functions, facts, geometry and edges. Evaluating another element's functions, or its element
  /// matrices, is a programming error (std::logic_error).
  virtual SpacePtr build_on(const std::vector<int>& elements) const = 0;
  /// Whether element `element` has its per-element data.
  virtual bool built_on(int element) const = 0;
};

/// Throws std::invalid_argument naming `who` unless `elements` are increasing element numbers
/// below `num_elements` (what build_on takes).
void check_element_set(const std::vector<int>& elements, int num_elements, const char* who);

/// `space` with the per-element data of `elements` (increasing): `space` itself when it has them
/// all already (every space without BuildsOnElements), else the space built on those elements.
SpacePtr on_elements(const SpacePtr& space, const std::vector<int>& elements);

}  // namespace iga
