// libFuzzer target: the YAML config loader. Any text must either load or fail with an InputError
// naming its place; then every node is read through every typed accessor, as the config parsers
// do, and each must again either succeed or throw InputError. Anything else (a crash, a sanitizer
// report, another exception, a hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "config/config_node.hpp"
#include "fuzz/fuzz_support.hpp"

namespace {

using iga::ConfigNode;

/// Reads `node` the ways a parser might; `depth` bounds the walk (aliases can make cycles).
void read_everything(const ConfigNode& node, int depth) {
  if (depth > 64) return;
  iga::fuzz::expect_input_error([&] { (void)node.where(); });
  iga::fuzz::expect_input_error([&] { (void)node.as_string(); });
  iga::fuzz::expect_input_error([&] { (void)node.as_double(); });
  iga::fuzz::expect_input_error([&] { (void)node.as_int(); });
  iga::fuzz::expect_input_error([&] { (void)node.as_bool(); });
  iga::fuzz::expect_input_error([&] { (void)node.as_doubles(); });
  iga::fuzz::expect_input_error([&] { (void)node.as_ints(); });
  iga::fuzz::expect_input_error([&] { (void)node.as_point(); });
  iga::fuzz::expect_input_error([&] { (void)node.as_choice({"poisson", "biharmonic", "bspline", "ws4"}); });
  iga::fuzz::expect_input_error([&] { node.check_keys({"problem", "domain", "space", "type", "degree"}); });
  iga::fuzz::expect_input_error([&] { (void)node.get_int("degree", 2); });
  iga::fuzz::expect_input_error([&] { (void)node.get_double("mesh_size", 0.5); });
  iga::fuzz::expect_input_error([&] { (void)node.get_string("type", "rectangle"); });
  iga::fuzz::expect_input_error([&] { (void)node.get_bool("recombine", false); });
  iga::fuzz::expect_input_error([&] { (void)node["problem"]; });
  iga::fuzz::expect_input_error([&] {
    for (const std::string& key : node.keys())
      if (auto child = node.find(key)) read_everything(*child, depth + 1);
  });
  iga::fuzz::expect_input_error([&] {
    if (node.is_sequence())
      for (const ConfigNode& item : node.items()) read_everything(item, depth + 1);
  });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  iga::fuzz::expect_input_error([&] { read_everything(ConfigNode::load_string(text, "fuzz.yaml"), 0); });
  return 0;
}
