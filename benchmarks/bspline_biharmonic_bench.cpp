// Speed of the phases of a clamped-plate solve with cubic C2 B-splines on the unit square: build
// the space, assemble the biharmonic matrix, factorize with CHOLMOD. The project's target is that
// building and assembling never cost more than the factorization.
//
// Run:  ./build/bspline_biharmonic_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <Eigen/CholmodSupport>

#include "assembly/assembler.hpp"
#include "spaces/bspline/tensor_bspline_space.hpp"

namespace {

using namespace iga;

std::shared_ptr<TensorBSplineSpace> make_space(int n) {
  static const auto square = std::make_shared<const PatchGeometry>(PatchGeometry::rectangle({0, 0}, {1, 1}));
  return std::make_shared<TensorBSplineSpace>(square, KnotVector::uniform(3, 2, n), KnotVector::uniform(3, 2, n));
}

void BM_BuildSpace(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(make_space(n));
  state.counters["dofs"] = (n + 3) * (n + 3);
}

void BM_Assemble(benchmark::State& state) {
  const auto space = make_space(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const Assembler assembler(*space);  // pattern included
    benchmark::DoNotOptimize(assembler.matrix(BilinearForm::bilaplace, 7));
  }
  state.counters["dofs"] = space->dimension();
}

void BM_Factorize(benchmark::State& state) {
  const auto space = make_space(static_cast<int>(state.range(0)));
  const Assembler assembler(*space);
  SparseMatrix A = assembler.matrix(BilinearForm::bilaplace, 7);
  // Clamp the outer two layers the cheap way (identity rows) so the matrix is SPD.
  const int n = static_cast<int>(state.range(0)) + 3;
  for (int k = 0; k < A.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(A, k); it; ++it) {
      auto boundary = [n](int i) { int x = i % n, y = i / n; return x < 2 || y < 2 || x >= n - 2 || y >= n - 2; };
      if (boundary(static_cast<int>(it.row())) || boundary(static_cast<int>(it.col())))
        it.valueRef() = it.row() == it.col() ? 1.0 : 0.0;
    }
  for (auto _ : state) {
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt(A);
    benchmark::DoNotOptimize(llt.info());
  }
  state.counters["dofs"] = space->dimension();
}

}  // namespace

BENCHMARK(BM_BuildSpace)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Assemble)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Factorize)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
