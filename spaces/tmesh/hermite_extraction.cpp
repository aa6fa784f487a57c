#include "spaces/tmesh/hermite_extraction.hpp"
#include "config/worth_threads.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <exception>
#include <iterator>
#include <map>
#include <stdexcept>
#include <tuple>

#include "spaces/tmesh/hermite_dofs.hpp"
#include "spaces/tmesh/local_forms.hpp"
#include "spaces/tmesh/section_space.hpp"

namespace iga {

namespace {

using tmesh_detail::add_scaled;
using tmesh_detail::assign_divided;
using tmesh_detail::assign_scaled;
using tmesh_detail::ConstFormRef;
using tmesh_detail::FormRef;
using tmesh_detail::LocalForms;
using tmesh_detail::positions_in;
using tmesh_detail::subtract_scaled;

/// A function of the edge space V_e along a composite edge, T(x) = sum_m tau_m L^{-m} phi_m(x) in
/// the G-basis of order `order` (n for d_e = 2; n-2 with pi_rho = 0, i.e. x^m/m!, for d_e = 0):
/// what each composite edge needs to give the traces of its normal orders.
struct EdgeSpace {
  double length = 1.0;
  int order = 0;
  double pi_rho = 0.0;
  int last_order = 0;  ///< k_a: the last one-sided tangential order at the lo end
  int hermite = -1;    ///< index of the inverse Hermite matrix of (order, pi_rho, length, k_a)
};

/// Scaled derivatives h^d T^{(d)}(x), d = 0..dmax, of the traces of one edge space as coefficients
/// of tau_m: coef(d, m) = (h/L)^d g(d, m) with g the scaled G-basis at x/L, used where g(d, m) != 0.
struct TraceTable {
  int columns = 0;
  std::vector<double> coef;
  std::vector<char> used;
};

TraceTable make_trace_table(const EdgeSpace& es, double x, double h, int dmax) {
  const Eigen::MatrixXd g = g_basis_scaled(es.order, es.pi_rho, es.length, x / es.length, dmax);
  TraceTable t;
  t.columns = es.order + 1;
  for (int d = 0; d <= dmax; ++d) {
    const double scale = std::pow(h / es.length, d);
    for (int m = 0; m <= es.order; ++m) {
      t.coef.push_back(scale * g(d, m));
      t.used.push_back(g(d, m) != 0.0);
    }
  }
  return t;
}

/// Trace tables by (edge space, x, h, dmax): dyadic meshes have a handful; one cache per thread.
class TraceTables {
 public:
  const TraceTable& get(const EdgeSpace& es, double x, double h, int dmax) {
    const auto key = std::make_tuple(es.order, es.pi_rho, es.length, x, h, dmax);
    auto it = tables_.find(key);
    if (it == tables_.end()) it = tables_.emplace(key, make_trace_table(es, x, h, dmax)).first;
    return it->second;
  }

