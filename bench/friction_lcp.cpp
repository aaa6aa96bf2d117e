// SPDX-License-Identifier: GPL-3.0-or-later
// Beyond the paper (issue 17): the complementarity method with Coulomb friction (the 4N problem,
// Lemke's method) against the frictionless complementarity problem (N unknowns, the same Lemke
// pivoting) on the same generated stack of boxes, each timed whole: the configuration's system
// assembled, the problem solved, the impulses applied to the bodies. Run the pairs interleaved:
//   bench_friction_lcp --benchmark_repetitions=10 --benchmark_enable_random_interleaving=true
#include <benchmark/benchmark.h>

#include <cstddef>
#include <vector>

#include "impulse/methods/complementarity.hpp"
#include "impulse/methods/friction_complementarity.hpp"
#include "impulse/multipoint/multipoint.hpp"
#include "scenes.hpp"

namespace {

namespace mp = impulse::multipoint;
namespace me = impulse::methods;

mp::Configuration stack(benchmark::State& state) {
  const impulse::scenes::Scene scene =
      impulse::scenes::stack(static_cast<std::size_t>(state.range(0)), 1);
  return impulse::scenes::configuration(scene);
}

// The frictionless problem, by Lemke's pivoting (the algorithm the friction problem uses).
void frictionless(benchmark::State& state) {
  const mp::Configuration c = stack(state);
  me::ComplementarityOptions options;
  options.algorithm = me::LcpAlgorithm::lemke;
  int pivots = 0;
  bool solved = true;
  for (auto _ : state) {
    const me::ComplementaritySolution s = me::solve_complementarity(c.assemble(), options);
    std::vector<mp::Body> after = c.after(s.Fdt);
    benchmark::DoNotOptimize(after.data());
    benchmark::ClobberMemory();
    pivots = s.iterations;
    solved = s.status == me::LcpStatus::solved;
  }
  // Every case reports the same counters: the CSV reporter stops the program when a case lacks
  // one that an earlier case put in its header (the order of
  // --benchmark_enable_random_interleaving).
  state.counters["contacts"] = static_cast<double>(c.contacts().size());
  state.counters["pivots"] = pivots;
  state.counters["solved"] = solved ? 1 : 0;
}

// The friction problem, μ = 0.5 at every contact, Newton's law.
void friction(benchmark::State& state) {
  const mp::Configuration c = stack(state);
  const std::vector<double> mu(c.contacts().size(), 0.5);
  int pivots = 0;
  bool solved = true;
  for (auto _ : state) {
    me::FrictionResolution r = me::resolve_friction_complementarity(c, mu);
    benchmark::DoNotOptimize(r.after.data());
    benchmark::ClobberMemory();
    pivots = r.solution.pivots;
    solved = r.solution.status == me::LcpStatus::solved;
  }
  state.counters["contacts"] = static_cast<double>(c.contacts().size());
  state.counters["pivots"] = pivots;
  state.counters["solved"] = solved ? 1 : 0;
}

}  // namespace

BENCHMARK(frictionless)->Name("lcp_frictionless")->Arg(2)->Arg(8)->Arg(32);
BENCHMARK(friction)->Name("lcp_friction")->Arg(2)->Arg(8)->Arg(32);

BENCHMARK_MAIN();
