#pragma once
/// @file
/// Linear forms in the global DOF vector, stored densely over one small sorted support, for the
/// Hermite extraction: the forms of an edge trace, a vertex jet or a cell's Bernstein coefficients
/// touch a few dozen DOFs, so dense rows over their union replace sparse vectors (whose every sum
/// allocated) without changing a single operation of the arithmetic.
///
/// Besides its values, each form records which entries it *stores*: the sparsity structure a
/// sparse-vector construction would give it (the union over the terms it was built from, exact
/// zeros included). A cell's active functions are the DOFs its coefficient forms store. Entries
/// not stored hold ±0, so `a + c b` over the whole row is the sparse sum up to the sign of zeros.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace iga::tmesh_detail {

/// `count` forms over the global DOFs `support` (sorted), row by row.
struct LocalForms {
  std::vector<int> support;
  int count = 0;
  std::vector<double> value;
  std::vector<char> stored;

  int width() const { return static_cast<int>(support.size()); }
  /// `forms` zero forms storing nothing (the support is kept).
  void reset(int forms) {
    count = forms;
    value.assign(static_cast<std::size_t>(forms) * support.size(), 0.0);
    stored.assign(static_cast<std::size_t>(forms) * support.size(), 0);
  }
  double* values(int f) { return value.data() + static_cast<std::size_t>(f) * support.size(); }
  const double* values(int f) const { return value.data() + static_cast<std::size_t>(f) * support.size(); }
  char* stores(int f) { return stored.data() + static_cast<std::size_t>(f) * support.size(); }
  const char* stores(int f) const { return stored.data() + static_cast<std::size_t>(f) * support.size(); }
};

/// One form as a (values, stored) row of a given width.
struct FormRef {
  double* v;
  char* s;
};
struct ConstFormRef {
  const double* v;
  const char* s;
};

/// dst = dst + c src over `width` entries, where src's entry j is dst's entry at[j] (at == nullptr:
/// the same entry).
inline void add_scaled(FormRef dst, double c, ConstFormRef src, int width, const int* at = nullptr) {
  for (int j = 0; j < width; ++j) {
    const int k = at ? at[j] : j;
    dst.v[k] = dst.v[k] + c * src.v[j];
    dst.s[k] |= src.s[j];
  }
}

/// dst = dst - c src (same entries).
inline void subtract_scaled(FormRef dst, double c, ConstFormRef src, int width) {
  for (int j = 0; j < width; ++j) {
    dst.v[j] = dst.v[j] - c * src.v[j];
    dst.s[j] |= src.s[j];
  }
}

/// dst = c src (same entries).
inline void assign_scaled(FormRef dst, double c, ConstFormRef src, int width) {
  for (int j = 0; j < width; ++j) {
    dst.v[j] = c * src.v[j];
    dst.s[j] = src.s[j];
  }
}

/// dst = src / c (same entries).
inline void assign_divided(FormRef dst, ConstFormRef src, double c, int width) {
  for (int j = 0; j < width; ++j) {
    dst.v[j] = src.v[j] / c;
    dst.s[j] = src.s[j];
  }
}

/// For each entry of `part` (sorted, a subset of `whole`, sorted), its position in `whole`.
inline void positions_in(const std::vector<int>& part, const std::vector<int>& whole, std::vector<int>& at) {
  at.resize(part.size());
  std::size_t k = 0;
  for (std::size_t j = 0; j < part.size(); ++j) {
    while (whole[k] != part[j]) ++k;
    at[j] = static_cast<int>(k);
  }
}

}  // namespace iga::tmesh_detail