 private:
  std::map<std::tuple<int, double, double, double, double, int>, TraceTable> tables_;
};

/// d = sum_m coef(row, m) tau_m over the m the table uses, with the tau_m (forms `first + m` of
/// `traces`) placed into d's entries `at`.
void trace_derivative(const TraceTable& t, int row, const LocalForms& traces, int first, const int* at, FormRef d) {
  for (int m = 0; m < t.columns; ++m)
    if (t.used[row * t.columns + m])
      add_scaled(d, t.coef[row * t.columns + m], {traces.values(first + m), traces.stores(first + m)}, traces.width(), at);
}

/// Sorted union of sorted lists (through a per-thread buffer: no allocation once grown).
void merge_into(std::vector<int>& out, const std::vector<int>& more) {
  thread_local std::vector<int> merged;
  merged.clear();
  std::set_union(out.begin(), out.end(), more.begin(), more.end(), std::back_inserter(merged));
  out.swap(merged);
}

/// Per-thread scratch of the cell loop (no allocation per cell once grown).
struct CellScratch {
  TraceTables tables;
  std::vector<int> support, at, active;
  std::vector<double> coef_v, gamma_v, col_v, work_v, powers;
  std::vector<char> coef_s, gamma_s, col_s, work_s, set;
};

}  // namespace

HermiteExtraction hermite_extraction(const TMesh& mesh, int r) {
  const HermiteDofs dofs = number_hermite_dofs(mesh, r);
  const int n = dofs.n, nr = r + 1, ni = n - 2 * r - 1;
  const std::vector<int>&vbase = dofs.vertex_base, &ebase = dofs.edge_base, &cbase = dofs.cell_base;
  auto last_order = [&](const CompositeEdge& e) { return dofs.last_order(e); };
  const auto& V = mesh.vertices();
  const auto& E = mesh.edges();
  const int nc = mesh.num_cells();

  HermiteExtraction out;
  out.dimension = dofs.dimension;

  // Jets J_w[a + b nr] = D_s^a D_t^b p(w) (physical derivatives): the unit forms of their DOFs at
  // non-T-junction vertices, traces of their host edges at T-junctions (filled below).
  std::vector<LocalForms> jet(V.size());
  for (size_t v = 0; v < V.size(); ++v)
    if (!V[v].t_junction) {
      for (int k = 0; k < nr * nr; ++k) jet[v].support.push_back(vbase[v] + k);
      jet[v].reset(nr * nr);
      for (int k = 0; k < nr * nr; ++k) jet[v].values(k)[k] = 1.0, jet[v].stores(k)[k] = 1;
    }

  // Edge spaces, and the inverse Hermite matrices of the distinct ones (a dyadic mesh has a
  // handful), in dependency order so that the first singular edge is the one reported.
  std::vector<EdgeSpace> space(E.size());
  std::vector<Eigen::MatrixXd> hermite_inverse;
  {
    std::map<std::tuple<int, double, double, int>, int> known;
    for (int e : mesh.edge_order()) {
      const CompositeEdge& ce = E[e];
      const double unit_len = ce.horizontal ? mesh.unit().x() : mesh.unit().y();
      EdgeSpace& es = space[e];
      es.length = (ce.hi - ce.lo) * unit_len;
      es.last_order = last_order(ce);
      // V_e: the common section space (d_e = 2) or the polynomials of degree n-2 (d_e = 0).
      const TCell& c0 = mesh.cells()[ce.cells.front()];
      const SectionSpec& along = mesh.sections()[ce.horizontal ? c0.section_s : c0.section_t];
      es.order = ce.d == 2 ? n : n - 2;
      es.pi_rho = ce.d == 2 ? along.pi_rho() : 0.0;
      const auto key = std::make_tuple(es.order, es.pi_rho, es.length, es.last_order);
      auto it = known.find(key);
      if (it == known.end()) {
        const int ka = es.last_order, order = es.order;
        const double L = es.length;
        const Eigen::MatrixXd g0 = g_basis_scaled(order, es.pi_rho, L, 0.0, ka);
        const Eigen::MatrixXd g1 = g_basis_scaled(order, es.pi_rho, L, 1.0, r);
        Eigen::MatrixXd H(order + 1, order + 1);
        for (int i = 0; i <= ka; ++i) H.row(i) = g0.row(i);
        for (int i = 0; i <= r; ++i) H.row(ka + 1 + i) = g1.row(i);
        // Lemma 3 needs a Hermite-unisolvent edge space; a trigonometric edge can be too long for that.
        const Eigen::FullPivLU<Eigen::MatrixXd> lu(H);
        if (!lu.isInvertible() || lu.rcond() < 1e-13)
          throw std::invalid_argument("the Hermite interpolation on a composite edge of length " + std::to_string(L) +
                                      " is singular in its section space (trigonometric w L too large)");
        it = known.emplace(key, static_cast<int>(hermite_inverse.size())).first;
        hermite_inverse.push_back(lu.inverse());
      }
      es.hermite = it->second;
    }
  }

  // Edges: traces for each normal order (form b (order+1) + m is tau_m of normal order b), then
  // the jets of their T-junctions. An edge needs the jets of its ends only, which the edges it
  // depends on give: edges of one dependency depth are independent and run in parallel.
  std::vector<LocalForms> traces(E.size());
  std::vector<std::vector<int>> by_depth;
  {
    std::vector<int> depth(E.size(), 0);
    for (int e : mesh.edge_order()) {
      for (int d : E[e].deps) depth[e] = std::max(depth[e], depth[d] + 1);
      if (static_cast<int>(by_depth.size()) <= depth[e]) by_depth.resize(depth[e] + 1);
      by_depth[depth[e]].push_back(e);
    }
  }
  for (const std::vector<int>& level : by_depth) {
    const int count = static_cast<int>(level.size());
    std::exception_ptr failure;
#pragma omp parallel if (worth_threads(count))
    {
      TraceTables tables;
      std::vector<int> at_a, at_b, own;
      std::vector<double> rhs_v, powers;
      std::vector<char> rhs_s;
#pragma omp for schedule(dynamic, 64)
      for (int q = 0; q < count; ++q) {
        try {
          const int e = level[q];
          const CompositeEdge& ce = E[e];
          const EdgeSpace& es = space[e];
          const int ka = es.last_order, order = es.order, ne = ka - r;
          const double L = es.length;
          const Eigen::MatrixXd& Hinv = hermite_inverse[es.hermite];
          const LocalForms& ja = jet[ce.v_lo];
          const LocalForms& jb = jet[ce.v_hi];
          if (ja.count == 0 || jb.count == 0) throw std::logic_error("hermite_extraction: edge processed before its end jets");
          LocalForms& T = traces[e];
          T.support = ja.support;
          merge_into(T.support, jb.support);
          if (ne > 0) {
            own.resize(nr * ne);
            for (int k = 0; k < nr * ne; ++k) own[k] = ebase[e] + k;
            merge_into(T.support, own);
          }
          positions_in(ja.support, T.support, at_a);
          positions_in(jb.support, T.support, at_b);
          const int w = T.width();
          T.reset(nr * (order + 1));
          rhs_v.resize(static_cast<std::size_t>(order + 1) * w);
          rhs_s.resize(rhs_v.size());
          auto rhs = [&](int k) {
            const std::size_t at = static_cast<std::size_t>(k) * w;
            return FormRef{rhs_v.data() + at, rhs_s.data() + at};
          };
          powers.resize(r + 1);
          for (int i = 0; i <= r; ++i) powers[i] = std::pow(L, i);
          for (int b = 0; b < nr; ++b) {
            // Jet index of (tangential order i, normal order b).
            auto jidx = [&](int i) { return ce.horizontal ? i + b * nr : b + i * nr; };
            std::fill(rhs_v.begin(), rhs_v.end(), 0.0);
            std::fill(rhs_s.begin(), rhs_s.end(), 0);
            for (int i = 0; i <= r; ++i) {
              const double scale = powers[i];
              for (int j = 0; j < ja.width(); ++j) {
                rhs(i).v[at_a[j]] = scale * ja.values(jidx(i))[j];
                rhs(i).s[at_a[j]] = ja.stores(jidx(i))[j];
              }
              for (int j = 0; j < jb.width(); ++j) {
                rhs(ka + 1 + i).v[at_b[j]] = scale * jb.values(jidx(i))[j];
                rhs(ka + 1 + i).s[at_b[j]] = jb.stores(jidx(i))[j];
              }
            }
            for (int i = r + 1; i <= ka; ++i) {
              const int dof = ebase[e] + b * ne + (i - r - 1);
              const int at = static_cast<int>(std::lower_bound(T.support.begin(), T.support.end(), dof) - T.support.begin());
              rhs(i).v[at] = 1.0;
              rhs(i).s[at] = 1;
            }
            for (int m = 0; m <= order; ++m) {
              const FormRef tau{T.values(b * (order + 1) + m), T.stores(b * (order + 1) + m)};
              for (int k = 0; k <= order; ++k)
                if (Hinv(m, k) != 0.0) add_scaled(tau, Hinv(m, k), {rhs(k).v, rhs(k).s}, w);
            }
          }
          const double unit_len = ce.horizontal ? mesh.unit().x() : mesh.unit().y();
          for (int v : ce.t_junctions) {
            const double x = ((ce.horizontal ? V[v].x : V[v].y) - ce.lo) * unit_len;
            const TraceTable& t = tables.get(es, x, 1.0, r);
            LocalForms& J = jet[v];
            J.support = T.support;
            J.reset(nr * nr);
            for (int b = 0; b < nr; ++b)
              for (int i = 0; i <= r; ++i) {
                const int k = ce.horizontal ? i + b * nr : b + i * nr;
                trace_derivative(t, i, T, b * (order + 1), nullptr, {J.values(k), J.stores(k)});
              }
          }
        } catch (...) {
#pragma omp critical(hermite_extraction_failure)
          if (!failure) failure = std::current_exception();
        }
      }
    }
    if (failure) std::rethrow_exception(failure);
  }

  // Bernstein derivatives at both ends of every (section, side length) of the cells.
  struct EndTables {
    Eigen::MatrixXd at0, at1;
  };
  std::map<CellSideKey, EndTables> ends;
  for (int c = 0; c < nc; ++c) {
    const TCell& cell = mesh.cells()[c];
    for (const auto& [key, h] : {std::make_pair(side_key_x(cell), mesh.width(c)), std::make_pair(side_key_y(cell), mesh.height(c))})
      if (!ends.count(key)) {
        const SectionBernstein bern(mesh.sections()[std::get<0>(key)], h);
        ends.emplace(key, EndTables{bern.derivatives(0.0, n), bern.derivatives(1.0, n)});
      }
  }

  // Cells: boundary strips of coefficients from the four side traces, interior from (C) DOFs. All
  // forms of a cell live on the union of its side traces' supports and its own DOFs.
  out.dofs.resize(nc);
  out.matrix.resize(nc);
  const int nl = (n + 1) * (n + 1);
  std::exception_ptr failure;
#pragma omp parallel if (worth_threads(nc))
  {
    CellScratch s;
    double mismatch = 0.0;
#pragma omp for schedule(dynamic, 64)
    for (int c = 0; c < nc; ++c) {
      try {
        const TCell& cell = mesh.cells()[c];
        const double hx = mesh.width(c), hy = mesh.height(c);
        const EndTables& bx = ends.at(side_key_x(cell));
        const EndTables& by = ends.at(side_key_y(cell));
        s.support.clear();
        for (int side = 0; side < 4; ++side) merge_into(s.support, traces[mesh.side_edge(c, side)].support);
        const int first_own = cbase[c], own = ni * ni;
        s.at.resize(own);
        for (int k = 0; k < own; ++k) s.at[k] = first_own + k;
        merge_into(s.support, s.at);
        const int w = static_cast<int>(s.support.size());
        const std::size_t W = static_cast<std::size_t>(w);
        s.coef_v.assign(nl * W, 0.0);
        s.coef_s.assign(nl * W, 0);
        s.set.assign(nl, 0);
        s.gamma_v.resize(nr * (n + 1) * W);
        s.gamma_s.resize(s.gamma_v.size());
        s.col_v.resize((n + 1) * W);
        s.col_s.resize(s.col_v.size());
        s.work_v.resize(W);
        s.work_s.resize(W);
        auto coef = [&](int loc) { return FormRef{s.coef_v.data() + loc * W, s.coef_s.data() + loc * W}; };
        auto gamma = [&](int b, int i) {
          const std::size_t at = (b * (n + 1) + i) * W;
          return FormRef{s.gamma_v.data() + at, s.gamma_s.data() + at};
        };
        auto col = [&](int l) { return FormRef{s.col_v.data() + l * W, s.col_s.data() + l * W}; };
        const FormRef work{s.work_v.data(), s.work_s.data()};
        auto cref = [](FormRef f) { return ConstFormRef{f.v, f.s}; };
        auto assign = [&](int i, int j, FormRef f) {
          const int loc = i + j * (n + 1);
          if (s.set[loc]) {
            // Both sides determine this coefficient: compare (round-off when consistent).
            const FormRef known = coef(loc);
            double scale = 1.0, m = 0.0;
            for (int k = 0; k < w; ++k) {
              scale = std::max(scale, std::abs(f.v[k]));
              m = std::max(m, std::abs(known.v[k] - f.v[k]));
            }
            mismatch = std::max(mismatch, m / scale);
            return;
          }
          s.set[loc] = 1;
          std::copy_n(f.v, w, coef(loc).v);
          std::copy_n(f.s, w, coef(loc).s);
        };
        for (int side = 0; side < 4; ++side) {
          const int e = mesh.side_edge(c, side);
          const CompositeEdge& ce = E[e];
          const bool horizontal = side == 0 || side == 2;
          const double unit_len = horizontal ? mesh.unit().x() : mesh.unit().y();
          const double x = ((horizontal ? cell.x0 : cell.y0) - ce.lo) * unit_len;  // side start along the edge
          const double h_tan = horizontal ? hx : hy, h_nor = horizontal ? hy : hx;
          const Eigen::MatrixXd& T0 = horizontal ? bx.at0 : by.at0;  // tangential Bernstein at the side start
          const Eigen::MatrixXd& N = (side == 0 || side == 3) ? (horizontal ? by.at0 : bx.at0) : (horizontal ? by.at1 : bx.at1);
          const bool at_start = side == 0 || side == 3;
          const LocalForms& T = traces[e];
          const int order = space[e].order;
          positions_in(T.support, s.support, s.at);
          const TraceTable& table = s.tables.get(space[e], x, h_tan, n);
          // gamma[b][i]: tangential Bernstein coefficients of the normal-order-b trace (physical).
          for (int b = 0; b < nr; ++b)
            for (int i = 0; i <= n; ++i) {
              std::fill_n(work.v, w, 0.0);
              std::fill_n(work.s, w, 0);
              trace_derivative(table, i, T, b * (order + 1), s.at.data(), work);
              for (int k = 0; k < i; ++k)
                if (T0(i, k) != 0.0) subtract_scaled(work, T0(i, k), cref(gamma(b, k)), w);
              assign_divided(gamma(b, i), cref(work), T0(i, i), w);
            }
          // Normal direction: sum_l c_{i,l} N(b, l) = h_nor^b gamma[b][i], triangular in b.
          s.powers.resize(nr);
          for (int b = 0; b < nr; ++b) s.powers[b] = std::pow(h_nor, b);
          for (int i = 0; i <= n; ++i)
            for (int b = 0; b < nr; ++b) {
              const int l = at_start ? b : n - b;
              assign_scaled(work, s.powers[b], cref(gamma(b, i)), w);
              for (int bb = 0; bb < b; ++bb) {
                const int ll = at_start ? bb : n - bb;
                if (N(b, ll) != 0.0) subtract_scaled(work, N(b, ll), cref(col(ll)), w);
              }
              assign_divided(col(l), cref(work), N(b, l), w);
              if (horizontal)
                assign(i, l, col(l));
              else
                assign(l, i, col(l));
            }
        }
        for (int j = r + 1; j < n - r; ++j)
          for (int i = r + 1; i < n - r; ++i) {
            const int dof = cbase[c] + (i - r - 1) + (j - r - 1) * ni;
            const int at = static_cast<int>(std::lower_bound(s.support.begin(), s.support.end(), dof) - s.support.begin());
            std::fill_n(work.v, w, 0.0);
            std::fill_n(work.s, w, 0);
            work.v[at] = 1.0;
            work.s[at] = 1;
            assign(i, j, work);
          }
        for (int loc = 0; loc < nl; ++loc)
          if (!s.set[loc]) throw std::logic_error("hermite_extraction: a Bernstein coefficient was not determined");
        // Dense block over the active functions: the DOFs some coefficient form stores.
        s.active.assign(w, -1);
        std::vector<int>& dofs = out.dofs[c];
        dofs.clear();
        for (int k = 0; k < w; ++k)
          for (int loc = 0; loc < nl; ++loc)
            if (s.coef_s[loc * W + k]) {
              s.active[k] = static_cast<int>(dofs.size());
              dofs.push_back(s.support[k]);
              break;
            }
        Eigen::MatrixXd& M = out.matrix[c];
        M = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(dofs.size()), nl);
        for (int loc = 0; loc < nl; ++loc)
          for (int k = 0; k < w; ++k)
            if (s.coef_s[loc * W + k]) M(s.active[k], loc) = s.coef_v[loc * W + k];
      } catch (...) {
#pragma omp critical(hermite_extraction_failure)
        if (!failure) failure = std::current_exception();
      }
    }
#pragma omp critical(hermite_extraction_mismatch)
    out.corner_mismatch = std::max(out.corner_mismatch, mismatch);
  }
  if (failure) std::rethrow_exception(failure);
  return out;
}

}  // namespace iga
