#pragma once
/// @file
/// Scalar functions of (x, y) given as strings in the config. GiNaC parses them and differentiates
/// symbolically (exact derivatives, never finite differences); muParser evaluates the printed
/// expressions fast. Known constants: pi. Known functions: those of GiNaC (sin, cos, exp, sqrt,
/// log, tan, atan, sinh, cosh, tanh, abs, pow, atan2, ...).

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace iga {

class SymbolicFunction {
 public:
  /// Parse `text` in the variables x and y. Throws InputError "<where>: cannot parse '...': reason"
  /// (also for unknown symbols); `where` names the config place.
  static SymbolicFunction parse(const std::string& text, const std::string& where);
  /// Parse `text` in the variables x, y and z (functions on surfaces in 3D; evaluate with at()).
  static SymbolicFunction parse_xyz(const std::string& text, const std::string& where);
  static SymbolicFunction constant(double value);

  SymbolicFunction diff_x() const;
  SymbolicFunction diff_y() const;
  SymbolicFunction diff_z() const;  ///< zero for functions of x and y
  SymbolicFunction laplacian() const;    ///< u_xx + u_yy
  SymbolicFunction bilaplacian() const;  ///< Δ²u
  SymbolicFunction operator-() const;
  bool is_zero() const;

  /// Printed form (evaluable by muParser with a Pi constant).
  std::string str() const;

  /// Evaluate at a point. Thread-safe: each thread uses its own compiled muParser instance.
  double operator()(const Eigen::Vector2d& p) const;
  double operator()(double x, double y) const { return (*this)(Eigen::Vector2d(x, y)); }
  /// Evaluate at a point in 3D (functions from parse_xyz; thread-safe like operator()).
  double at(const Eigen::Vector3d& p) const;

  struct Impl;

 private:
  friend class FunctionBatch;
  std::shared_ptr<const Impl> impl_;
};

/// Several functions of (x, y) evaluated together at many points, e.g. an exact solution and its
/// derivatives in the error norms. One program computes the subexpressions they share (sin(pi x)
/// in u, u_x, u_xx, ...) once per point: compiled from the GiNaC expressions to code over blocks of
/// points (expression_vector_program.hpp), or a muParser program for what that compiler does not know.
class FunctionBatch {
 public:
  /// Throws InputError like SymbolicFunction::parse if muParser rejects the joint program.
  explicit FunctionBatch(const std::vector<SymbolicFunction>& functions);

  int size() const;
  /// values(i, k) = f_i(points.col(k)), values resized to size() x points.cols(). Thread-safe.
  void evaluate(const Eigen::Matrix2Xd& points, Eigen::MatrixXd& values) const;

  struct Impl;

 private:
  std::shared_ptr<const Impl> impl_;
};

}  // namespace iga
