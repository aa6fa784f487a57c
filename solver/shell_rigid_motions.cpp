#include "solver/shell_rigid_motions.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/Geometry>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "assembly/assembler.hpp"
#include "assembly/integrators.hpp"
#include "assembly/surface_load.hpp"
#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "spaces/element_values.hpp"

namespace iga {

namespace {

/// Centroid of the surface and its largest distance from it (over the quadrature points).
void extent(const Space& space, int quad_degree, Eigen::Vector3d& center, double& length) {
  ElementValues ev(space, update_values);
  double area = 0;
  center.setZero();
  std::vector<Eigen::Vector3d> points;
  for (int e = 0; e < space.num_elements(); ++e) {
    ev.reinit(e, *space.quadrature(e, quad_degree));
    for (int k = 0; k < ev.num_points(); ++k) {
      area += ev.jxw()(k);
      center += ev.jxw()(k) * ev.values().x3.col(k);
      points.push_back(ev.values().x3.col(k));
    }
  }
  center /= area;
  length = 0;
  for (const Eigen::Vector3d& x : points) length = std::max(length, (x - center).norm());
  if (!(length > 0)) length = 1.0;
}

/// Row of "component c of a + θ/L × y" (y = x − x₀) in the unknowns (a, θ).
Eigen::Matrix<double, 1, 6> component_row(int c, const Eigen::Vector3d& y, double length) {
  Eigen::Matrix<double, 1, 6> row = Eigen::Matrix<double, 1, 6>::Zero();
  row(c) = 1.0;
  // (θ × y)_c = θ_a y_b − θ_b y_a with (c, a, b) cyclic.
  const int a = (c + 1) % 3, b = (c + 2) % 3;
  row(3 + a) = y(b) / length;
  row(3 + b) = -y(a) / length;
  return row;
}

std::string vector_text(const Eigen::Vector3d& v) {
  std::string s = "(";
  for (int i = 0; i < 3; ++i) s += (i ? ", " : "") + format_number(std::abs(v(i)) < 1e-12 ? 0.0 : v(i));
  return s + ")";
}

}  // namespace

std::string RigidMotions::describe() const {
  std::string out;
  for (int k = 0; k < count(); ++k) {
    Eigen::VectorXd m = modes.col(k);
    // Sign: the largest entry positive, for stable messages.
    Eigen::Index i;
    m.cwiseAbs().maxCoeff(&i);
    if (m(i) < 0) m = -m;
    const Eigen::Vector3d a = m.head<3>(), t = m.tail<3>();
    std::string one;
    if (a.norm() > 1e-12) one += "translation " + vector_text(a);
    if (t.norm() > 1e-12) one += std::string(one.empty() ? "" : " + ") + "rotation about " + vector_text(t);
    out += (k ? "; " : "") + one;
  }
  return out + " (rotations about the centroid " + vector_text(center) + ")";
}

RigidMotions free_rigid_motions(const Space& space, const std::vector<ShellSupport>& supports, int quad_degree) {
  RigidMotions m;
  extent(space, quad_degree, m.center, m.length);
  // Five points per held edge, a row per held component there.
  std::vector<Eigen::Matrix<double, 1, 6>> rows;
  const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
  PointValues g;
  for (const ShellSupport& s : supports) {
    for (const BoundaryEdge& e : space.boundary_edges(s.part)) {
      QuadratureRule rule;
      for (int k = 0; k <= 4; ++k) rule.points.push_back(reference_edge_point(space.cell_shape(e.element), e.local_edge, k / 4.0));
      rule.weights.assign(rule.points.size(), 0.0);
      evaluator->evaluate_geometry(e.element, rule, g);
      for (int k = 0; k < rule.size(); ++k)
        for (int c = 0; c < 3; ++c)
          if (s.fixed[c]) rows.push_back(component_row(c, g.x3.col(k) - m.center, m.length));
    }
  }
  if (rows.empty()) {
    m.modes = Eigen::MatrixXd::Identity(6, 6);
    return m;
  }
  Eigen::MatrixXd C(rows.size(), 6);
  for (std::size_t r = 0; r < rows.size(); ++r) C.row(r) = rows[r];
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(C, Eigen::ComputeFullV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  int rank = 0;
  // Rows are O(1) (unit translations, rotations scaled by 1/L): a held motion has σ of order 1
  // times the sample count's root; 1e-8 of the largest separates the exact zeros from them.
  for (int i = 0; i < sigma.size(); ++i)
    if (sigma(i) > 1e-8 * sigma(0)) ++rank;
  m.modes = svd.matrixV().rightCols(6 - rank);
  return m;
}

LoadResultant load_resultant(const Space& space, const AreaForce& f, const std::vector<ShellPointLoad>& points,
                             const Eigen::Vector3d& center, int quad_degree) {
  LoadResultant r;
  ElementValues ev(space, update_values | update_surface_curvature);
  for (int e = 0; e < space.num_elements(); ++e) {
    ev.reinit(e, *space.quadrature(e, quad_degree));
    for (int k = 0; k < ev.num_points(); ++k) {
      const Eigen::Vector3d x = ev.values().x3.col(k), fx = f(e, x, ev.values().normal3.col(k));
      r.force += ev.jxw()(k) * fx;
      r.moment += ev.jxw()(k) * (x - center).cross(fx);
      r.magnitude += ev.jxw()(k) * fx.norm();
    }
  }
  for (const ShellPointLoad& p : points) {
    r.force += p.force;
    r.moment += (p.point - center).cross(p.force);
    r.magnitude += p.force.norm();
  }
  return r;
}

RigidMotionBasis rigid_motion_basis(const Space& space, const RigidMotions& motions, int quad_degree) {
  const int n = space.dimension(), k = motions.count();
  RigidMotionBasis out;
  out.coefficients = Eigen::MatrixXd::Zero(3 * n, k);
  out.moments = Eigen::MatrixXd::Zero(3 * n, k);
  if (k == 0) return out;
  // ∫ N_i and ∫ (x − x₀)_j N_i / L, and their L2 projections (the coefficients of 1 and of the
  // scaled coordinates).
  Eigen::MatrixXd loads(n, 4);
  const Eigen::Vector3d x0 = motions.center;
  const double L = motions.length;
  for (int j = 0; j < 4; ++j)
    loads.col(j) = surface_load(
        space,
        [j, &x0, L](const Eigen::Vector3d& x, const Eigen::Vector3d&, double) { return j == 0 ? 1.0 : (x(j - 1) - x0(j - 1)) / L; },
        quad_degree);
  const SparseMatrix M = Assembler(space).matrix(mass_integrator(), quad_degree);
  const Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> mass(M);
  if (mass.info() != Eigen::Success) throw std::runtime_error("rigid motions: the mass matrix is not positive definite");
  const Eigen::MatrixXd projected = mass.solve(loads);
  for (int m = 0; m < k; ++m) {
    const Eigen::Vector3d a = motions.modes.col(m).head<3>(), t = motions.modes.col(m).tail<3>();
    for (int c = 0; c < 3; ++c) {
      // Component c of a + t × y: a_c + t_a y_b − t_b y_a, (c, a, b) cyclic.
      const int ia = (c + 1) % 3, ib = (c + 2) % 3;
      Eigen::Vector4d weights(a(c), 0.0, 0.0, 0.0);
      weights(1 + ib) += t(ia);
      weights(1 + ia) -= t(ib);
      out.coefficients.col(m).segment(c * n, n) = projected * weights;
      out.moments.col(m).segment(c * n, n) = loads * weights;
    }
  }
  return out;
}

std::vector<int> pin_rigid_motions(const RigidMotionBasis& basis, Constraints& c) {
  const int k = static_cast<int>(basis.coefficients.cols());
  if (k == 0) return {};
  // Candidates: free coefficients that are plain functions (not a basis-change column).
  std::vector<bool> changed(c.free.size(), false);
  for (const auto& t : c.basis_change) changed[t.col()] = true;
  std::vector<int> candidates;
  for (std::size_t p = 0; p < c.free.size(); ++p)
    if (!changed[p]) candidates.push_back(static_cast<int>(p));
  Eigen::MatrixXd rows(k, candidates.size());
  for (std::size_t j = 0; j < candidates.size(); ++j) rows.col(j) = basis.coefficients.row(c.free[candidates[j]]).transpose();
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(rows);
  if (qr.rank() < k)
    throw std::runtime_error("rigid motions: their unheld coefficients are dependent (rank " + std::to_string(qr.rank()) +
                             " of " + std::to_string(k) + ")");
  std::vector<int> pinned_positions;
  for (int j = 0; j < k; ++j) pinned_positions.push_back(candidates[qr.colsPermutation().indices()(j)]);
  std::sort(pinned_positions.begin(), pinned_positions.end());
  // Move them to the constrained set (value 0) and renumber the basis change's columns.
  std::vector<int> pins, free, shift(c.free.size(), 0);
  int removed = 0;
  for (std::size_t p = 0; p < c.free.size(); ++p) {
    if (std::binary_search(pinned_positions.begin(), pinned_positions.end(), static_cast<int>(p))) {
      pins.push_back(c.free[p]);
      ++removed;
      continue;
    }
    shift[p] = removed;
    free.push_back(c.free[p]);
  }
  for (auto& t : c.basis_change) t = Eigen::Triplet<double>(t.row(), t.col() - shift[t.col()], t.value());
  c.free = std::move(free);
  for (int i : pins) c.values(i) = 0.0;
  c.constrained.insert(c.constrained.end(), pins.begin(), pins.end());
  std::sort(c.constrained.begin(), c.constrained.end());
  return pins;
}

void remove_rigid_motions(const RigidMotionBasis& basis, Eigen::VectorXd& u) {
  if (basis.coefficients.cols() == 0) return;
  const Eigen::MatrixXd gram = basis.moments.transpose() * basis.coefficients;  // RᵀMR
  u -= basis.coefficients * gram.ldlt().solve(basis.moments.transpose() * u);
}

}  // namespace iga
