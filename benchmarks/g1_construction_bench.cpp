// Speed of building the G1 multipatch space against the phases that follow it, for the clamped
// plate on 3p_square (issue 5: "at 2e5 DOFs building the space must take less time than
// assembly"). Arguments: refinement level, degree k. Level 6, k = 5 is the ~2e5-DOF case
// (198k DOFs); k = 6 at level 5 and the 4t_star triangles at level 6 check the other shapes.
//
//   BM_G1RefineMesh:  PatchMesh refined `level` times (the config path does this before the space)
//   BM_G1BuildSpace:  G1Space on the refined mesh (gluing data, local null spaces, extraction)
//   BM_G1Assemble:    Assembler (pattern) and the biharmonic matrix, quadrature degree
//                     2k + 3 as the solver uses on bilinear patches
//   BM_G1Factorize:   CHOLMOD supernodal LLT of the clamped (reduced) matrix
//
// Speed is measured here, never asserted in tests.
// Run:  ./build/g1_construction_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <Eigen/CholmodSupport>
#include <string>

#include "assembly/assembler.hpp"
#include "assembly/boundary_conditions.hpp"
#include "spaces/g1/g1_space.hpp"
#include "spaces/g1/multipatch_domains.hpp"

namespace {

using namespace iga;

std::string domain_name(int id) { return id == 0 ? "3p_square" : "4t_star"; }

std::shared_ptr<const PatchMesh> refined_mesh(const std::string& name, int level) {
  PatchMesh mesh = multipatch_domain(name);
  for (int l = 0; l < level; ++l) mesh = mesh.refined();
  return std::make_shared<const PatchMesh>(std::move(mesh));
}

int quad_degree(const Space& space) { return 2 * space.degree() + (space.affine_elements() ? 1 : 3); }

void BM_G1RefineMesh(benchmark::State& state) {
  const int level = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(refined_mesh(domain_name(static_cast<int>(state.range(2))), level));
}

void BM_G1BuildSpace(benchmark::State& state) {
  const auto mesh = refined_mesh(domain_name(static_cast<int>(state.range(2))), static_cast<int>(state.range(0)));
  const int k = static_cast<int>(state.range(1));
  int dofs = 0;
  for (auto _ : state) {
    const G1Space space(mesh, k);
    dofs = space.dimension();
    benchmark::DoNotOptimize(dofs);
  }
  state.counters["dofs"] = dofs;
  state.counters["patches"] = mesh->num_faces();
}

void BM_G1Assemble(benchmark::State& state) {
  const auto mesh = refined_mesh(domain_name(static_cast<int>(state.range(2))), static_cast<int>(state.range(0)));
  const G1Space space(mesh, static_cast<int>(state.range(1)));
  for (auto _ : state) {
    const Assembler assembler(space);  // pattern included
    benchmark::DoNotOptimize(assembler.matrix(BilinearForm::bilaplace, quad_degree(space)));
  }
  state.counters["dofs"] = space.dimension();
}

void BM_G1Factorize(benchmark::State& state) {
  const auto mesh = refined_mesh(domain_name(static_cast<int>(state.range(2))), static_cast<int>(state.range(0)));
  const G1Space space(mesh, static_cast<int>(state.range(1)));
  const int qa = quad_degree(space);
  const Assembler assembler(space);
  const SparseMatrix A = assembler.matrix(BilinearForm::bilaplace, qa);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(space.dimension());
  EssentialBoundary clamped;
  clamped.value_edges = clamped.normal_edges = space.boundary_edges("all");
  const BoundaryField zero = [](const Point2&, const Point2&) { return 0.0; };
  const Constraints c = impose_essential(space, clamped, zero, zero, qa);
  SparseMatrix A_free;
  Eigen::VectorXd b_free;
  reduce_system(A, b, c, A_free, b_free);
  for (auto _ : state) {
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt(A_free);
    benchmark::DoNotOptimize(llt.info());
  }
  state.counters["free_dofs"] = static_cast<double>(A_free.rows());
  state.counters["nnz"] = static_cast<double>(A_free.nonZeros());
}

// {level, k, domain (0 = 3p_square, 1 = 4t_star)}
void cases(benchmark::internal::Benchmark* b) {
  b->Args({5, 5, 0})->Args({6, 5, 0})->Args({5, 6, 0})->Args({6, 5, 1});
  b->Unit(benchmark::kMillisecond)->Iterations(1);
}

}  // namespace

BENCHMARK(BM_G1RefineMesh)->Apply(cases);
BENCHMARK(BM_G1BuildSpace)->Apply(cases);
BENCHMARK(BM_G1Assemble)->Apply(cases);
BENCHMARK(BM_G1Factorize)->Apply(cases);

BENCHMARK_MAIN();
