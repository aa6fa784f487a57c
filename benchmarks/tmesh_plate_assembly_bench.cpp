// Speed of the plate matrix of a T-mesh solve: Assembler::matrix_extended of the bilaplace form (the
// double-double path the solver's residuals use) for the C1 bicubic T-mesh of the patch tests
// (unit square, two nested refinements, then uniform levels). Speed is measured here, never
// asserted in tests. Run with OMP_NUM_THREADS=1 for single-thread numbers.
//
// Run:  OMP_NUM_THREADS=1 ./build/tmesh_plate_assembly_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include "assembly/assembler.hpp"
#include "config/config_node.hpp"
#include "solver/solve_problem.hpp"
#include "spaces/space_factory.hpp"

namespace {

using namespace iga;

SpacePtr make_plate_space(int level) {
  const ConfigNode root = ConfigNode::load_string(
      "domain: {type: rectangle, min: [0, 0], max: [1, 1]}\n"
      "space: {type: tmesh, section: poly, n: 3, regularity: 1, elements: [2, 2], "
      "refine: [[0, 0, 0.5, 0.5], [0.25, 0.25, 0.5, 0.5]]}\n",
      "bench.yaml");
  return make_space(root["domain"], root["space"], level);
}

void BM_TMeshPlateMatrixExtended(benchmark::State& state) {
  // A new space per iteration: a solve assembles each space's matrix once, so per-space caches
  // of element matrices must start cold here too.
  int dofs = 0, elements = 0;
  for (auto _ : state) {
    state.PauseTiming();
    const SpacePtr space = make_plate_space(static_cast<int>(state.range(0)));
    const Assembler assembler(*space);
    const int degree = assembly_quadrature_degree(*space);
    dofs = space->dimension();
    elements = space->num_elements();
    state.ResumeTiming();
    benchmark::DoNotOptimize(assembler.matrix_extended(BilinearForm::bilaplace, degree));
  }
  state.counters["dofs"] = dofs;
  state.counters["elements"] = elements;
}

BENCHMARK(BM_TMeshPlateMatrixExtended)->Arg(5)->Arg(6)->Iterations(3)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
