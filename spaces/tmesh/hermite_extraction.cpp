#include "spaces/tmesh/hermite_extraction.hpp"

#include <Eigen/LU>
#include <cmath>
#include <map>
#include <stdexcept>

#include "spaces/tmesh/section_space.hpp"

namespace iga {

namespace {

/// A linear form in the global DOF vector.
using Form = Eigen::SparseVector<double>;

/// A function of the edge space V_e along a composite edge, T(x) = sum_m tau_m L^{-m} phi_m(x) in
/// the G-basis of order `order` (n for d_e = 2; n-2 with pi_rho = 0, i.e. x^m/m!, for d_e = 0).
struct Trace {
  double length = 1.0;
  int order = 0;
  double pi_rho = 0.0;
  std::vector<Form> tau;  // order+1
};

/// Scaled derivatives (h^d T^{(d)}) of a trace at x for d = 0..dmax, as forms.
std::vector<Form> trace_derivatives(const Trace& T, double x, double h, int dmax, int ndof) {
  const Eigen::MatrixXd g = g_basis_scaled(T.order, T.pi_rho, T.length, x / T.length, dmax);
  std::vector<Form> out(dmax + 1, Form(ndof));
  for (int d = 0; d <= dmax; ++d) {
    const double scale = std::pow(h / T.length, d);
    for (int m = 0; m <= T.order; ++m)
      if (g(d, m) != 0.0) out[d] += (scale * g(d, m)) * T.tau[m];
  }
  return out;
}

}  // namespace

HermiteExtraction hermite_extraction(const TMesh& mesh, int r) {
  if (!mesh.admissibility_problem().empty())
    throw std::invalid_argument("the T-mesh is not admissible: " + mesh.admissibility_problem());
  const int n = mesh.sections()[mesh.cells()[0].section_s].n;
  for (const SectionSpec& sp : mesh.sections())
    if (sp.n != n) throw std::invalid_argument("the Hermite extraction needs the same n in every section space");
  bool reduced = false;  // some edge with d_e = 0
  for (const CompositeEdge& e : mesh.edges()) {
    if (e.d == 1) throw std::invalid_argument("composite edges with d_e = 1 are not supported by the Hermite extraction");
    reduced = reduced || e.d == 0;
  }
  const int need = reduced ? 2 * r + 3 : 2 * r + 1;
  if (r < 0 || n < need)
    throw std::invalid_argument("C^" + std::to_string(r) + " generalized splines need n >= " + std::to_string(need) +
                                (reduced ? " (edges between different section spaces)" : "") + " (got n = " +
                                std::to_string(n) + ")");
  const int nr = r + 1, ni = n - 2 * r - 1;
  // Per edge: last one-sided tangential order k_a and edge DOFs per normal order (k_a - r).
  auto last_order = [&](const CompositeEdge& e) { return n - r - 3 + e.d; };
  const auto& V = mesh.vertices();
  const auto& E = mesh.edges();
  const int nc = mesh.num_cells();

  HermiteExtraction out;
  // DOF numbering.
  std::vector<int> vbase(V.size(), -1), ebase(E.size()), cbase(nc);
  int next = 0;
  for (size_t v = 0; v < V.size(); ++v)
    if (!V[v].t_junction) {
      vbase[v] = next;
      next += nr * nr;
    }
  out.num_vertex_dofs = next;
  for (size_t e = 0; e < E.size(); ++e) {
    ebase[e] = next;
    next += nr * (last_order(E[e]) - r);
  }
  out.num_edge_dofs = next - out.num_vertex_dofs;
  for (int c = 0; c < nc; ++c) {
    cbase[c] = next;
    next += ni * ni;
  }
  out.num_cell_dofs = next - out.num_vertex_dofs - out.num_edge_dofs;
  const int ndof = next;
  out.dimension = ndof;
  auto unit = [&](int k) {
    Form f(ndof);
    f.insert(k) = 1.0;
    return f;
  };

  // Jets J_w[a + b nr] = D_s^a D_t^b p(w) (physical derivatives).
  std::vector<std::vector<Form>> jet(V.size());
  for (size_t v = 0; v < V.size(); ++v)
    if (!V[v].t_junction) {
      jet[v].resize(nr * nr);
      for (int k = 0; k < nr * nr; ++k) jet[v][k] = unit(vbase[v] + k);
    }

  // Edges in dependency order: traces for each normal order, then the jets of their T-junctions.
  std::vector<std::vector<Trace>> traces(E.size());
  for (int e : mesh.edge_order()) {
    const CompositeEdge& ce = E[e];
    const double unit_len = ce.horizontal ? mesh.unit().x() : mesh.unit().y();
    const double L = (ce.hi - ce.lo) * unit_len;
    const int ka = last_order(ce), ne = ka - r;
    // V_e: the common section space (d_e = 2) or the polynomials of degree n-2 (d_e = 0).
    const TCell& c0 = mesh.cells()[ce.cells.front()];
    const SectionSpec& along = mesh.sections()[ce.horizontal ? c0.section_s : c0.section_t];
    const int order = ce.d == 2 ? n : n - 2;
    const double pr = ce.d == 2 ? along.pi_rho() : 0.0;
    const Eigen::MatrixXd g0 = g_basis_scaled(order, pr, L, 0.0, ka);
    const Eigen::MatrixXd g1 = g_basis_scaled(order, pr, L, 1.0, r);
    Eigen::MatrixXd H(order + 1, order + 1);
    for (int i = 0; i <= ka; ++i) H.row(i) = g0.row(i);
    for (int i = 0; i <= r; ++i) H.row(ka + 1 + i) = g1.row(i);
    // Lemma 3 needs a Hermite-unisolvent edge space; a trigonometric edge can be too long for that.
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(H);
    if (!lu.isInvertible() || lu.rcond() < 1e-13)
      throw std::invalid_argument("the Hermite interpolation on a composite edge of length " + std::to_string(L) +
                                  " is singular in its section space (trigonometric w L too large)");
    const Eigen::MatrixXd Hinv = lu.inverse();
    const auto& ja = jet[ce.v_lo];
    const auto& jb = jet[ce.v_hi];
    if (ja.empty() || jb.empty()) throw std::logic_error("hermite_extraction: edge processed before its end jets");
    traces[e].resize(nr);
    for (int b = 0; b < nr; ++b) {
      // Jet index of (tangential order i, normal order b).
      auto jidx = [&](int i) { return ce.horizontal ? i + b * nr : b + i * nr; };
      std::vector<Form> rhs(order + 1, Form(ndof));
      for (int i = 0; i <= r; ++i) {
        rhs[i] = std::pow(L, i) * ja[jidx(i)];
        rhs[ka + 1 + i] = std::pow(L, i) * jb[jidx(i)];
      }
      for (int i = r + 1; i <= ka; ++i) rhs[i] = unit(ebase[e] + b * ne + (i - r - 1));
      Trace& T = traces[e][b];
      T.length = L;
      T.order = order;
      T.pi_rho = pr;
      T.tau.assign(order + 1, Form(ndof));
      for (int m = 0; m <= order; ++m)
        for (int k = 0; k <= order; ++k)
          if (Hinv(m, k) != 0.0) T.tau[m] += Hinv(m, k) * rhs[k];
    }
    for (int v : ce.t_junctions) {
      const double x = ((ce.horizontal ? V[v].x : V[v].y) - ce.lo) * unit_len;
      jet[v].assign(nr * nr, Form(ndof));
      for (int b = 0; b < nr; ++b) {
        const std::vector<Form> d = trace_derivatives(traces[e][b], x, 1.0, r, ndof);
        for (int i = 0; i <= r; ++i) jet[v][ce.horizontal ? i + b * nr : b + i * nr] = d[i];
      }
    }
  }

  // Cells: boundary strips of coefficients from the four side traces, interior from (C) DOFs.
  out.dofs.resize(nc);
  out.matrix.resize(nc);
  const int nl = (n + 1) * (n + 1);
  for (int c = 0; c < nc; ++c) {
    const TCell& cell = mesh.cells()[c];
    const double hx = mesh.width(c), hy = mesh.height(c);
    const SectionBernstein bx(mesh.sections()[cell.section_s], hx), by(mesh.sections()[cell.section_t], hy);
    const Eigen::MatrixXd X0 = bx.derivatives(0.0, n), X1 = bx.derivatives(1.0, n);
    const Eigen::MatrixXd Y0 = by.derivatives(0.0, n), Y1 = by.derivatives(1.0, n);
    std::vector<Form> coef(nl, Form(ndof));
    std::vector<char> set(nl, 0);
    auto assign = [&](int i, int j, Form f) {
      const int loc = i + j * (n + 1);
      if (set[loc]) {
        const Form diff = coef[loc] - f;
        double scale = 1.0;
        for (Form::InnerIterator it(f); it; ++it) scale = std::max(scale, std::abs(it.value()));
        double m = 0.0;
        for (Form::InnerIterator it(diff); it; ++it) m = std::max(m, std::abs(it.value()));
        out.corner_mismatch = std::max(out.corner_mismatch, m / scale);
        return;
      }
      set[loc] = 1;
      coef[loc] = std::move(f);
    };
    for (int side = 0; side < 4; ++side) {
      const int e = mesh.side_edge(c, side);
      const CompositeEdge& ce = E[e];
      const bool horizontal = side == 0 || side == 2;
      const double unit_len = horizontal ? mesh.unit().x() : mesh.unit().y();
      const double x = ((horizontal ? cell.x0 : cell.y0) - ce.lo) * unit_len;  // side start along the edge
      const double h_tan = horizontal ? hx : hy, h_nor = horizontal ? hy : hx;
      const Eigen::MatrixXd& T0 = horizontal ? X0 : Y0;  // tangential Bernstein at the side start
      const Eigen::MatrixXd& N = (side == 0 || side == 3) ? (horizontal ? Y0 : X0) : (horizontal ? Y1 : X1);
      const bool at_start = side == 0 || side == 3;
      // gamma[b][i]: tangential Bernstein coefficients of the normal-order-b trace (physical).
      std::vector<std::vector<Form>> gamma(nr, std::vector<Form>(n + 1, Form(ndof)));
      for (int b = 0; b < nr; ++b) {
        const std::vector<Form> d = trace_derivatives(traces[e][b], x, h_tan, n, ndof);
        for (int i = 0; i <= n; ++i) {
          Form g = d[i];
          for (int k = 0; k < i; ++k)
            if (T0(i, k) != 0.0) g -= T0(i, k) * gamma[b][k];
          gamma[b][i] = g / T0(i, i);
        }
      }
      // Normal direction: sum_l c_{i,l} N(b, l) = h_nor^b gamma[b][i], triangular in b.
      for (int i = 0; i <= n; ++i) {
        std::vector<Form> col(n + 1, Form(ndof));
        for (int b = 0; b < nr; ++b) {
          const int l = at_start ? b : n - b;
          Form f = std::pow(h_nor, b) * gamma[b][i];
          for (int bb = 0; bb < b; ++bb) {
            const int ll = at_start ? bb : n - bb;
            if (N(b, ll) != 0.0) f -= N(b, ll) * col[ll];
          }
          col[l] = f / N(b, l);
          if (horizontal)
            assign(i, l, col[l]);
          else
            assign(l, i, col[l]);
        }
      }
    }
    for (int j = r + 1; j < n - r; ++j)
      for (int i = r + 1; i < n - r; ++i) assign(i, j, unit(cbase[c] + (i - r - 1) + (j - r - 1) * ni));
    for (int loc = 0; loc < nl; ++loc)
      if (!set[loc]) throw std::logic_error("hermite_extraction: a Bernstein coefficient was not determined");
    // Dense block over the active functions.
    std::map<int, int> active;
    for (const Form& f : coef)
      for (Form::InnerIterator it(f); it; ++it) active.emplace(int(it.index()), 0);
    std::vector<int>& dofs = out.dofs[c];
    for (auto& [g, a] : active) {
      a = static_cast<int>(dofs.size());
      dofs.push_back(g);
    }
    Eigen::MatrixXd& M = out.matrix[c];
    M = Eigen::MatrixXd::Zero(dofs.size(), nl);
    for (int loc = 0; loc < nl; ++loc)
      for (Form::InnerIterator it(coef[loc]); it; ++it) M(active[int(it.index())], loc) = it.value();
  }
  return out;
}

}  // namespace iga
