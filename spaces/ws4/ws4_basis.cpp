#include "spaces/ws4/ws4_basis.hpp"

#include <cstdint>
#include <unordered_map>

#include "spaces/ws4/ws4_knots.hpp"

namespace iga::ws4 {

namespace {

using Counts = std::array<int, 12>;

std::uint64_t key(const Counts& c) {
  std::uint64_t k = 0;
  for (int i = 0; i < 12; ++i) k |= static_cast<std::uint64_t>(c[i]) << (3 * i);
  return k;
}

/// Twice the signed area of (a, b, c) in the integer coordinates 4 * (x, y) of boundary points:
/// exact, so collinearity of knots is decided exactly.
long long orient(int a, int b, int c) {
  const auto& p = Ws4Split::boundary_points();
  const long long ax = p[a][1], ay = p[a][2], bx = p[b][1], by = p[b][2], cx = p[c][1], cy = p[c][2];
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

/// Polynomial pieces on one region of the simplex splines M_Ξ for sub-multisets Ξ, memoised on Ξ,
/// in scalar type Real (the one-time construction runs in long double or double-double).
template <class Real>
class RegionRecurrence {
  using PolyL = BasicPoly4<Real>;
  struct PointL {
    Real x, y;
  };
  static Real cross2(const PointL& a, const PointL& b) { return a.x * b.y - a.y * b.x; }
  static PointL minus(const PointL& a, const PointL& b) { return {a.x - b.x, a.y - b.y}; }

 public:
  /// Pieces in coordinates x - center (small monomial coefficients, little cancellation).
  explicit RegionRecurrence(const Point2& center) : center_(center) {}

  const PolyL& M(const Counts& xi) {
    const std::uint64_t k = key(xi);
    auto it = memo_.find(k);
    if (it != memo_.end()) return it->second;
    PolyL result = compute(xi);
    return memo_.emplace(k, result).first->second;
  }

 private:
  PolyL compute(const Counts& xi) {
    std::vector<int> distinct;
    int total = 0;
    for (int i = 0; i < 12; ++i) {
      total += xi[i];
      if (xi[i] > 0) distinct.push_back(i);
    }
    // First affinely independent triple of distinct knots; none means collinear knots, a line
    // measure that vanishes off its line (and the region interior is off every knot line).
    int ta = -1, tb = -1, tc = -1;
    for (size_t i = 0; i < distinct.size() && ta < 0; ++i)
      for (size_t j = i + 1; j < distinct.size() && ta < 0; ++j)
        for (size_t l = j + 1; l < distinct.size() && ta < 0; ++l)
          if (orient(distinct[i], distinct[j], distinct[l]) != 0) {
            ta = distinct[i];
            tb = distinct[j];
            tc = distinct[l];
          }
    if (ta < 0) return PolyL();
    auto knot = [&](int k) {
      const auto& t = Ws4Split::boundary_points()[k];
      return PointL{Real(t[1]) / 4 - Real(center_.x()), Real(t[2]) / 4 - Real(center_.y())};
    };
    const PointL a = knot(ta), b = knot(tb), c = knot(tc);
    const Real det = cross2(minus(b, a), minus(c, a));
    const int d = total - 3;
    if (d == 0) {
      // 1/area on the open triangle: the region's center (the origin here, strictly inside the
      // region) decides.
      const PointL o{0, 0};
      const Real s0 = cross2(minus(b, a), minus(o, a)), s1 = cross2(minus(c, b), minus(o, b)),
                 s2 = cross2(minus(a, c), minus(o, c));
      const bool in = det > 0 ? (s0 > 0 && s1 > 0 && s2 > 0) : (s0 < 0 && s1 < 0 && s2 < 0);
      return PolyL::constant(in ? Real(2) / (det > 0 ? det : -det) : Real(0));
    }
    // Recurrence B: M_Ξ = (d+2)/d Σ_z β_z(x) M_{Ξ\z} with the barycentric coordinates β of x
    // w.r.t. (a, b, c); β_a(x) = (b×c + x×(b−c)) / det and cyclically.
    PolyL result;
    const int tri[3] = {ta, tb, tc};
    const PointL pts[3] = {a, b, c};
    for (int k = 0; k < 3; ++k) {
      const PointL& u = pts[(k + 1) % 3];
      const PointL& v = pts[(k + 2) % 3];
      const PointL e = minus(u, v);
      Counts sub = xi;
      --sub[tri[k]];
      const PolyL m = M(sub);  // copy: the memo may rehash while this frame is live
      if (m.is_zero()) continue;
      result.add_scaled(Real(d + 2) / d, m.times_affine(cross2(u, v) / det, e.y / det, -e.x / det));
    }
    return result;
  }

  Point2 center_;
  std::unordered_map<std::uint64_t, PolyL> memo_;
};

/// The pieces of the 51 functions on every region (region-major), c_i / 960 times M_{Ξ_i}, in Real.
template <class Real>
std::vector<BasicPoly4<Real>> build_pieces(const Ws4Split& split) {
  const auto& sets = ws4_knot_sets();
  const int nr = static_cast<int>(split.regions().size());
  std::vector<BasicPoly4<Real>> pieces(static_cast<size_t>(nr) * Ws4Basis::size);
  // Regions are independent (a tenth of a second of recurrences in all: worth the threads).
#pragma omp parallel for schedule(dynamic, 8)
  for (int r = 0; r < nr; ++r) {
    RegionRecurrence<Real> rec(split.regions()[r].centroid);
    for (int i = 0; i < Ws4Basis::size; ++i)
      pieces[r * Ws4Basis::size + i].add_scaled(Real(sets[i].c) / Real(960), rec.M(sets[i].multiplicity));
  }
  return pieces;
}

}  // namespace

const Ws4Basis& Ws4Basis::reference() {
  static const Ws4Basis basis;
  return basis;
}

Ws4Basis::Ws4Basis() : split_(Ws4Split::reference()), pieces_extended_(build_pieces<long double>(split_)) {
  pieces_.reserve(pieces_extended_.size());
  for (const BasicPoly4<long double>& p : pieces_extended_) pieces_.push_back(p.cast<double>());
}

std::vector<BasicPoly4<DoubleDouble>> Ws4Basis::pieces_double_double() const {
  return build_pieces<DoubleDouble>(split_);
}

void Ws4Basis::tabulate(const std::vector<Point2>& points, ReferenceDerivatives& out) const {
  const int q = static_cast<int>(points.size());
  for (Eigen::MatrixXd* m : {&out.value, &out.dxi, &out.deta, &out.dxixi, &out.dxieta, &out.detaeta}) m->resize(size, q);
  for (int k = 0; k < q; ++k) {
    const int r = split_.locate(points[k]);
    const Point2 x = points[k] - center(r);
    for (int i = 0; i < size; ++i) {
      const Poly4& p = piece(r, i);
      const Poly4 px = p.derivative(0), py = p.derivative(1);
      out.value(i, k) = p(x);
      out.dxi(i, k) = px(x);
      out.deta(i, k) = py(x);
      out.dxixi(i, k) = px.derivative(0)(x);
      out.dxieta(i, k) = px.derivative(1)(x);
      out.detaeta(i, k) = py.derivative(1)(x);
    }
  }
}

void Ws4Basis::directional_derivatives(const Point2& x, const std::vector<Point2>& w, double* out) const {
  const int r = split_.locate(x);
  for (int i = 0; i < size; ++i) {
    Poly4 p = piece(r, i);
    for (const Point2& v : w) p = p.directional(v);
    out[i] = p(x - center(r));
  }
}

}  // namespace iga::ws4
