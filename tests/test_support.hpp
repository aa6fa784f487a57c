#pragma once
// Helpers shared by tests: build spaces and problems from YAML text, as a user's config would.

#include <string>

#include "solver/config_node.hpp"
#include "solver/problem.hpp"
#include "spaces/space_factory.hpp"

namespace iga::test {

/// A space from `domain:` and `space:` YAML snippets, refined `level` times.
inline SpacePtr space_from_yaml(const std::string& yaml, int level = 0) {
  const ConfigNode root = ConfigNode::load_string(yaml, "test.yaml");
  return make_space(root["domain"], root["space"], level);
}

inline ProblemSpec problem_from_yaml(const std::string& yaml) {
  return parse_problem(ConfigNode::load_string(yaml, "test.yaml")["problem"]);
}

}  // namespace iga::test
