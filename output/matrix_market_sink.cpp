#include "output/matrix_market_sink.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <unsupported/Eigen/SparseExtra>

namespace iga {

namespace {

void check_written(bool ok, const std::filesystem::path& file) {
  if (!ok) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace

LevelSink matrix_market_sink(const StudySettings& settings, const std::string& directory, const ProgressSink& progress) {
  const std::filesystem::path dir = std::filesystem::path(directory) / "matrices";
  return [&settings, dir, progress](int level, const Space& space, const DiscreteSolution& solution) {
    if (progress) progress("[level " + std::to_string(level) + "] writing matrices");
    std::filesystem::create_directories(dir);
    const LinearSystem sys = assemble_linear_system(space, settings.problem);
    const std::vector<int>& free = sys.constraints.free;
    // The solved coefficients of the free functions (a basis change only alters constrained ones).
    Eigen::VectorXd u_free(static_cast<Eigen::Index>(free.size()));
    for (std::size_t i = 0; i < free.size(); ++i) u_free(static_cast<Eigen::Index>(i)) = solution.coefficients(free[i]);
    const std::string l = std::to_string(level);
    check_written(Eigen::saveMarket(sys.A_free, (dir / ("matrix_" + l + ".mtx")).string()), dir / ("matrix_" + l + ".mtx"));
    check_written(Eigen::saveMarketVector(sys.b_free, (dir / ("rhs_" + l + ".mtx")).string()), dir / ("rhs_" + l + ".mtx"));
    check_written(Eigen::saveMarketVector(u_free, (dir / ("solution_" + l + ".mtx")).string()),
                  dir / ("solution_" + l + ".mtx"));
    const std::filesystem::path map = dir / ("free_dofs_" + l + ".txt");
    std::ofstream out(map);
    for (int i : free) out << i << '\n';
    check_written(static_cast<bool>(out), map);
  };
}

}  // namespace iga
