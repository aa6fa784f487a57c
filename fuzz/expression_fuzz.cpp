// libFuzzer target: the expression parser and its symbolic derivatives. Any text must either
// parse or fail with InputError; a parsed function is differentiated the way the problem setup
// does (gradient, Laplacian, bilaplacian) and evaluated at a few points (any double, NaN included,
// is an answer; crashes, other exceptions and hangs are findings).
#include <cstddef>
#include <cstdint>
#include <string>

#include "config/expression.hpp"
#include "fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  iga::fuzz::expect_input_error([&] {
    const iga::SymbolicFunction u = iga::SymbolicFunction::parse(text, "fuzz.yaml:1:1: problem.exact");
    const iga::SymbolicFunction derived[] = {u, u.diff_x(), u.diff_y(), u.laplacian(), u.bilaplacian(), -u};
    for (const auto& f : derived) {
      (void)f.str();
      (void)f.is_zero();
      for (const double x : {0.0, 0.5, 1.0, -0.25})
        for (const double y : {0.0, 0.3, 1.0}) (void)f(x, y);
    }
  });
  return 0;
}
