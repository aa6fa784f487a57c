// libFuzzer target: a whole `problem:` section, as parse_problem reads it (pde, form, exact or
// source, boundary conditions, data), with the symbolic derivatives it takes. The text is a YAML
// document; any failure must be an InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "config/config_node.hpp"
#include "fuzz/fuzz_support.hpp"
#include "solver/problem.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  iga::fuzz::expect_input_error([&] {
    const iga::ConfigNode root = iga::ConfigNode::load_string(text, "fuzz.yaml");
    const iga::ProblemSpec problem = iga::parse_problem(root["problem"]);
    const iga::ExactSolution exact = problem.exact_solution();
    if (exact.u) (void)exact.u(iga::Point2(0.5, 0.25));
  });
  return 0;
}
