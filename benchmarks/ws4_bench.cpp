// Speed of the phases of a WS4 (C3 quartic macro-element) solve on the unit square with
// N x N squares (2 N² triangles): build the space (extractions), assemble the Laplace matrix
// (closed form), assemble a load vector (Evaluator::integrate_values), compute error norms
// (Evaluator::evaluate_function) and factorize + solve K + M with CHOLMOD (SPD, same pattern as
// the Dirichlet problem). Speed is measured here, never asserted in tests.
//
// Run:  ./build/ws4_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <Eigen/CholmodSupport>
#include <cmath>
#include <numbers>

#include "assembly/assembler.hpp"
#include "assembly/error_norms.hpp"
#include "spaces/ws4/ws4_space.hpp"

namespace {

using namespace iga;

std::shared_ptr<const ws4::Ws4Space> make_space(int n) {
  return std::make_shared<const ws4::Ws4Space>(ws4::Triangulation::rectangle(n, n, Point2(0, 0), Point2(1, 1)));
}

double source(const Point2& x) {
  const double pi = std::numbers::pi;
  return 2 * pi * pi * std::sin(pi * x.x()) * std::sin(pi * x.y());
}

void BM_Ws4BuildSpace(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(make_space(n));
  state.counters["triangles"] = 2 * n * n;
}

void BM_Ws4AssembleLaplace(benchmark::State& state) {
  const auto space = make_space(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const Assembler assembler(*space);  // pattern included
    benchmark::DoNotOptimize(assembler.matrix(BilinearForm::laplace, 8));
  }
  state.counters["dofs"] = space->dimension();
}

void BM_Ws4AssembleLoad(benchmark::State& state) {
  const auto space = make_space(static_cast<int>(state.range(0)));
  const Assembler assembler(*space);
  for (auto _ : state) benchmark::DoNotOptimize(assembler.load(source, 8));
  state.counters["dofs"] = space->dimension();
}

void BM_Ws4Solve(benchmark::State& state) {
  const auto space = make_space(static_cast<int>(state.range(0)));
  const Assembler assembler(*space);
  const SparseMatrix A = assembler.matrix(BilinearForm::laplace, 8) + assembler.matrix(BilinearForm::mass, 8);
  const Eigen::VectorXd b = assembler.load(source, 8);
  for (auto _ : state) {
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt(A);
    benchmark::DoNotOptimize(llt.solve(b));
  }
  state.counters["dofs"] = space->dimension();
  state.counters["nnz"] = static_cast<double>(A.nonZeros());
}

void BM_Ws4ErrorNorms(benchmark::State& state) {
  const auto space = make_space(static_cast<int>(state.range(0)));
  const Eigen::VectorXd c = Eigen::VectorXd::Ones(space->dimension());
  ExactSolution exact;
  exact.u = [](const Point2& x) { return x.x() * x.y(); };
  exact.ux = [](const Point2& x) { return x.y(); };
  exact.uy = [](const Point2& x) { return x.x(); };
  exact.uxx = exact.uyy = [](const Point2&) { return 0.0; };
  exact.uxy = [](const Point2&) { return 1.0; };
  for (auto _ : state) benchmark::DoNotOptimize(error_norms(*space, c, exact, 2 * space->degree() + 8));
  state.counters["dofs"] = space->dimension();
}

}  // namespace

BENCHMARK(BM_Ws4BuildSpace)->Arg(64)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Ws4AssembleLaplace)->Arg(64)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Ws4AssembleLoad)->Arg(64)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Ws4Solve)->Arg(64)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Ws4ErrorNorms)->Arg(16)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
