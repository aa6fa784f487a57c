#include "spaces/ws4/ws4_piece_kernels.hpp"

#include <cstring>
#include <stdexcept>
#include <type_traits>

#include "spaces/ws4/poly4.hpp"

/// Three copies of each kernel: baseline, AVX2 + FMA (x86-64-v3) and AVX-512 (x86-64-v4). The
/// project's IGA_AVX2_CLONES (config/cpu_dispatch.hpp) has no FMA in its AVX2 copy, and Horner's
/// rule is a chain of multiply-adds. Clang builds (fuzz, sanitizers) need no speed: one copy.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define WS4_KERNEL_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define WS4_KERNEL_CLONES
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

/// out[0 .. 4 NB) = Σ_m moments[m] row m of a 15 x (4 NB) block (NB vectors of accumulators).
/// Two partial sums (even and odd m) halve the chains of dependent multiply-adds.
template <int NB>
WS4_INLINE void block_times_moments(const double* block, const double* moments, double* out) {
  V4 even[NB] = {}, odd[NB] = {};
  int m = 0;
  for (; m + 1 < kMonomials; m += 2) {
    const double me = moments[m], mo = moments[m + 1];
    const double* row = block + m * NB * kLanes;
    for (int j = 0; j < NB; ++j) {
      even[j] += me * load(row + j * kLanes);
      odd[j] += mo * load(row + (NB + j) * kLanes);
    }
  }
  const double* row = block + m * NB * kLanes;  // the last (15th) row
  for (int j = 0; j < NB; ++j) store(out + j * kLanes, (even[j] + moments[m] * load(row + j * kLanes)) + odd[j]);
}

}  // namespace

WS4_KERNEL_CLONES
void region_polynomials(const Ws4PieceTable& table, const int* regions, int slots, const double* b,
                        double* coefficients) {
  if (slots > kSlots) throw std::logic_error("region_polynomials: more slots than a coefficient table holds");
  constexpr int nv = kPadded / kLanes;
  const int* function = table.function.data();
  const double* pieces = table.by_function.data();
  for (int s = 0; s < slots; ++s) {
    const int r = regions[s];
    // Two partial sums (even and odd functions): two independent chains of multiply-adds.
    V4 even[nv] = {}, odd[nv] = {};
    int k = table.begin[r];
    const int end = table.begin[r + 1];
    const double* first_piece = pieces + static_cast<size_t>(table.piece_begin[r] - k) * kPadded;
    for (; k + 1 < end; k += 2) {
      const double be = b[function[k]], bo = b[function[k + 1]];
      const double* pe = first_piece + static_cast<size_t>(k) * kPadded;
      for (int v = 0; v < nv; ++v) {
        even[v] += be * load(pe + v * kLanes);
        odd[v] += bo * load(pe + kPadded + v * kLanes);
      }
    }
    if (k < end) {
      const double be = b[function[k]];
      const double* pe = first_piece + static_cast<size_t>(k) * kPadded;
      for (int v = 0; v < nv; ++v) even[v] += be * load(pe + v * kLanes);
    }
    double sum[kPadded];
    for (int v = 0; v < nv; ++v) store(sum + v * kLanes, even[v] + odd[v]);
    for (int m = 0; m < kMonomials; ++m) coefficients[m * kSlots + s] = sum[m];
  }
}

WS4_KERNEL_CLONES
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

WS4_KERNEL_CLONES
void evaluate_run(const double* coefficients, int slot, int order, const double* x, const double* y, int count,
                  double* const* out) {
  const double* c = coefficients + slot;
  switch (order) {
    case 0: evaluate_points<0>(c, x, y, count, out); break;
    case 1: evaluate_points<1>(c, x, y, count, out); break;
    default: evaluate_points<2>(c, x, y, count, out); break;
  }
}

WS4_KERNEL_CLONES
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

WS4_KERNEL_CLONES
void transposed_pieces(const Ws4PieceTable& table, const int* regions, int slots, const double* moments, double* b) {
  constexpr int kMaxWidth = 8 * kLanes;
  if (table.max_width > kMaxWidth) throw std::logic_error("transposed_pieces: more active functions than expected");
  const int* function = table.function.data();
  double out[kMaxWidth];
  for (int s = 0; s < slots; ++s) {
    const int r = regions[s];
    const double* block = table.by_monomial.data() + static_cast<size_t>(table.block_begin[r]) * kMonomials;
    const double* mom = moments + static_cast<size_t>(s) * kPadded;
    switch (table.width(r) / kLanes) {  // the register count, known to the compiler
      case 1: block_times_moments<1>(block, mom, out); break;
      case 2: block_times_moments<2>(block, mom, out); break;
      case 3: block_times_moments<3>(block, mom, out); break;
      case 4: block_times_moments<4>(block, mom, out); break;
      case 5: block_times_moments<5>(block, mom, out); break;
      case 6: block_times_moments<6>(block, mom, out); break;
      case 7: block_times_moments<7>(block, mom, out); break;
      default: block_times_moments<8>(block, mom, out); break;
    }
    const int first = table.begin[r], n = table.active(r);
    for (int j = 0; j < n; ++j) b[function[first + j]] += out[j];
  }
}

WS4_KERNEL_CLONES
void affine_points(const Eigen::Matrix2d& j, const Point2& p0, const double* xi, const double* eta, int count,
                   double* x) {
  const double j00 = j(0, 0), j01 = j(0, 1), j10 = j(1, 0), j11 = j(1, 1), x0 = p0.x(), y0 = p0.y();
  int k = 0;
  for (; k + kLanes <= count; k += kLanes) {
    const V4 a = load(xi + k), b = load(eta + k);
    const V4 u = x0 + j00 * a + j01 * b, v = y0 + j10 * a + j11 * b;
    store(x + 2 * k, __builtin_shufflevector(u, v, 0, 4, 1, 5));
    store(x + 2 * k + kLanes, __builtin_shufflevector(u, v, 2, 6, 3, 7));
  }
  for (; k < count; ++k) {
    x[2 * k] = x0 + j00 * xi[k] + j01 * eta[k];
    x[2 * k + 1] = y0 + j10 * xi[k] + j11 * eta[k];
  }
}

WS4_KERNEL_CLONES
void repeat_matrix(const Eigen::Matrix2d& j, int count, double* out) {
  const V4 m = {j(0, 0), j(1, 0), j(0, 1), j(1, 1)};  // column-major, as Eigen stores it
  for (int k = 0; k < count; ++k) store(out + 4 * k, m);
}

}  // namespace iga::ws4::piece_kernels
