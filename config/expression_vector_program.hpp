#pragma once
/// @file
/// Internal to FunctionBatch: GiNaC expressions compiled to straight-line code over arrays of
/// points. Each instruction runs over a block of points at once, so the dispatch cost of an
/// interpreter is paid once per block instead of once per point (muParser pays it per point and
/// operation, which made it the largest cost of error norms and loads with polynomial data).
/// Common subexpressions of all the functions are computed once. Callers hold the GiNaC lock.

#include <ginac/ginac.h>

#include <optional>
#include <vector>

#include "config/expression_vector_math.hpp"

namespace iga::expression_detail {

class VectorProgram {
 public:
  /// Points evaluated together: the work arrays of one block stay in the first-level caches.
  static constexpr int kBlock = 64;

  /// values[i * stride + k] = f_i(x[k], y[k]) for k < count (count <= kBlock), `work` scratch.
  void run(const double* x, const double* y, int count, std::vector<double>& work, double* values,
           int stride) const;
  int size() const { return static_cast<int>(results_.size()); }
  /// Number of instructions (each one pass over a block).
  int length() const { return static_cast<int>(code_.size()); }

  enum class Op { constant, x, y, add, mul, power_int, sqrt, power, call1, call2 };
  struct Instruction {
    Op op;
    int a = -1, b = -1;  ///< operand slots
    int n = 0;           ///< power_int: the exponent
    double c = 0;        ///< constant: the value
    double (*f1)(double) = nullptr;
    double (*f2)(double, double) = nullptr;
    /// The same over arrays (libmvec), when there is one: used instead of f1, f2 or std::pow.
    ArrayFunction1 array1 = nullptr;
    ArrayFunction2 array2 = nullptr;
  };

 private:
  friend std::optional<VectorProgram> vector_program(const std::vector<GiNaC::ex>& es);
  std::vector<Instruction> code_;  ///< instruction i writes slot i
  std::vector<int> results_;       ///< slot of each function
};

/// The program of `es` (functions of x and y), or nothing when an expression holds something this
/// compiler does not know (the caller then keeps muParser).
std::optional<VectorProgram> vector_program(const std::vector<GiNaC::ex>& es);

}  // namespace iga::expression_detail
