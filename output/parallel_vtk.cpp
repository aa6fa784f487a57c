#include "output/parallel_vtk.hpp"

#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "config/errors.hpp"
#include "output/parallel_vtk_pieces.hpp"
#include "solver/petsc_runtime.hpp"
#include "solver/petsc_session.hpp"

namespace iga {

namespace fs = std::filesystem;

fs::path piece_path(const fs::path& pvtu, int rank) {
  return pvtu.parent_path() / (pvtu.stem().string() + "_" + std::to_string(rank) + ".vtu");
}

bool parallel_vtk_output() { return mpi_size() > 1; }

std::string shared_output_directory(const std::string& root_directory) {
  const std::string directory = broadcast_from_root(root_directory);
  on_every_rank([&] {
    std::error_code ec;
    if (!fs::is_directory(directory, ec))
      throw InputError("rank " + std::to_string(mpi_rank()) + " cannot see the output staging directory '" + directory +
                       "': the ranks must share it (set TMPDIR to a directory every node sees)");
  });
  return directory;
}

// Built in (programs linking the PETSc implementation) or found in the loaded plugin.
extern "C" bool iga_petsc_write_solution_pvtu(const Space&, const Eigen::VectorXd&, const VtkFieldOptions&,
                                              const std::string&) __attribute__((weak));

bool write_solution_pvtu(const Space& space, const Eigen::VectorXd& coefficients, const VtkFieldOptions& options,
                         const std::string& pvtu_filename) {
  using Writer = bool (*)(const Space&, const Eigen::VectorXd&, const VtkFieldOptions&, const std::string&);
  Writer writer = iga_petsc_write_solution_pvtu;
  if (!writer) writer = reinterpret_cast<Writer>(petsc_plugin_symbol("iga_petsc_write_solution_pvtu"));
  if (!writer)
    throw std::logic_error("write_solution_pvtu: no MPI in this run (one rank writes .vtu files)");
  return writer(space, coefficients, options, pvtu_filename);
}

void remove_solution_dataset(const std::string& filename) {
  const fs::path path(filename);
  std::error_code ec;
  fs::remove(path, ec);
  if (path.extension() == ".pvtu")
    for (int r = 0; r < mpi_size(); ++r) fs::remove(piece_path(path, r), ec);
}

}  // namespace iga
