// Where the PETSc runtime comes from (petsc_runtime.hpp), and the backends' entry points that
// forward to it. iga-run opens the plugin the first time a run needs PETSc; a program that links
// the implementation has it built in.
#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

#include "config/companion_file.hpp"
#include "config/errors.hpp"
#include "solver/petsc_runtime.hpp"
#include "solver/petsc_session.hpp"

// Defined where the implementation is linked in; null in iga-run, which opens the plugin instead.
extern "C" iga::PetscRuntime* iga_petsc_runtime() __attribute__((weak));

namespace iga {

namespace {

namespace fs = std::filesystem;

#ifdef IGA_WITH_PETSC
constexpr const char* plugin_name = "iga-run-petsc.so";

/// Beside the executable (the build tree), in ../lib/iga-run/ from it (an installed tree moved
/// elsewhere), or where it was installed.
fs::path plugin_path() {
  std::vector<std::string> installed;
#ifdef IGA_PETSC_PLUGIN_INSTALLED_PATH
  installed.push_back(IGA_PETSC_PLUGIN_INSTALLED_PATH);
#endif
  return find_companion_file("iga-run's PETSc plugin", plugin_name, {"../lib/iga-run"}, installed);
}

void* plugin_handle = nullptr;

PetscRuntime* load_plugin() {
  const fs::path path = plugin_path();
  // RTLD_NOW: a plugin that does not match this executable fails here, with the symbol named.
  plugin_handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!plugin_handle)
    throw std::runtime_error("cannot load iga-run's PETSc plugin '" + path.string() + "': " + dlerror());
  auto* entry = reinterpret_cast<PetscRuntime* (*)()>(dlsym(plugin_handle, "iga_petsc_runtime"));
  if (!entry) throw std::runtime_error("'" + path.string() + "' is not iga-run's PETSc plugin (no entry point)");
  return entry();
}
#endif

}  // namespace

PetscRuntime* petsc_runtime(bool load) {
#ifdef IGA_WITH_PETSC
  static PetscRuntime* runtime = iga_petsc_runtime ? iga_petsc_runtime() : nullptr;
  if (!runtime && load) runtime = load_plugin();
  return runtime;
#else
  if (load) throw InputError("solver.type: petsc: this iga-run was built without PETSc");
  return nullptr;
#endif
}

void* petsc_plugin_symbol(const char* name) {
#ifdef IGA_WITH_PETSC
  return plugin_handle ? dlsym(plugin_handle, name) : nullptr;
#else
  (void)name;
  return nullptr;
#endif
}

bool slepc_available() {
#ifdef IGA_WITH_SLEPC
  return true;
#else
  return false;
#endif
}

}  // namespace iga
