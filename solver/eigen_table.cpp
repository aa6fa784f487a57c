#include "solver/eigen_table.hpp"

#include <cmath>

namespace iga {

namespace {
/// |λ_h − λ| / |λ|, or |λ_h| for λ = 0 (the constants of a closed surface or of pure Neumann).
double relative(double value, double reference) {
  return reference == 0.0 ? std::abs(value) : std::abs(value - reference) / std::abs(reference);
}
}  // namespace

std::vector<EigenRow> eigen_rows(const std::vector<EigenLevel>& levels, const std::vector<double>& exact) {
  std::vector<EigenRow> rows;
  for (std::size_t l = 0; l < levels.size(); ++l) {
    const EigenLevel& L = levels[l];
    for (int i = 0; i < L.values.size(); ++i) {
      EigenRow r{L.level, L.h, L.dofs, i + 1, L.values(i), {}, {}, {}, {}};
      if (i < static_cast<int>(exact.size())) {
        r.reference = exact[i];
        r.relative_error = relative(L.values(i), exact[i]);
        const EigenLevel* prev = l > 0 ? &levels[l - 1] : nullptr;
        if (prev && i < prev->values.size()) {
          const double e0 = relative(prev->values(i), exact[i]);
          const double e1 = *r.relative_error;
          if (e0 > 0 && e1 > 0) {
            const double drop = std::log(e0 / e1);
            if (prev->h != L.h) r.rate = drop / std::log(prev->h / L.h);
            if (prev->dofs != L.dofs) r.rate_dofs = drop / std::log(double(L.dofs) / prev->dofs);
          }
        }
      }
      rows.push_back(r);
    }
  }
  return rows;
}

std::vector<SpectrumRow> spectrum_rows(const EigenLevel& level, const std::vector<double>& exact) {
  std::vector<SpectrumRow> rows;
  const int N = static_cast<int>(level.spectrum.size());
  for (int i = 0; i < N; ++i) {
    SpectrumRow r{level.level, i + 1, N, level.spectrum(i), {}, {}};
    if (i < static_cast<int>(exact.size())) {
      r.reference = exact[i];
      r.ratio = level.spectrum(i) / exact[i];
    }
    rows.push_back(r);
  }
  return rows;
}

}  // namespace iga
