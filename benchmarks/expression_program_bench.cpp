// Speed of FunctionBatch (the compiled expression programs of config/expression_vector_program)
// on the exact solutions and sources of the shipped configs: the jet {u, u_x, u_y, u_xx, u_xy, u_yy}
// used by the error norms and the source f = Δ²u or -Δu used by load vectors, for polynomial,
// transcendental and singular data. Counters: ns per point and the length of the program.
// Speed is measured here, never asserted in tests.
//
// Run:  ./build/expression_program_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <ginac/ginac.h>

#include <Eigen/Core>
#include <random>
#include <string>
#include <vector>

#include "config/expression.hpp"
#include "config/expression_printer.hpp"
#include "config/expression_vector_program.hpp"

namespace {

using namespace iga;

const char* const kCases[] = {
    "x^2*(1-x)^2*y^2*(1-y)^2",
    "sin(pi*x)*sin(pi*y)",
    "exp(x)*cos(y)",
    "(x^2 + y^2)^(1/3) * sin(2/3 * (atan2(x - y, -x - y) + 3*pi/4))",
};

std::vector<SymbolicFunction> jet(const SymbolicFunction& u) {
  const SymbolicFunction ux = u.diff_x(), uy = u.diff_y();
  return {u, ux, uy, ux.diff_x(), ux.diff_y(), uy.diff_y()};
}

/// The program length of the same functions, compiled from GiNaC directly (the expressions
/// SymbolicFunction builds: derivatives expanded when that is not longer).
GiNaC::ex tidy(const GiNaC::ex& e) {
  auto size = [](const GiNaC::ex& f) {
    size_t n = 0;
    for (auto it = f.preorder_begin(); it != f.preorder_end(); ++it) ++n;
    return n;
  };
  const GiNaC::ex expanded = e.expand();
  return size(expanded) <= size(e) ? expanded : e;
}

int program_length(const std::string& text, bool source) {
  using expression_detail::sym_x;
  using expression_detail::sym_y;
  GiNaC::symtab table;
  table["x"] = sym_x();
  table["y"] = sym_y();
  table["pi"] = GiNaC::Pi;
  GiNaC::parser reader(table, true);
  const GiNaC::ex u = reader(text);
  std::vector<GiNaC::ex> es;
  if (source) {
    auto laplace = [&](const GiNaC::ex& v) { return tidy(v.diff(sym_x(), 2) + v.diff(sym_y(), 2)); };
    es.push_back(laplace(laplace(u)));
  } else {
    const GiNaC::ex ux = tidy(u.diff(sym_x())), uy = tidy(u.diff(sym_y()));
    es = {u, ux, uy, tidy(ux.diff(sym_x())), tidy(ux.diff(sym_y())), tidy(uy.diff(sym_y()))};
  }
  const auto program = expression_detail::vector_program(es);
  return program ? program->length() : -1;
}

void run(benchmark::State& state, bool source) {
  const std::string text = kCases[state.range(0)];
  const SymbolicFunction u = SymbolicFunction::parse(text, "bench");
  const FunctionBatch batch(source ? std::vector<SymbolicFunction>{u.bilaplacian()} : jet(u));
  // The points of one element row of a fine mesh: inside the unit square, away from the corner.
  constexpr int kPoints = 5472;
  Eigen::Matrix2Xd points(2, kPoints);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(0.01, 0.99);
  for (int k = 0; k < kPoints; ++k) points.col(k) << coordinate(random), coordinate(random);
  Eigen::MatrixXd values;
  for (auto _ : state) {
    batch.evaluate(points, values);
    benchmark::DoNotOptimize(values.data());
    benchmark::ClobberMemory();
  }
  state.SetLabel(text.substr(0, 24));
  state.counters["ns_per_point"] = benchmark::Counter(kPoints * 1e-9,
                                                      benchmark::Counter::kIsIterationInvariantRate |
                                                          benchmark::Counter::kInvert);
  state.counters["instructions"] = program_length(text, source);
}

/// The cost of compiling the jet and the source once (parse, derivatives, the program).
void BM_Compile(benchmark::State& state) {
  const std::string text = kCases[state.range(0)];
  for (auto _ : state) {
    const SymbolicFunction u = SymbolicFunction::parse(text, "bench");
    const FunctionBatch jet_batch(jet(u)), source_batch({u.bilaplacian()});
    benchmark::DoNotOptimize(&jet_batch);
    benchmark::DoNotOptimize(&source_batch);
  }
  state.SetLabel(text.substr(0, 24));
}

void BM_Jet(benchmark::State& state) { run(state, false); }
void BM_Source(benchmark::State& state) { run(state, true); }

}  // namespace

BENCHMARK(BM_Jet)->DenseRange(0, 3);
BENCHMARK(BM_Source)->DenseRange(0, 3);
BENCHMARK(BM_Compile)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
