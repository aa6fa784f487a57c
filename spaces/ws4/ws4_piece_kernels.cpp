#include "spaces/ws4/ws4_piece_kernels.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <type_traits>

#include "config/cpu_dispatch.hpp"
#include "spaces/ws4/poly4.hpp"

// Three copies of each kernel (IGA_X86_64_V3_V4_CLONES): Horner's rule is a chain of
// multiply-adds, which the AVX2 copy of IGA_AVX2_CLONES would run without FMA.
// The vector helpers below pass and return vector types by value; they are always inlined, so
// GCC's note that their calling convention differs between the copies concerns no call.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
/// The helpers below must be inlined into the kernels: a call would run the baseline copy.
#if defined(__GNUC__)
#define WS4_INLINE inline __attribute__((always_inline))
#else
#define WS4_INLINE inline
#endif

namespace iga::ws4::piece_kernels {

namespace {

constexpr int kMonomials = Ws4PieceTable::monomials;
constexpr int kPadded = Ws4PieceTable::padded;
constexpr int kMaxWidth = 24;  ///< widest block of the table (checked by the kernels)
/// Regions of one orbit taken together (a sixth of the regions have orbits of 3, the rest of 6):
/// 3 x 4 accumulators, within the 16 vector registers of AVX2 with the piece's 4.
constexpr int kMembers = 3;

/// Four doubles, one vector register of AVX2 (two SSE2 registers in the baseline copy): GCC's and
/// Clang's vector extension, so that the loops below are vectorised whatever the cost model says.
using V4 = double __attribute__((vector_size(4 * sizeof(double))));
constexpr int kLanes = 4;
/// Eight doubles: one AVX-512 register, two of AVX2 (the points of a run, 16 or 32 in the rules
/// of the space, in whole vectors).
using V8 = double __attribute__((vector_size(8 * sizeof(double))));

template <class V = V4>
WS4_INLINE V load(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <class V>
WS4_INLINE void store(double* p, V v) {
  std::memcpy(p, &v, sizeof v);
}
template <class T>
WS4_INLINE T splat(double a) {
  if constexpr (std::is_same_v<T, double>)
    return a;
  else
    return T{} + a;
}
/// The same, lane by lane: where T is wider than a register (the baseline copy), `T{} + a` with a
/// scalar loaded from memory went through the stack in the contraction kernels.
WS4_INLINE V4 broadcast(double a) {
  V4 v;
  for (int lane = 0; lane < kLanes; ++lane) v[lane] = a;
  return v;
}

/// p(x, y) for degree <= D, coefficients in Poly4 index order: Horner in x for each power of y,
/// then in y. T = double or V4 (four points at once, the same operations per lane).
/// Coefficient j is c[j * S] (S: the slots of a coefficient table).
template <int D, int S = 1, class T>
WS4_INLINE T horner(const double* c, T x, T y) {
  T outer = splat<T>(0.0);
  for (int b = D; b >= 0; --b) {
    T inner = splat<T>(c[Poly4::index(D - b, b) * S]);
    for (int a = D - b - 1; a >= 0; --a) inner = inner * x + c[Poly4::index(a, b) * S];
    outer = outer * y + inner;
  }
  return outer;
}

constexpr int kSlots = block_slots;
static_assert(kSlots % kLanes == 0);

/// Rows of `out` (degree D) = the derivative of the rows of `in` (degree D + 1) along the
/// physical axis whose components in each slot's coordinates are (g_xi[s], g_eta[s]): for each
/// monomial x^a y^b of degree <= D, g_xi (a + 1) in[a + 1, b] + g_eta (b + 1) in[a, b + 1].
template <int D>
WS4_INLINE void derive(const double* in, const double* g_xi, const double* g_eta, double* out) {
  // Four slots at a time: eight-wide vectors are split badly where there is no AVX-512.
  for (int s = 0; s < kSlots; s += kLanes) {
    const V4 gx = load(g_xi + s), ge = load(g_eta + s);
    for (int a = 0; a <= D; ++a)
      for (int b = 0; a + b <= D; ++b) {
        const V4 f = gx * (a + 1), h = ge * (b + 1);
        const V4 p = load(in + Poly4::index(a + 1, b) * kSlots + s);
        const V4 q = load(in + Poly4::index(a, b + 1) * kSlots + s);
        store(out + Poly4::index(a, b) * kSlots + s, f * p + h * q);
      }
  }
}

/// value, dx, dy, dxx, dxy, dyy (the first 1, 3 or 6 for Order 0, 1, 2) at one point or four.
/// c: the column of one slot in a coefficient table.
template <int Order, class T>
WS4_INLINE void point_values(const double* c, T x, T y, T* v) {
  v[0] = horner<4, kSlots>(c, x, y);
  if constexpr (Order >= 1) {
    v[1] = horner<3, kSlots>(c + dx_row * kSlots, x, y);
    v[2] = horner<3, kSlots>(c + dy_row * kSlots, x, y);
  }
  if constexpr (Order >= 2) {
    v[3] = horner<2, kSlots>(c + dxx_row * kSlots, x, y);
    v[4] = horner<2, kSlots>(c + dxy_row * kSlots, x, y);
    v[5] = horner<2, kSlots>(c + dyy_row * kSlots, x, y);
  }
}

template <int Order>
WS4_INLINE void evaluate_points(const double* c, const double* x, const double* y, int count, double* const* out) {
  constexpr int n = Order == 0 ? 1 : Order == 1 ? 3 : 6;
  int k = 0;
  for (; k + 8 <= count; k += 8) {
    V8 v[n];
    point_values<Order>(c, load<V8>(x + k), load<V8>(y + k), v);
    for (int a = 0; a < n; ++a) store(out[a] + k, v[a]);
  }
  for (; k + kLanes <= count; k += kLanes) {
    V4 v[n];
    point_values<Order>(c, load(x + k), load(y + k), v);
    for (int a = 0; a < n; ++a) store(out[a] + k, v[a]);
  }
  for (; k < count; ++k) {
    double v[n];
    point_values<Order>(c, x[k], y[k], v);
    for (int a = 0; a < n; ++a) out[a][k] = v[a];
  }
}

/// Adds w x^a y^b to sums[Poly4::index(a, b)] for all 15 monomials (T = double or V4).
template <class T>
WS4_INLINE void accumulate_moments(T x, T y, T w, T* sums) {
  const T x2 = x * x, x3 = x2 * x, x4 = x2 * x2;
  const T t1 = w * y, t2 = t1 * y, t3 = t2 * y, t4 = t3 * y;  // w y^b
  sums[Poly4::index(0, 0)] += w;
  sums[Poly4::index(1, 0)] += w * x;
  sums[Poly4::index(2, 0)] += w * x2;
  sums[Poly4::index(3, 0)] += w * x3;
  sums[Poly4::index(4, 0)] += w * x4;
  sums[Poly4::index(0, 1)] += t1;
  sums[Poly4::index(1, 1)] += t1 * x;
  sums[Poly4::index(2, 1)] += t1 * x2;
  sums[Poly4::index(3, 1)] += t1 * x3;
  sums[Poly4::index(0, 2)] += t2;
  sums[Poly4::index(1, 2)] += t2 * x;
  sums[Poly4::index(2, 2)] += t2 * x2;
  sums[Poly4::index(0, 3)] += t3;
  sums[Poly4::index(1, 3)] += t3 * x;
  sums[Poly4::index(0, 4)] += t4;
}

/// (Σ a, Σ b, Σ c, Σ d) over the lanes of each, (l0 + l1) + (l2 + l3): three additions and six
/// shuffles for four sums.
WS4_INLINE V4 sum_lanes(V4 a, V4 b, V4 c, V4 d) {
  const V4 ab = __builtin_shufflevector(a, b, 0, 4, 2, 6) + __builtin_shufflevector(a, b, 1, 5, 3, 7);
  const V4 cd = __builtin_shufflevector(c, d, 0, 4, 2, 6) + __builtin_shufflevector(c, d, 1, 5, 3, 7);
  return __builtin_shufflevector(ab, cd, 0, 1, 4, 5) + __builtin_shufflevector(ab, cd, 2, 3, 6, 7);
}

/// u_h on K regions of one orbit: each piece of the representative is loaded once and serves
/// the K regions (their functions permuted), so the table is read once per orbit, not per region;
/// 4 K independent chains of multiply-adds.
template <int K>
WS4_INLINE void member_polynomials(const Ws4PieceTable& t, const int* regions, const int* slots, const double* b,
                                   double* values, int stride) {
  const int r0 = t.representative[regions[0]];
  const int n = t.active(r0);
  const double* pieces = t.by_function.data() + static_cast<size_t>(t.piece_begin[r0]) * kPadded;
  const int* function[K];
  for (int i = 0; i < K; ++i) function[i] = t.function.data() + t.begin[regions[i]];
  V4 acc[K][4];
  for (int i = 0; i < K; ++i)
    for (int v = 0; v < 4; ++v) acc[i][v] = V4{};
  for (int j = 0; j < n; ++j) {
    const double* p = pieces + static_cast<size_t>(j) * kPadded;
    const V4 p0 = load(p), p1 = load(p + 4), p2 = load(p + 8), p3 = load(p + 12);
    for (int i = 0; i < K; ++i) {
      const V4 bi = broadcast(b[function[i][j]]);
      acc[i][0] += bi * p0;
      acc[i][1] += bi * p1;
      acc[i][2] += bi * p2;
      acc[i][3] += bi * p3;
    }
  }
  for (int i = 0; i < K; ++i) {
    double sum[kPadded];
    for (int v = 0; v < 4; ++v) store(sum + 4 * v, acc[i][v]);
    for (int m = 0; m < kMonomials; ++m) values[m * stride + slots[i]] = sum[m];
  }
}

/// The transposed member_polynomials for K regions of one orbit whose representative's block has
/// NB vectors per row: out[i][0 .. 4 NB) = Σ_m moments[i][m] row m; each row is loaded once for
/// the K regions (K NB independent chains).
template <int K, int NB>
WS4_INLINE void member_contractions(const double* block, const double* const* moments, double (*out)[kMaxWidth]) {
  V4 acc[K][NB];
  for (int i = 0; i < K; ++i)
    for (int j = 0; j < NB; ++j) acc[i][j] = V4{};
  for (int m = 0; m < kMonomials; ++m) {
    const double* row = block + m * NB * kLanes;
    for (int j = 0; j < NB; ++j) {
      const V4 r = load(row + j * kLanes);
      for (int i = 0; i < K; ++i) acc[i][j] += broadcast(moments[i][m]) * r;
    }
  }
  for (int i = 0; i < K; ++i)
    for (int j = 0; j < NB; ++j) store(out[i] + j * kLanes, acc[i][j]);
}

template <int K>
WS4_INLINE void member_transposed(const Ws4PieceTable& t, const int* regions, const int* slots, const double* moments,
                                  double* b) {
  const int r0 = t.representative[regions[0]];
  const double* block = t.by_monomial.data() + static_cast<size_t>(t.block_begin[r0]) * kMonomials;
  const double* mom[K];
  for (int i = 0; i < K; ++i) mom[i] = moments + static_cast<size_t>(slots[i]) * kPadded;
  double out[K][kMaxWidth];
  switch (t.width(r0) / kLanes) {  // the register count, known to the compiler
    case 1: member_contractions<K, 1>(block, mom, out); break;
    case 2: member_contractions<K, 2>(block, mom, out); break;
    case 3: member_contractions<K, 3>(block, mom, out); break;
    case 4: member_contractions<K, 4>(block, mom, out); break;
    case 5: member_contractions<K, 5>(block, mom, out); break;
    default: member_contractions<K, 6>(block, mom, out); break;
  }
  const int n = t.active(r0);
  for (int i = 0; i < K; ++i) {
    const int* function = t.function.data() + t.begin[regions[i]];
    for (int j = 0; j < n; ++j) b[function[j]] += out[i][j];
  }
}

}  // namespace

IGA_X86_64_V3_V4_CLONES
void orbit_polynomials(const Ws4PieceTable& table, const int* regions, const int* slots, int members, const double* b,
                       double* values, int stride) {
  for (int first = 0; first < members; first += kMembers) {
    switch (std::min(kMembers, members - first)) {
      case 3: member_polynomials<3>(table, regions + first, slots + first, b, values, stride); break;
      case 2: member_polynomials<2>(table, regions + first, slots + first, b, values, stride); break;
      default: member_polynomials<1>(table, regions + first, slots + first, b, values, stride); break;
    }
  }
}

IGA_X86_64_V3_V4_CLONES
void orbit_transposed(const Ws4PieceTable& table, const int* regions, const int* slots, int members,
                      const double* moments, double* b) {
  if (table.max_width > kMaxWidth) throw std::logic_error("orbit_transposed: more active functions than expected");
  for (int first = 0; first < members; first += kMembers) {
    switch (std::min(kMembers, members - first)) {
      case 3: member_transposed<3>(table, regions + first, slots + first, moments, b); break;
      case 2: member_transposed<2>(table, regions + first, slots + first, moments, b); break;
      default: member_transposed<1>(table, regions + first, slots + first, moments, b); break;
    }
  }
}

IGA_X86_64_V3_V4_CLONES
void derivative_polynomials(const double* g, int order, double* coefficients) {
  double* c = coefficients;
  const double *g00 = g, *g10 = g + kSlots, *g01 = g + 2 * kSlots, *g11 = g + 3 * kSlots;
  derive<3>(c + value_row * kSlots, g00, g10, c + dx_row * kSlots);
  derive<3>(c + value_row * kSlots, g01, g11, c + dy_row * kSlots);
  if (order < 2) return;
  derive<2>(c + dx_row * kSlots, g00, g10, c + dxx_row * kSlots);
  derive<2>(c + dx_row * kSlots, g01, g11, c + dxy_row * kSlots);
  derive<2>(c + dy_row * kSlots, g01, g11, c + dyy_row * kSlots);
}

IGA_X86_64_V3_V4_CLONES
void evaluate_run(const double* coefficients, int slot, int order, const double* x, const double* y, int count,
                  double* const* out) {
  const double* c = coefficients + slot;
  switch (order) {
    case 0: evaluate_points<0>(c, x, y, count, out); break;
    case 1: evaluate_points<1>(c, x, y, count, out); break;
    default: evaluate_points<2>(c, x, y, count, out); break;
  }
}

IGA_X86_64_V3_V4_CLONES
void add_moments(const double* x, const double* y, const double* w, int count, double* moments) {
  // Four points at a time, one partial sum per monomial and lane; the lanes are added four
  // monomials at a time (sum_lanes), the last of the 16 being zero.
  const int whole = count / kLanes * kLanes;
  if (whole > 0) {
    V4 sums[kPadded];
    for (V4& v : sums) v = V4{};
    for (int k = 0; k < whole; k += kLanes) accumulate_moments(load(x + k), load(y + k), load(w + k), sums);
    for (int m = 0; m < kPadded; m += kLanes)
      store(moments + m, load(moments + m) + sum_lanes(sums[m], sums[m + 1], sums[m + 2], sums[m + 3]));
  }
  for (int k = whole; k < count; ++k) accumulate_moments(x[k], y[k], w[k], moments);
}

IGA_X86_64_V3_V4_CLONES
void affine_points(const Eigen::Matrix2d& j, const Point2& p0, const double* __restrict xi,
                   const double* __restrict eta, int count, double* __restrict x) {
  // A plain loop: the compiler interleaves the two coordinates with the shuffles of each target
  // (written with vector shuffles, the baseline copy went through the stack).
  const double j00 = j(0, 0), j01 = j(0, 1), j10 = j(1, 0), j11 = j(1, 1), x0 = p0.x(), y0 = p0.y();
  for (int k = 0; k < count; ++k) {
    x[2 * k] = x0 + j00 * xi[k] + j01 * eta[k];
    x[2 * k + 1] = y0 + j10 * xi[k] + j11 * eta[k];
  }
}

IGA_X86_64_V3_V4_CLONES
void repeat_matrix(const Eigen::Matrix2d& j, int count, double* out) {
  const V4 m = {j(0, 0), j(1, 0), j(0, 1), j(1, 1)};  // column-major, as Eigen stores it
  for (int k = 0; k < count; ++k) store(out + 4 * k, m);
}

}  // namespace iga::ws4::piece_kernels
