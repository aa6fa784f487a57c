#include "spaces/g1_4split/gluing.hpp"

#include <cmath>
#include <stdexcept>

namespace iga {

Blending blending_from_name(const std::string& name) {
  if (name == "q0") return Blending::q0;
  if (name == "q1") return Blending::q1;
  if (name == "c1") return Blending::c1;
  if (name == "linear") return Blending::linear;
  if (name == "lines") return Blending::lines;
  throw std::invalid_argument("unknown blending '" + name + "' (q0, q1, c1, linear, lines)");
}

std::string blending_name(Blending b) {
  switch (b) {
    case Blending::q0: return "q0";
    case Blending::q1: return "q1";
    case Blending::c1: return "c1";
    case Blending::linear: return "linear";
    case Blending::lines: return "lines";
  }
  return "?";
}

double SplitGluing::eval(double t, int order, int half) const {
  if (half < 0) half = t < 0.5 ? 0 : 1;
  const auto& c = piece[half];
  double sum = 0.0;
  for (int j = order; j < 4; ++j) {
    double f = 1.0;
    for (int i = 0; i < order; ++i) f *= (j - i);
    sum += c[j] * f * std::pow(t, j - order);
  }
  return sum;
}

namespace {

/// Powers of t of p(1 - t) for p = c (degree <= 3): binomial expansion (exact for dyadic data).
std::array<double, 4> flip(const std::array<double, 4>& c) {
  static const int binom[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
  std::array<double, 4> out{};
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i <= j; ++i) out[i] += c[j] * binom[j][i] * ((i % 2) ? -1.0 : 1.0);
  return out;
}

}  // namespace

SplitGluing SplitGluing::symmetric(double A0, double A1, Blending b) {
  // d0 on the two halves in powers of t.
  std::array<std::array<double, 4>, 2> d0{};
  switch (b) {
    case Blending::q0: d0 = {{{1, 0, -4, 0}, {0, 0, 0, 0}}}; break;
    case Blending::q1: d0 = {{{1, 0, -2, 0}, {2, -4, 2, 0}}}; break;
    case Blending::c1: d0 = {{{1, 0, -12, 16}, {0, 0, 0, 0}}}; break;
    case Blending::linear: d0 = {{{1, -1, 0, 0}, {1, -1, 0, 0}}}; break;
    case Blending::lines:
      throw std::invalid_argument("blending 'lines' is built from the whole mesh (line_gluing), not edge by edge");
  }
  SplitGluing g;
  for (int h = 0; h < 2; ++h) {
    // d1(t) = d0(1 - t): on half h it is the flipped polynomial of half 1 - h.
    const std::array<double, 4> d1 = flip(d0[1 - h]);
    for (int j = 0; j < 4; ++j) g.piece[h][j] = A0 * d0[h][j] - A1 * d1[j];
  }
  return g;
}

SplitGluing SplitGluing::piecewise_linear(double a0, double mid, double a1) {
  SplitGluing g;
  g.piece[0] = {a0, 2 * (mid - a0), 0, 0};
  g.piece[1] = {2 * mid - a1, 2 * (a1 - mid), 0, 0};
  return g;
}

SplitGluing SplitGluing::reversed() const {
  SplitGluing g;
  for (int h = 0; h < 2; ++h) {
    const std::array<double, 4> f = flip(piece[1 - h]);
    for (int j = 0; j < 4; ++j) g.piece[h][j] = -f[j];
  }
  return g;
}

SplitGluing SplitGluing::restricted(double t0, double t1) const {
  const double mid = 0.5 * (t0 + t1);
  const int half = mid < 0.5 ? 0 : 1;
  const auto& c = piece[half];
  const double d = t1 - t0;
  // p(t0 + d s) in powers of s (Horner on polynomials).
  std::array<double, 4> out{};
  for (int j = 3; j >= 0; --j) {
    std::array<double, 4> next{};
    for (int i = 0; i < 4; ++i) {
      next[i] += out[i] * t0;
      if (i + 1 < 4) next[i + 1] += out[i] * d;
    }
    next[0] += c[j];
    out = next;
  }
  const double sign = d > 0 ? 1.0 : -1.0;
  SplitGluing g;
  for (int j = 0; j < 4; ++j) g.piece[0][j] = g.piece[1][j] = sign * out[j];
  return g;
}

double vertex_gluing_value(int faces, bool boundary) {
  const double pi = std::acos(-1.0);
  const double A = boundary ? 2 * std::cos(pi / faces) : 2 * std::cos(2 * pi / faces);
  return std::abs(A) < 1e-12 ? 0.0 : A;
}

}  // namespace iga
