#pragma once
/// @file
/// The eigenvalues of an eigen study, level by level, against the reference eigenvalues: relative
/// errors and their orders in h and in the number of DOFs (what eigenvalues.csv and the terminal
/// table show, output/eigen_report.hpp).

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace iga {

/// One level's eigenvalues (ascending).
struct EigenLevel {
  int level = 0;
  double h = 0;
  int dofs = 0;
  int free_dofs = 0;
  Eigen::VectorXd values;
  Eigen::VectorXd spectrum;  ///< eigen.spectrum: all eigenvalues (empty above max_spectrum_unknowns)
};

/// One eigenvalue of one level. Without a reference the optional members are empty; the rates
/// need the previous level's error of the same index too.
struct EigenRow {
  int level = 0;
  double h = 0;
  int dofs = 0;
  int index = 1;  ///< 1 = the smallest
  double eigenvalue = 0;
  /// relative_error: |λ_h − λ| / |λ|, or |λ_h| where λ = 0.
  std::optional<double> reference, relative_error;
  /// log(e_prev / e) / log(h_prev / h): 2p for smooth eigenfunctions of second-order problems.
  std::optional<double> rate;
  /// log(e_prev / e) / log(N / N_prev): half the rate in h on uniform 2D refinement.
  std::optional<double> rate_dofs;
};

/// Every eigenvalue of every level, level by level, index by index.
std::vector<EigenRow> eigen_rows(const std::vector<EigenLevel>& levels, const std::vector<double>& exact);

/// A level's whole spectrum against references (as many as given): n, λ_h,n and λ_h,n / λ_n.
struct SpectrumRow {
  int level = 0;
  int n = 1;  ///< 1 .. N
  int N = 0;  ///< the level's free unknowns
  double eigenvalue = 0;
  std::optional<double> reference, ratio;
};
std::vector<SpectrumRow> spectrum_rows(const EigenLevel& level, const std::vector<double>& exact);

}  // namespace iga
