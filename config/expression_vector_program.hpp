#pragma once
/// @file
/// Internal to FunctionBatch: GiNaC expressions compiled to straight-line code over arrays of
/// points. Each instruction runs over a block of points at once, so the dispatch cost of an
/// interpreter is paid once per block instead of once per point (muParser pays it per point and
/// operation, which made it the largest cost of error norms and loads with polynomial data).
/// Common subexpressions of all the functions are computed once; constants are immediate operands,
/// a product feeding a sum is one multiply-add, polynomials run as written, factored or in Horner
/// form (whichever is shortest), powers of one base share one pow, and work slots are reused once
/// their value is dead. Callers hold the GiNaC lock.

#include <ginac/ginac.h>

#include <optional>
#include <vector>

#include "config/expression_vector_math.hpp"

namespace iga::expression_detail {

class VectorProgram {
 public:
  /// Points evaluated together: the live work arrays of one block stay in the first-level cache
  /// (slots are reused), and each instruction's dispatch is paid once per 128 points (64 were
  /// 5-10 % slower in benchmarks/expression_program_bench, 256 no faster).
  static constexpr int kBlock = 128;

  /// values[i + k * stride] = f_i(x[k], y[k]) for k < count (count <= kBlock), `work` scratch.
  void run(const double* x, const double* y, int count, std::vector<double>& work, double* values,
           int stride) const;
  int size() const { return static_cast<int>(results_.size()); }
  /// Number of instructions (each one pass over a block).
  int length() const { return static_cast<int>(code_.size()); }

  /// Straight-line operations; a, b, d are slots, c and c2 numbers taken as they are (a constant
  /// operand costs no pass that fills an array with it).
  enum class Op {
    constant,   ///< c
    add,        ///< a + b
    mul,        ///< a * b
    add_c,      ///< a + c
    mul_c,      ///< a * c
    div,        ///< a / b
    div_c,      ///< c / a
    affine,     ///< a * c + c2
    mul_add,    ///< a * b + d
    mul_c_add,  ///< a * c + d
    mul_add_c,  ///< a * b + c
    power_int,  ///< a^n, n >= 0
    sqrt,
    power,  ///< a^b
    call1,  ///< f1(a)
    call2   ///< f2(a, b)
  };
  /// Slot numbers of the two inputs (the point arrays themselves, never copied).
  static constexpr int kInputX = -2, kInputY = -3;
  struct Instruction {
    Op op;
    int a = -1, b = -1, d = -1;  ///< operand slots
    int n = 0;                   ///< power_int: the exponent (>= 0)
    double c = 0, c2 = 0;        ///< immediate operands
    double (*f1)(double) = nullptr;
    double (*f2)(double, double) = nullptr;
    /// The same over arrays (libmvec), when there is one: used instead of f1, f2 or std::pow.
    ArrayFunction1 array1 = nullptr;
    ArrayFunction2 array2 = nullptr;
    int out = -1;  ///< the slot written
  };

 private:
  friend std::optional<VectorProgram> vector_program(const std::vector<GiNaC::ex>& es);
  std::vector<Instruction> code_;
  std::vector<int> results_;  ///< slot of each function
  int slots_ = 0;             ///< work slots of kBlock values
};

/// The program of `es` (functions of x and y), or nothing when an expression holds something this
/// compiler does not know (the caller then keeps muParser).
std::optional<VectorProgram> vector_program(const std::vector<GiNaC::ex>& es);

}  // namespace iga::expression_detail
