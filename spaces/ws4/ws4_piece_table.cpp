#include "spaces/ws4/ws4_piece_table.hpp"

#include <algorithm>

#include "spaces/ws4/ws4_basis.hpp"

namespace iga::ws4 {

const Ws4PieceTable& Ws4PieceTable::reference() {
  static const Ws4PieceTable table = [] {
    const Ws4Basis& basis = Ws4Basis::reference();
    const int nr = static_cast<int>(basis.split().regions().size());
    Ws4PieceTable t;
    t.begin.assign(1, 0);
    t.block_begin.assign(1, 0);
    for (int r = 0; r < nr; ++r) {
      const int first = static_cast<int>(t.function.size());
      for (int i = 0; i < Ws4Basis::size; ++i)
        if (!basis.piece(r, i).is_zero()) t.function.push_back(i);
      const int n = static_cast<int>(t.function.size()) - first;
      const int width = (n + 3) / 4 * 4;
      t.begin.push_back(first + n);
      t.block_begin.push_back(t.block_begin.back() + width);
      t.max_width = std::max(t.max_width, width);
      t.by_function.resize(t.function.size() * padded, 0.0);
      t.by_monomial.resize(static_cast<size_t>(t.block_begin.back()) * monomials, 0.0);
      double* block = t.by_monomial.data() + static_cast<size_t>(t.block_begin[r]) * monomials;
      for (int j = 0; j < n; ++j) {
        const Poly4& p = basis.piece(r, t.function[first + j]);
        for (int a = 0; a <= Poly4::max_degree; ++a)
          for (int b = 0; a + b <= Poly4::max_degree; ++b) {
            const int m = Poly4::index(a, b);
            t.by_function[static_cast<size_t>(first + j) * padded + m] = p.coefficient(a, b);
            block[m * width + j] = p.coefficient(a, b);
          }
      }
    }
    return t;
  }();
  return table;
}

}  // namespace iga::ws4
