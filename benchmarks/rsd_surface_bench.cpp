// The icosphere geometry study of the RSD G1 surfaces (../shared/notes/rsd-g1-surfaces.md §5.6):
// icosphere level L = 0..5 with exact sphere normals and projected-chord tangents, Π0 and Π1,
// corrected (Hermite, §6.1) and uncorrected. Counters: h (longest mesh edge), radial and normal
// (degrees) errors, relative area and volume errors against 4π and 4π/3, G1 residual, max |z|.
// The time is the construction of the surface (the measures are computed once, outside the loop).
//
// Run:  ./build/rsd_surface_bench --benchmark_counters_tabular=true
// Rates between levels: log(e_L / e_{L+1}) / log(h_L / h_{L+1}) from the printed columns.
#include <benchmark/benchmark.h>

#include <cmath>

#include "geometry/builtin_surface_meshes.hpp"
#include "geometry/rsd/rsd_surface.hpp"
#include "geometry/rsd/surface_measures.hpp"

namespace {

using namespace iga;
using namespace iga::rsd;

double longest_edge(const TriangleSurfaceMesh& mesh) {
  double h = 0;
  for (const auto& t : mesh.triangles)
    for (int c = 0; c < 3; ++c) h = std::max(h, (mesh.points[t[c]] - mesh.points[t[(c + 1) % 3]]).norm());
  return h;
}

void BM_IcosphereSurface(benchmark::State& state) {
  const int level = static_cast<int>(state.range(0));
  const RsdOptions options{state.range(1) == 0 ? RsdTuple::pi0 : RsdTuple::pi1,
                           state.range(2) == 0 ? RsdMethod::hermite : RsdMethod::none};
  const TriangleSurfaceMesh mesh = icosphere(level);
  RsdSurface surface;
  for (auto _ : state) {
    surface = build_rsd_surface(mesh, options);
    benchmark::DoNotOptimize(surface.patches.data());
  }
  const SphereDeviation d = sphere_deviation(surface);
  const AreaVolume av = area_and_volume(surface);
  state.SetLabel(tuple_name(options.tuple) + " " + method_name(options.method));
  state.counters["L"] = level;
  state.counters["h"] = longest_edge(mesh);
  state.counters["radial"] = d.radial;
  state.counters["normal_deg"] = d.normal_degrees;
  state.counters["area_err"] = std::abs(av.area - 4 * M_PI) / (4 * M_PI);
  state.counters["volume_err"] = std::abs(av.volume - 4 * M_PI / 3) / (4 * M_PI / 3);
  state.counters["g1"] = surface.report.max_g1_residual;
  state.counters["max_z"] = surface.report.max_z;
}

BENCHMARK(BM_IcosphereSurface)
    ->ArgsProduct({{0, 1, 2, 3, 4, 5}, {0, 1}, {0, 1}})
    ->ArgNames({"L", "pi", "uncorrected"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
