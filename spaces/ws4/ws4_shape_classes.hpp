#pragma once
/// @file
/// Shape classes of a WS4 mesh: the extraction C_K = A⁻¹ T_K depends on an element only through its
/// edge vectors, corner frames, edge orientations and DOF scales (T_K is translation invariant), and
/// its element matrices Cᵀ K_ref(J) C only through those and J. On a structured mesh a handful of
/// classes cover all elements, so both are computed once per class instead of once per element.

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "config/double_double.hpp"
#include "spaces/bilinear_form.hpp"
#include "spaces/ws4/ws4_hermite_transform.hpp"

namespace iga::ws4 {

/// The same element moved so that corner 0 is the origin (corners 1, 2 are then the columns of J
/// as the space computes it, in double): the input of the extraction of its class.
ElementDofGeometry translated_to_origin(const ElementDofGeometry& geometry);

/// Elements grouped by the bits of their translated geometry (equal bits: equal extraction and
/// element matrices, exactly).
struct ShapeClasses {
  std::vector<int> of_element;      ///< class of each element
  std::vector<int> representative;  ///< the first element of each class
  std::vector<int> count;           ///< elements per class
  int size() const { return static_cast<int>(representative.size()); }
};
ShapeClasses group_by_shape(const std::vector<ElementDofGeometry>& translated);

/// Double-double element matrices of the classes shared by several elements, built for all classes
/// at once (build_all, before an element loop); thread-safe. Classes of one element are not kept: on
/// an unstructured mesh every element is its own class, and caching would only hold a 41 kB matrix
/// per element.
class ElementMatrixCache {
 public:
  explicit ElementMatrixCache(std::vector<int> class_size)
      : class_size_(std::move(class_size)), entries_(class_size_.size() * kForms) {}

  /// The cached matrix of `form` for `cls`, or null (a class of one element, or not built yet).
  const DoubleDoubleMatrix* find(int cls, BilinearForm form) const {
    std::lock_guard<std::mutex> lock(mutex_);
    return entries_[slot(cls, form)].get();
  }

  /// Build the matrices of `form` for every class shared by several elements, in parallel;
  /// compute(cls, out) fills the matrix of class cls.
  template <class Compute>
  void build_all(BilinearForm form, Compute&& compute) const {
    const int n = static_cast<int>(class_size_.size());
    std::vector<std::shared_ptr<DoubleDoubleMatrix>> fresh(n);
#pragma omp parallel for schedule(dynamic, 1) if (n > 1)
    for (int c = 0; c < n; ++c) {
      if (class_size_[c] < 2 || find(c, form)) continue;
      fresh[c] = std::make_shared<DoubleDoubleMatrix>();
      compute(c, *fresh[c]);
    }
    std::lock_guard<std::mutex> lock(mutex_);
    for (int c = 0; c < n; ++c)
      if (fresh[c] && !entries_[slot(c, form)]) entries_[slot(c, form)] = std::move(fresh[c]);
  }

  /// local = the matrix of `form` for class `cls`: the cached one after build_all, else compute's
  /// (the same matrix bit for bit: every element of a class has the same J and extraction).
  template <class Compute>
  void get(int cls, BilinearForm form, DoubleDoubleMatrix& local, Compute&& compute) const {
    if (const DoubleDoubleMatrix* cached = find(cls, form))
      local = *cached;
    else
      compute(local);
  }

 private:
  static constexpr std::size_t kForms = kNumBilinearForms;
  static std::size_t slot(int cls, BilinearForm form) {
    return static_cast<std::size_t>(cls) * kForms + static_cast<std::size_t>(form);
  }
  std::vector<int> class_size_;
  mutable std::mutex mutex_;
  mutable std::vector<std::shared_ptr<const DoubleDoubleMatrix>> entries_;
};

}  // namespace iga::ws4
