#include "solver/resource_checks.hpp"

#include <algorithm>
#include <cmath>

#include "solver/petsc_session.hpp"
#include "spaces/space_factory.hpp"

namespace iga {

SpaceSize measure(const Space& space) {
  SpaceSize s;
  s.elements = space.num_elements();
  s.dofs = space.dimension();
  std::vector<int> dofs;
  for (int e = 0; e < space.num_elements(); ++e) {
    space.element_dofs(e, dofs);
    s.element_entries += static_cast<double>(dofs.size()) * static_cast<double>(dofs.size());
  }
  return s;
}

SpaceSize uniform_estimate(const SpaceSize& level0, int level) {
  const double growth = std::pow(4.0, level);
  return {level0.elements * growth, level0.dofs * growth, level0.element_entries * growth, level0.build_bytes * growth};
}

MemoryModel memory_model(SolverKind kind, const PetscSettings& petsc) {
  const bool iterative = kind == SolverKind::petsc && (petsc.pc == "gamg" || petsc.pc == "hypre" || petsc.pc == "ilu");
  return {!iterative, std::max(1, mpi_size())};
}

double estimated_memory_bytes(const SpaceSize& size, const MemoryModel& model) {
  const double ranks = std::max(1, model.ranks);
  if (model.factorization)
    return size.build_bytes + 8.5 * size.element_entries * std::log2(std::max(2.0, size.dofs)) / ranks;
  return size.build_bytes + 400.0 * size.dofs + 7.0 * size.element_entries / ranks;
}

void check_space_request(const ConfigNode& space, const ResourceLimits& limits) {
  if (auto degree = space.find("degree")) {
    const std::vector<double> degrees = degree->is_sequence() ? degree->as_doubles() : std::vector<double>{degree->as_double()};
    for (double p : degrees)
      if (p > limits.max_degree)
        degree->fail("degree " + format_number(p) + " exceeds limits.max_degree = " + std::to_string(limits.max_degree) +
                     how_to_raise("max_degree"));
  }
  if (auto elements = space.find("elements")) {
    std::vector<double> n = elements->is_sequence() ? elements->as_doubles() : std::vector<double>{elements->as_double()};
    if (n.size() == 1) n.push_back(n[0]);
    double total = 1.0;
    for (double v : n) total *= std::max(1.0, v);
    if (total > limits.max_elements)
      elements->fail("about " + format_number(total) + " elements exceed limits.max_elements = " +
                     format_number(limits.max_elements) + how_to_raise("max_elements"));
  }
}

void check_requested_levels(const ConfigNode& domain, const ConfigNode& space, int levels, const ResourceLimits& limits,
                            const ConfigNode& blame, const std::string& levels_name, const MemoryModel& model) {
  const auto which = [&](int level, const std::string& basis) {
    return (level == 0 ? std::string("level 0") : "level " + std::to_string(level) + " of " + levels_name + " " +
                                                      std::to_string(levels)) +
           " (from " + basis + ")";
  };
  const std::vector<SpaceRequestSize> sizes = requested_space_sizes(domain, space, levels);
  for (std::size_t level = 0; level < sizes.size(); ++level) {
    const SpaceRequestSize& r = sizes[level];
    const ConfigNode& node = level > 0 ? blame : r.blame ? *r.blame : space;
    check_size({r.elements, r.dofs, r.element_entries, r.build_bytes}, limits, node,
               which(static_cast<int>(level), r.basis), model);
  }
}

void check_size(const SpaceSize& size, const ResourceLimits& limits, const ConfigNode& node, const std::string& what,
                const MemoryModel& model) {
  if (size.elements > limits.max_elements)
    node.fail(what + " has " + format_number(size.elements) + " elements, more than limits.max_elements = " +
              format_number(limits.max_elements) + how_to_raise("max_elements"));
  if (size.dofs > limits.max_dofs)
    node.fail(what + " has " + format_number(size.dofs) + " degrees of freedom, more than limits.max_dofs = " +
              format_number(limits.max_dofs) + how_to_raise("max_dofs"));
  const double gb = estimated_memory_bytes(size, model) / 1e9;
  if (gb > limits.max_memory_gb) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", gb);
    const std::string parts = std::string(size.build_bytes > 0 ? "the space, " : "") +
                              (model.factorization ? "matrix and factor" : "matrix and preconditioner");
    const std::string per_rank = model.ranks > 1 ? ", per rank of " + std::to_string(model.ranks) : "";
    node.fail(what + " needs about " + buf + " GB (" + parts + per_rank + "), more than limits.max_memory_gb = " +
              format_number(limits.max_memory_gb) + how_to_raise("max_memory_gb"));
  }
}

}  // namespace iga
