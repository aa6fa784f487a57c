#include "spaces/ws4/ws4_edge_traces.hpp"

#include <stdexcept>
#include <string>

namespace iga::ws4 {

namespace {

struct TraceMap {
  int m, j;
  double s;
  std::vector<long double> coefficients;
};

constexpr long double q(long double numerator, long double denominator = 1) { return numerator / denominator; }

/// Notes App. B (exact rationals).
const std::vector<TraceMap>& maps() {
  static const std::vector<TraceMap> table = {
      {0, 1, 0.5, {q(-8, 3), q(-5, 6), q(-1, 9), q(-1, 144), q(8, 3), q(-5, 6), q(1, 9), q(-1, 144)}},
      {0, 2, 0.25, {q(-8), q(-5), q(-11, 24), q(-1, 96), q(8), q(-3), q(11, 24), q(-1, 32)}},
      {0, 2, 0.75, {q(8), q(3), q(11, 24), q(1, 32), q(-8), q(5), q(-11, 24), q(1, 96)}},
      {0, 3, 0.25, {q(-64), q(-40), q(-35, 3), q(-13, 12), q(64), q(-24), q(11, 3), q(-1, 4)}},
      {0, 3, 0.5, {q(128), q(64), q(34, 3), q(5, 6), q(-128), q(64), q(-34, 3), q(5, 6)}},
      {0, 3, 0.75, {q(-64), q(-24), q(-11, 3), q(-1, 4), q(64), q(-40), q(35, 3), q(-13, 12)}},
      {1, 1, 0.25, {q(-5, 2), q(-1, 8), q(1, 96), q(-1, 2), q(1, 8), q(-1, 96), q(3)}},
      {1, 1, 0.75, {q(1, 2), q(1, 8), q(1, 96), q(5, 2), q(-1, 8), q(-1, 96), q(-3)}},
      {1, 2, 0.25, {q(-20), q(-9), q(-11, 12), q(-4), q(1), q(-1, 12), q(24)}},
      {1, 2, 0.5, {q(24), q(6), q(1, 2), q(24), q(-6), q(1, 2), q(-48)}},
      {1, 2, 0.75, {q(-4), q(-1), q(-1, 12), q(-20), q(9), q(-11, 12), q(24)}},
      {2, 1, 0.25, {q(-8), q(-1), q(0), q(0), q(8), q(0)}},
      {2, 1, 0.5, {q(4), q(1, 2), q(-4), q(1, 2), q(-8), q(8)}},
      {2, 1, 0.75, {q(0), q(0), q(8), q(-1), q(0), q(-8)}},
  };
  return table;
}

}  // namespace

const EdgeTraceData& edge_trace_data(int m) {
  static const EdgeTraceData data[3] = {{4, {}}, {3, {0.5}}, {2, {0.25, 0.75}}};
  if (m < 0 || m > 2) throw std::logic_error("edge_trace_data: m = " + std::to_string(m));
  return data[m];
}

const std::vector<long double>& edge_trace_map(int m, int j, double s) {
  for (const TraceMap& t : maps())
    if (t.m == m && t.j == j && t.s == s) return t.coefficients;
  throw std::logic_error("edge_trace_map: no map for m = " + std::to_string(m) + ", j = " + std::to_string(j) +
                         ", s = " + std::to_string(s));
}

}  // namespace iga::ws4
