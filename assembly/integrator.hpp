#pragma once
/// @file
/// Element operators as objects. An Integrator computes the element matrix of a bilinear form
/// a(u, v) from evaluated basis data (ElementValues), in the scalar the caller sums in (double,
/// long double or double-double), and says which values it needs. The standard forms
/// (integrators.hpp) also name themselves by a BilinearForm tag, the key under which a space's
/// ClosedForms may have their matrices without quadrature; the assembler asks those first and
/// integrates the others.
///
/// A vector-valued form (a shell's membrane or bending energy, three displacement components)
/// is another Integrator: its element matrix is (components · n)², blocks of the n functions per
/// pair of components, read from the derivative tensors of PointValues (gradient(i, k),
/// hessian(i, k), normal3); it has no closed-form tag, so the assembler integrates it. Only the
/// dof table (one index per function and component) has to grow for it, not this interface.

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>

#include "assembly/split_matrix.hpp"
#include "config/double_double.hpp"
#include "spaces/bilinear_form.hpp"
#include "spaces/element_values.hpp"

namespace iga {

class Integrator {
 public:
  /// A constant coefficient c: the element matrix is c times the form's (a field later: the
  /// integrators then weigh their quadrature points by it).
  explicit Integrator(double coefficient = 1.0) : coefficient_(coefficient) {}
  virtual ~Integrator() = default;

  /// The update flags (point_values.hpp) an element loop must evaluate for this form.
  virtual unsigned flags() const = 0;
  virtual std::string name() const = 0;
  /// The standard form this is (up to the coefficient), under which ClosedForms may answer;
  /// empty: always integrated.
  virtual std::optional<BilinearForm> closed_form_kind() const { return std::nullopt; }
  double coefficient() const { return coefficient_; }

  /// The element matrix on the element last evaluated by `ev` (n x n, n = ev.num_functions()),
  /// coefficient included, with the quadrature sums in the scalar of `local`: double, long double
  /// (the basis values stay double) or double-double (products of values and weights exact, sums
  /// compensated). Thread-safe.
  template <class Local>
  void element_matrix(const ElementValues& ev, Local& local) const {
    unit_matrix(ev, local);
    if (coefficient_ != 1.0) scale(local, coefficient_);
  }

  /// local *= c in the scalar of `local` (as the assembler scales closed-form matrices).
  static void scale(Eigen::MatrixXd& local, double c) { local *= c; }
  static void scale(MatrixXld& local, double c) { local *= static_cast<long double>(c); }
  static void scale(DoubleDoubleMatrix& local, double c);

 protected:
  /// The matrix with coefficient 1, in each scalar (integrators.hpp writes the three once, as a
  /// template over the scalar).
  virtual void unit_matrix(const ElementValues& ev, Eigen::MatrixXd& local) const = 0;
  virtual void unit_matrix(const ElementValues& ev, MatrixXld& local) const = 0;
  virtual void unit_matrix(const ElementValues& ev, DoubleDoubleMatrix& local) const = 0;

 private:
  double coefficient_;
};

/// A handle to an integrator, cheap to copy and shared between threads (integrators are
/// immutable): what the assembler, FormTerm lists and Formulation::terms() pass around.
class Form {
 public:
  /// The standard form of that tag (integrators.hpp) with coefficient c. Implicit, so that a tag
  /// can be written where a form is asked for.
  Form(BilinearForm kind, double coefficient = 1.0);  // NOLINT(google-explicit-constructor)
  Form(std::shared_ptr<const Integrator> integrator) : integrator_(std::move(integrator)) {}  // NOLINT

  const Integrator& operator*() const { return *integrator_; }
  const Integrator* operator->() const { return integrator_.get(); }

 private:
  std::shared_ptr<const Integrator> integrator_;
};

/// One term of a matrix Σ terms (Laplace–Beltrami with reaction: laplace + c mass); its
/// coefficient is the integrator's.
using FormTerm = Form;

}  // namespace iga
