// Speed of building the 4-split G1 space (nested levels: gluing inherited, geometry subdivided,
// local basis rebuilt, det J certified) next to the g1 space on the same domain and level
// (5p_pentagon, valence 5 at the centre). Arguments: refinement level, degree k.
//
//   BM_G14BuildSpace:  G14Space from the coarse mesh (all levels up to `level`)
//   BM_G1BuildSpace:   G1Space on the mesh refined `level` times (for comparison)
//
// Speed is measured here, never asserted in tests.
// Run:  ./build/g1_4split_construction_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include "spaces/g1/g1_space.hpp"
#include "spaces/g1/multipatch_domains.hpp"
#include "spaces/g1_4split/g1_4split_space.hpp"

namespace {

using namespace iga;

void BM_G14BuildSpace(benchmark::State& state) {
  const PatchMesh mesh = multipatch_domain("5p_pentagon");
  G14Options o;
  o.level = static_cast<int>(state.range(0));
  o.degree = static_cast<int>(state.range(1));
  int dofs = 0;
  for (auto _ : state) dofs = G14Space(mesh, o).dimension();
  state.counters["dofs"] = dofs;
}
BENCHMARK(BM_G14BuildSpace)->Args({2, 5})->Args({3, 5})->Args({4, 5})->Unit(benchmark::kMillisecond);

void BM_G1BuildSpace(benchmark::State& state) {
  PatchMesh mesh = multipatch_domain("5p_pentagon");
  for (int l = 0; l < state.range(0); ++l) mesh = mesh.refined();
  const auto shared = std::make_shared<const PatchMesh>(std::move(mesh));
  int dofs = 0;
  for (auto _ : state) dofs = G1Space(shared, static_cast<int>(state.range(1))).dimension();
  state.counters["dofs"] = dofs;
}
BENCHMARK(BM_G1BuildSpace)->Args({2, 5})->Args({3, 5})->Args({4, 5})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
