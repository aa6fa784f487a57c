#include "mesh/gmsh_session.hpp"

#include <gmsh.h>

#include <mutex>
#include <utility>
#include <vector>

#include "config/errors.hpp"

namespace iga {

namespace {

// Options a .geo file or a reader may change; Gmsh 4.8 cannot restore defaults, so their start-up
// values are saved and put back before every use (one file's settings must not leak into the next).
const char* const mesh_options[] = {"Mesh.MeshSizeMax",
                                    "Mesh.MeshSizeMin",
                                    "Mesh.MeshSizeFactor",
                                    "Mesh.MeshSizeFromPoints",
                                    "Mesh.MeshSizeFromCurvature",
                                    "Mesh.MeshSizeExtendFromBoundary",
                                    "Mesh.RecombineAll",
                                    "Mesh.RecombinationAlgorithm",
                                    "Mesh.Algorithm",
                                    "Mesh.ElementOrder",
                                    "Mesh.SubdivisionAlgorithm",
                                    "Mesh.SaveAll"};

struct GmshProcess {
  GmshProcess() {
    start();
    for (const char* name : mesh_options) {
      double value = 0.0;
      gmsh::option::getNumber(name, value);
      defaults.emplace_back(name, value);
    }
  }
  ~GmshProcess() { gmsh::finalize(); }
  static void start() {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);  // a user's gmshrc must not change results
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.NumThreads", 1);  // deterministic meshes; the solver owns the cores
  }
  /// After an error Gmsh 4.8 keeps parser state that spoils the next file (it then meshes
  /// nothing), so a failure restarts the whole SDK.
  static void restart() {
    gmsh::finalize();
    start();
  }
  void restore_defaults() const {
    for (const auto& [name, value] : defaults) gmsh::option::setNumber(name, value);
  }
  std::mutex lock;
  std::vector<std::pair<std::string, double>> defaults;
};

GmshProcess& gmsh_process() {
  static GmshProcess process;
  return process;
}

}  // namespace

void with_gmsh(const std::string& source, const std::function<void()>& work) {
  GmshProcess& process = gmsh_process();
  const std::lock_guard<std::mutex> guard(process.lock);
  // Gmsh 4.8 throws its last error message as a std::string (General.AbortOnError = 2).
  auto fail = [&](const std::string& message) {
    GmshProcess::restart();
    throw InputError(source + ": gmsh: " + message);
  };
  try {
    gmsh::clear();
    process.restore_defaults();
    work();
    gmsh::clear();
  } catch (const InputError&) {
    gmsh::clear();
    throw;
  } catch (const std::string& message) {
    fail(message);
  } catch (const char* message) {
    fail(message);
  } catch (const std::exception& e) {
    fail(e.what());
  }
}

}  // namespace iga
