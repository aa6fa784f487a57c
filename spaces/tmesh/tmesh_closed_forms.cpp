#include "spaces/tmesh/tmesh_closed_forms.hpp"

#include <atomic>
#include <functional>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "quadrature/quadrature_rule.hpp"

namespace iga {

TMeshClosedForms::TMeshClosedForms(const TMeshSpace& space) : space_(space) {
  // Side integrals with the 1D Gauss rule of the assembly's tensor rule on coarse cells, and with
  // that rule's 8 extra points on fine ones too: the closed-form matrices go to the double-double
  // solve, where a quadrature error of 1e-17 is not round-off (the plate's L2 error moved by
  // 2e-4 relative with 4 extra points at w h = pi/128). They are computed once per side length.
  const int n = space.section().n;
  const QuadratureRule gauss = gauss_legendre_for_degree(2 * n + 1 + (space.extra_degree() > 0 ? kFullExtraDegree : 0));
  for (const auto& [key, b] : space.bernstein_bases()) {
    DerivativeMoments<LongDoubleMatrix>& s = side_integrals_[key];
    DerivativeMoments<DoubleDoubleMatrix>& sd = side_integrals_dd_[key];
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) {
        s.moment[a][c].setZero(b.n() + 1, b.n() + 1);
        sd.moment[a][c].hi.setZero(b.n() + 1, b.n() + 1);
        sd.moment[a][c].lo.setZero(b.n() + 1, b.n() + 1);
      }
    for (int k = 0; k < gauss.size(); ++k) {
      const Eigen::MatrixXd d = b.derivatives(gauss.points[k].x(), 2);
      const double w = gauss.weights[k];
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c)
          for (int j = 0; j <= b.n(); ++j)
            for (int i = 0; i <= b.n(); ++i) {
              s.moment[a][c](i, j) += static_cast<long double>(w) * static_cast<long double>(d(a, i)) *
                                      static_cast<long double>(d(c, j));
              // Double-double: w d_i exact (two-product), then times d_j, summed with compensated
              // additions.
              sd.moment[a][c].set(i, j, sd.moment[a][c](i, j) + dd_detail::two_prod(w, d(a, i)) * d(c, j));
            }
    }
  }
  static std::atomic<std::uint64_t> next_instance{1};
  instance_id_ = next_instance++;
}

namespace {
/// The cell map x = x0 + diag(hx, hy) ξ.
Eigen::Matrix2d cell_jacobian(const TMesh& mesh, int cell) {
  return Eigen::Vector2d(mesh.width(cell), mesh.height(cell)).asDiagonal();
}
}  // namespace

bool TMeshClosedForms::double_double(int element, BilinearForm form, DoubleDoubleMatrix& local) const {
  const TMesh& mesh = space_.mesh();
  const TCell& cell = mesh.cells()[element];
  // K_c depends on the form, the sections and the side lengths only: a dyadic mesh has a handful,
  // so each thread keeps them (keyed by this space, whose id no later space reuses).
  using Key = std::tuple<int, int, std::int64_t, int, std::int64_t>;
  struct Cache {
    std::uint64_t owner = 0;
    std::map<Key, DoubleDoubleMatrix> matrices;
  };
  thread_local Cache cache;
  if (cache.owner != instance_id_) {
    cache.owner = instance_id_;
    cache.matrices.clear();
  }
  const Key key{static_cast<int>(form), cell.section_s, cell.x1 - cell.x0, cell.section_t, cell.y1 - cell.y0};
  auto it = cache.matrices.find(key);
  if (it == cache.matrices.end()) {
    it = cache.matrices.emplace(key, DoubleDoubleMatrix()).first;
    tensor_form_matrix(side_integrals_dd_.at(side_key_x(cell)), side_integrals_dd_.at(side_key_y(cell)),
                       affine_form_terms<DoubleDouble>(form, cell_jacobian(mesh, element)), it->second);
  }
  const DoubleDoubleMatrix& k = it->second;
  const Eigen::MatrixXd& e = space_.extraction().matrix[element];
  // Cells of one size away from T-junctions and the boundary share E_c as well (the same Hermite
  // functions, the same scaling): their matrices are computed once, looked up by the bytes of E_c.
  struct Known {
    Eigen::MatrixXd e;
    DoubleDoubleMatrix local;
  };
  thread_local std::map<std::pair<const DoubleDoubleMatrix*, std::size_t>, std::vector<Known>> known;
  thread_local std::uint64_t known_owner = 0;
  thread_local std::size_t known_count = 0;
  if (known_owner != instance_id_ || known_count > 1024) {  // bounded (a few MB): graded meshes have many
    known_owner = instance_id_;
    known.clear();
    known_count = 0;
  }
  const std::size_t hash = std::hash<std::string_view>{}(
      std::string_view(reinterpret_cast<const char*>(e.data()), static_cast<std::size_t>(e.size()) * sizeof(double)));
  std::vector<Known>& same_hash = known[{&k, hash}];
  for (const Known& c : same_hash)
    if (c.e.rows() == e.rows() && c.e.cols() == e.cols() && c.e == e) {
      local = c.local;
      return true;
    }
  // E_c is active × local: the extraction of affine_element_matrices.hpp is its transpose.
  symmetric_congruence(e.transpose(), k, local);
  same_hash.push_back({e, local});
  ++known_count;
  return true;
}

bool TMeshClosedForms::extended(int element, BilinearForm form, LongDoubleMatrix& local) const {
  const TMesh& mesh = space_.mesh();
  const TCell& cell = mesh.cells()[element];
  thread_local LongDoubleMatrix k;  // scratch: no allocation per element
  tensor_form_matrix(side_integrals_.at(side_key_x(cell)), side_integrals_.at(side_key_y(cell)),
                     affine_form_terms<long double>(form, cell_jacobian(mesh, element)), k);
  symmetric_congruence(space_.extraction().matrix[element].transpose(), k, local);
  return true;
}

bool TMeshClosedForms::rounded(int element, BilinearForm form, Eigen::MatrixXd& local) const {
  LongDoubleMatrix extended;
  this->extended(element, form, extended);
  local = extended.cast<double>();
  return true;
}

}  // namespace iga
