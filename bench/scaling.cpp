// SPDX-License-Identifier: GPL-3.0-or-later
// Many-body scenes that scale.
//
// `solve_<kind>/N` times what a caller does with a scene of N contacts: multipoint::assemble
// (validation, every body's block, the ⊕) and impulse::solve, with the library's automatic
// choices (dense storage and method up to sparse_threshold contacts, sparse above).
// `assemble_<kind>/N` times the assembly alone, `solve_<kind>_dense/N` forces the dense method
// for comparison, `solve_<kind>_sparse/N` the sparse one. Scenes are generated once per size,
// outside the timed loop. Counters report the sparse method's iterations, the rank deficit, the
// relative residual |A Fdt - B| / |B|, the componentwise backward error
// |A Fdt - B| / (| |A| |Fdt| | + |B|) and eps | |A| |Fdt| | / |B|, the relative residual that the
// rounding of A Fdt alone leaves.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "impulse/core/solve.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "scenes.hpp"

namespace {

namespace mp = impulse::multipoint;
using impulse::scenes::Scene;

void solve_scene(benchmark::State& state, const char* kind, impulse::SolveMethod method) {
  const Scene scene = impulse::scenes::generate(kind, static_cast<std::size_t>(state.range(0)), 1);
  const std::vector<impulse::Elasticity> elasticities(scene.bodies.size(), scene.elasticity);
  impulse::SolverOptions options;
  options.method = method;
  impulse::Solution last;
  for (auto _ : state) {
    const impulse::ContactSystem system = mp::assemble(scene.bodies, elasticities, scene.contacts);
    impulse::Solution solution = impulse::solve(system, options);
    benchmark::DoNotOptimize(solution.Fdt.data());
    benchmark::ClobberMemory();
    last = std::move(solution);
  }
  state.counters["contacts"] = static_cast<double>(scene.contacts.size());
  state.counters["iterations"] = last.iterations;
  state.counters["sparse"] = last.method == impulse::SolveMethod::sparse ? 1 : 0;
  // |A| |Fdt|: the size of the terms that each row of A Fdt sums, the rounding level of the
  // residual. The componentwise backward error is the residual against it.
  Eigen::VectorXd terms(last.Fdt.size());
  if (last.method == impulse::SolveMethod::sparse) {
    terms.noalias() = Eigen::SparseMatrix<double>(last.sparse_A.cwiseAbs()) * last.Fdt.cwiseAbs();
  } else {
    terms.noalias() = last.A.cwiseAbs() * last.Fdt.cwiseAbs();
  }
  state.counters["rel_residual"] = last.residual / last.B.norm();
  state.counters["backward_error"] = last.residual / (terms.norm() + last.B.norm());
  state.counters["eps_terms_over_B"] =
      std::numeric_limits<double>::epsilon() * terms.norm() / last.B.norm();
  state.counters["rank_deficit"] = static_cast<double>(last.Fdt.size() - last.rank);
}

void assemble_scene(benchmark::State& state, const char* kind) {
  const Scene scene = impulse::scenes::generate(kind, static_cast<std::size_t>(state.range(0)), 1);
  const std::vector<impulse::Elasticity> elasticities(scene.bodies.size(), scene.elasticity);
  for (auto _ : state) {
    impulse::ContactSystem system = mp::assemble(scene.bodies, elasticities, scene.contacts);
    benchmark::DoNotOptimize(system);
    benchmark::ClobberMemory();
  }
}

void sizes(benchmark::internal::Benchmark* b) {
  for (const std::int64_t n : {10, 100, 1'000, 10'000, 100'000}) {
    b->Arg(n);
  }
  b->Unit(benchmark::kMillisecond);
}

void dense_sizes(benchmark::internal::Benchmark* b) {
  for (const std::int64_t n : {10, 100, 256, 1'000}) {
    b->Arg(n);
  }
  b->Unit(benchmark::kMillisecond);
}

}  // namespace

BENCHMARK_CAPTURE(solve_scene, stack, "stack", impulse::SolveMethod::automatic)
    ->Name("solve_stack")
    ->Apply(sizes);
BENCHMARK_CAPTURE(solve_scene, pyramid, "pyramid", impulse::SolveMethod::automatic)
    ->Name("solve_pyramid")
    ->Apply(sizes);
BENCHMARK_CAPTURE(solve_scene, cradle, "cradle", impulse::SolveMethod::automatic)
    ->Name("solve_cradle")
    ->Apply(sizes);
BENCHMARK_CAPTURE(assemble_scene, stack, "stack")->Name("assemble_stack")->Apply(sizes);
BENCHMARK_CAPTURE(assemble_scene, pyramid, "pyramid")->Name("assemble_pyramid")->Apply(sizes);
BENCHMARK_CAPTURE(assemble_scene, cradle, "cradle")->Name("assemble_cradle")->Apply(sizes);
BENCHMARK_CAPTURE(solve_scene, stack_dense, "stack", impulse::SolveMethod::dense)
    ->Name("solve_stack_dense")
    ->Apply(dense_sizes);
BENCHMARK_CAPTURE(solve_scene, pyramid_dense, "pyramid", impulse::SolveMethod::dense)
    ->Name("solve_pyramid_dense")
    ->Apply(dense_sizes);
BENCHMARK_CAPTURE(solve_scene, cradle_dense, "cradle", impulse::SolveMethod::dense)
    ->Name("solve_cradle_dense")
    ->Apply(dense_sizes);
BENCHMARK_CAPTURE(solve_scene, stack_sparse, "stack", impulse::SolveMethod::sparse)
    ->Name("solve_stack_sparse")
    ->Apply(dense_sizes);
BENCHMARK_CAPTURE(solve_scene, pyramid_sparse, "pyramid", impulse::SolveMethod::sparse)
    ->Name("solve_pyramid_sparse")
    ->Apply(dense_sizes);
BENCHMARK_CAPTURE(solve_scene, cradle_sparse, "cradle", impulse::SolveMethod::sparse)
    ->Name("solve_cradle_sparse")
    ->Apply(dense_sizes);

BENCHMARK_MAIN();
