// libFuzzer target: the PETSc options of a config (`solver.options`) against the allow-list
// (parse_config_petsc_options; no PETSc needed). Any text must either be accepted or fail with
// InputError. What is accepted must be safe to hand to PETSc: no name of the families that touch
// files, debuggers or signals, no viewer target but standard output, and written back as text it
// parses to the same options (PETSc splits it the same way iga-run did).
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "fuzz/fuzz_support.hpp"
#include "solver/petsc_option_policy.hpp"

namespace {

[[noreturn]] void finding(const std::string& what, const std::string& option) {
  std::fprintf(stderr, "fuzz: accepted %s: %s\n", what.c_str(), option.c_str());
  std::abort();
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

void check_accepted(const std::vector<iga::PetscOption>& options) {
  std::string text;
  for (const iga::PetscOption& o : options) {
    const std::string name = lower(o.name);
    for (const char* family : {"-log", "-malloc", "-options", "-prefix", "-history", "-debugger", "-on_error",
                               "-start_in", "-stop_for", "-info", "-viewer", "-no_signal", "-help", "-draw", "-saws"})
      if (name.rfind(family, 0) == 0) finding("a forbidden option", o.name);
    for (const char* part : {"dump", "file", "python", "socket", "binary", "matlab", "_mat_view", "vec_view"})
      if (name.find(part) != std::string::npos) finding("a forbidden option", o.name);
    if (o.value) {
      if (o.value->find(':') != std::string::npos && *o.value != ":stdout" && *o.value != "ascii:stdout")
        finding("a viewer target", o.name + " " + *o.value);
      for (char c : *o.value)
        if (std::isspace(static_cast<unsigned char>(c))) finding("a value with white space", o.name);
    }
    text += o.name + (o.value ? " " + *o.value : "") + "\n";
  }
  const std::vector<iga::PetscOption> again = iga::parse_config_petsc_options(text);
  if (again.size() != options.size()) finding("text that does not read back", text);
  for (std::size_t i = 0; i < again.size(); ++i)
    if (again[i].name != options[i].name || again[i].value != options[i].value) finding("text that reads back differently", text);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  iga::fuzz::expect_input_error([&] { check_accepted(iga::parse_config_petsc_options(text)); });
  return 0;
}
