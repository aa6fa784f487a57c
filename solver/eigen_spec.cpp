#include "solver/eigen_spec.hpp"

#include <algorithm>
#include <cmath>
#include <regex>

#include "config/errors.hpp"
#include "config/expression.hpp"

namespace iga {

std::vector<double> eigenvalues_from_formula(const std::string& formula, const std::string& where, int count) {
  // The expression parser knows x and y: m and n are renamed, so x and y must not appear.
  static const std::regex xy(R"(\b[xy]\b)"), m(R"(\bm\b)"), n(R"(\bn\b)");
  if (std::regex_search(formula, xy))
    throw InputError(where + ": the eigenvalue formula is in m and n (the mode numbers), not x and y");
  const std::string renamed = std::regex_replace(std::regex_replace(formula, m, "x"), n, "y");
  const SymbolicFunction f = SymbolicFunction::parse(renamed, where);
  const auto at = [&](int i, int j) {
    const double v = f(i, j);
    if (!std::isfinite(v)) throw InputError(where + ": the eigenvalue formula is not finite for some m, n >= 1");
    return v;
  };
  // f increasing in m and n: every value with m > k or n > k is at least min(f(k+1, 1), f(1, k+1)),
  // so once the count-th smallest over m, n <= k is below that, it is the count-th smallest of all.
  for (int k = static_cast<int>(std::ceil(std::sqrt(count))) + 1;; k *= 2) {
    std::vector<double> values;
    values.reserve(static_cast<std::size_t>(k) * k);
    for (int i = 1; i <= k; ++i)
      for (int j = 1; j <= k; ++j) values.push_back(at(i, j));
    std::sort(values.begin(), values.end());
    if (values[count - 1] <= std::min(at(k + 1, 1), at(1, k + 1)) || k >= count) {
      values.resize(count);
      return values;
    }
  }
}

EigenSpec parse_eigen(const ConfigNode& node) {
  node.check_keys({"count", "exact_eigenvalues", "spectrum"});
  EigenSpec e;
  e.where = node.where();
  const ConfigNode count = node["count"];
  e.count = count.as_int();
  if (e.count < 1 || e.count > max_eigen_count)
    count.fail("count must be between 1 and " + std::to_string(max_eigen_count) + " (got " + std::to_string(e.count) +
               ")");
  if (const auto exact = node.find("exact_eigenvalues")) {
    if (exact->is_sequence()) {
      for (const ConfigNode& item : exact->items()) {
        const double v = SymbolicFunction::parse(item.as_string(), item.where())(0.0, 0.0);
        if (!(std::isfinite(v) && v >= 0)) item.fail("an exact eigenvalue must be a finite number >= 0");
        if (!e.exact.empty() && v < e.exact.back()) item.fail("exact eigenvalues must be in ascending order");
        e.exact.push_back(v);
      }
      if (e.exact.empty()) exact->fail("give at least one exact eigenvalue");
    } else if (exact->is_scalar()) {
      e.formula = exact->as_string();
      e.formula_where = exact->where();
      e.exact = eigenvalues_from_formula(e.formula, e.formula_where, e.count);
    } else {
      exact->fail("expected a list of eigenvalues or a formula in m and n, e.g. \"pi^2*(m^2 + n^2)\"");
    }
  }
  if (const auto spectrum = node.find("spectrum")) e.spectrum = spectrum->as_bool();
  return e;
}

}  // namespace iga
