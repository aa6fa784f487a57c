/// parse_limits: defaults without a section, each key overridable, bad values named.
#include "config/resource_limits.hpp"

#include <gtest/gtest.h>

namespace iga {
namespace {

std::string error_of(const std::string& yaml) {
  try {
    parse_limits(ConfigNode::load_string(yaml, "run.yaml").find("limits"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ResourceLimits, DefaultsFitAWorkstation) {
  const ResourceLimits l = parse_limits(std::nullopt);
  EXPECT_EQ(l.max_degree, 12);
  EXPECT_EQ(l.max_elements, 4e6);
  EXPECT_EQ(l.max_dofs, 5e6);
  EXPECT_EQ(l.max_memory_gb, default_memory_gb());
  EXPECT_GT(l.max_memory_gb, 0.0);
}

TEST(ResourceLimits, KeysOverrideTheDefaults) {
  const ResourceLimits l = parse_limits(
      ConfigNode::load_string("limits: {max_degree: 20, max_elements: 1e7, max_dofs: 2e7, max_memory_gb: 64}\n")
          .find("limits"));
  EXPECT_EQ(l.max_degree, 20);
  EXPECT_EQ(l.max_elements, 1e7);
  EXPECT_EQ(l.max_dofs, 2e7);
  EXPECT_EQ(l.max_memory_gb, 64.0);
}

TEST(ResourceLimits, BadValuesNameTheKey) {
  EXPECT_EQ(error_of("limits: {max_dofs: -1}\n"), "run.yaml:1:20: limits.max_dofs: max_dofs must be a positive number");
  EXPECT_EQ(error_of("limits: {max_degree: 2.5}\n"), "run.yaml:1:22: limits.max_degree: max_degree must be an integer <= 1000");
  EXPECT_NE(error_of("limits: {max_dof: 5}\n").find("did you mean 'max_dofs'"), std::string::npos);
  EXPECT_NE(error_of("limits: {max_memory_gb: .nan}\n").find("limits.max_memory_gb"), std::string::npos);
}

}  // namespace
}  // namespace iga
