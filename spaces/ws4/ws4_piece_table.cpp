#include "spaces/ws4/ws4_piece_table.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <stdexcept>

#include "spaces/ws4/ws4_basis.hpp"
#include "spaces/ws4/ws4_knots.hpp"

namespace iga::ws4 {

namespace {

/// One of the six affine maps of the reference triangle onto itself: x -> offset + linear x,
/// and the permutation of the basis functions it induces (B_function[i](A x) = B_i(x)).
struct Symmetry {
  Eigen::Matrix2d linear;
  Point2 offset;
  std::array<int, 51> function;
};

/// The six symmetries, the identity first. The function permutation comes from the knot sets:
/// A maps the boundary points onto each other, and the knot multiset of B_i onto that of B_π(i).
std::vector<Symmetry> symmetries() {
  const Point2 corner[3] = {Point2(0, 0), Point2(1, 0), Point2(0, 1)};
  const int orders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  const auto& knots = ws4_knot_sets();
  std::vector<Symmetry> out;
  for (const auto& order : orders) {
    Symmetry s;
    s.offset = corner[order[0]];
    s.linear.col(0) = corner[order[1]] - corner[order[0]];
    s.linear.col(1) = corner[order[2]] - corner[order[0]];
    std::array<int, 12> point{};  // boundary point k -> A(point k)
    for (int k = 0; k < 12; ++k) {
      const Point2 image = s.offset + s.linear * Ws4Split::boundary_point(k);
      point[k] = -1;
      for (int l = 0; l < 12; ++l)
        if ((Ws4Split::boundary_point(l) - image).norm() < 1e-12) point[k] = l;
      if (point[k] < 0) throw std::logic_error("Ws4PieceTable: a symmetry does not map the boundary points");
    }
    for (int i = 0; i < 51; ++i) {
      std::array<int, 12> image{};
      for (int k = 0; k < 12; ++k) image[point[k]] = knots[i].multiplicity[k];
      s.function[i] = -1;
      for (int j = 0; j < 51; ++j)
        if (knots[j].multiplicity == image && knots[j].c == knots[i].c) s.function[i] = j;
      if (s.function[i] < 0) throw std::logic_error("Ws4PieceTable: a symmetry does not map the knot sets");
    }
    out.push_back(s);
  }
  return out;
}

}  // namespace

const Ws4PieceTable& Ws4PieceTable::reference() {
  static const Ws4PieceTable table = [] {
    const Ws4Basis& basis = Ws4Basis::reference();
    const int nr = static_cast<int>(basis.split().regions().size());
    const std::vector<Symmetry> maps = symmetries();
    Ws4PieceTable t;
    t.representative.assign(nr, -1);
    t.inverse_linear.resize(nr);
    t.piece_begin.resize(nr);
    t.block_begin.resize(nr);
    t.block_width.resize(nr);
    std::vector<const Symmetry*> map_of(nr, nullptr);
    std::vector<std::vector<int>> active_of(nr);  // the representatives' active functions
    for (int r0 = 0; r0 < nr; ++r0) {
      if (t.representative[r0] >= 0) continue;
      // r0 represents its orbit: store its pieces in both layouts.
      std::vector<int>& active = active_of[r0];
      for (int i = 0; i < Ws4Basis::size; ++i)
        if (!basis.piece(r0, i).is_zero()) active.push_back(i);
      const int n = static_cast<int>(active.size());
      const int width = (n + 3) / 4 * 4;
      const int piece_begin = static_cast<int>(t.by_function.size()) / padded;
      const int block_begin = static_cast<int>(t.by_monomial.size()) / monomials;
      t.max_width = std::max(t.max_width, width);
      t.by_function.resize(t.by_function.size() + static_cast<size_t>(n) * padded, 0.0);
      t.by_monomial.resize(t.by_monomial.size() + static_cast<size_t>(width) * monomials, 0.0);
      double* block = t.by_monomial.data() + static_cast<size_t>(block_begin) * monomials;
      for (int j = 0; j < n; ++j) {
        const Poly4& p = basis.piece(r0, active[j]);
        for (int a = 0; a <= Poly4::max_degree; ++a)
          for (int b = 0; a + b <= Poly4::max_degree; ++b) {
            t.by_function[static_cast<size_t>(piece_begin + j) * padded + Poly4::index(a, b)] = p.coefficient(a, b);
            block[Poly4::index(a, b) * width + j] = p.coefficient(a, b);
          }
      }
      // Its images: r = A(r0), located by the image of r0's center (an interior point).
      for (const Symmetry& s : maps) {
        const int r = basis.split().locate(s.offset + s.linear * basis.center(r0));
        if (t.representative[r] >= 0) continue;
        t.representative[r] = r0;
        map_of[r] = &s;
        t.inverse_linear[r] = s.linear.inverse();
        t.piece_begin[r] = piece_begin;
        t.block_begin[r] = block_begin;
        t.block_width[r] = width;
      }
      if (t.representative[r0] != r0) throw std::logic_error("Ws4PieceTable: the identity must map a region to itself");
    }
    // Per region, π of its representative's active functions, in the representative's order.
    t.begin.assign(1, 0);
    for (int r = 0; r < nr; ++r) {
      for (const int i : active_of[t.representative[r]]) t.function.push_back(map_of[r]->function[i]);
      t.begin.push_back(static_cast<int>(t.function.size()));
    }
    return t;
  }();
  return table;
}

}  // namespace iga::ws4
