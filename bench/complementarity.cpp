// SPDX-License-Identifier: GPL-3.0-or-later
// The methods beside the paper's on the page's scenes of about 100 contacts: what a control
// change costs the library once the scene is read, method by method. Each case is timed whole,
// the way the scene pipeline runs a method: the paper's system assembled and solved (every
// method starts from it), the method, the bodies after.
//
//   paper/<scene>                       the paper's method alone
//   complementarity/<scene>             the complementarity method as the page runs it (the
//                                       automatic algorithm, started from the paper's solution)
//   complementarity_cold/<scene>        the same algorithm started from zero
//   complementarity_lemke/<scene>       Lemke's pivoting on the same problem
//   friction_complementarity/<scene>    Coulomb friction (mu = 0.5 at every contact, Newton's law)
//                                       as one complementarity problem
//   serial/<scene>                      serial collisions, each the paper's formula (to their end
//                                       or a bound of 1000 per contact, ten times the
//                                       library's default, so that the stack's 100,000
//                                       collisions measure the loop: the stack reaches it)
//   serial_friction/<scene>             serial collisions, each the exact rule with friction
//                                       (mu = 0.5, Newton's law)
//
// Scenes (bench/scenes.hpp, seed 1): stack (50 boxes, 100 contacts), cradle (101 balls),
// pyramid (100 contacts, dependent), and rough_stack, the stack sliding sideways at 1 (so that
// friction acts). Run the cases interleaved:
//   bench_complementarity --benchmark_repetitions=10 --benchmark_enable_random_interleaving=true
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "impulse/methods/complementarity.hpp"
#include "impulse/methods/friction_complementarity.hpp"
#include "impulse/methods/resolve.hpp"
#include "scenes.hpp"

namespace {

namespace mp = impulse::multipoint;
namespace me = impulse::methods;

constexpr std::size_t contacts = 100;

mp::Configuration configuration(const std::string& kind) {
  if (kind == "rough_stack") {  // sliding at 1 to the right as it lands
    return impulse::scenes::configuration(
        impulse::scenes::sliding(impulse::scenes::generate("stack", contacts, 1)));
  }
  return impulse::scenes::configuration(impulse::scenes::generate(kind, contacts, 1));
}

void paper(benchmark::State& state, const std::string& kind) {
  const mp::Configuration c = configuration(kind);
  for (auto _ : state) {
    const me::Paper p = me::paper(c, {});
    std::vector<mp::Body> after = c.after(p.solution.Fdt);
    benchmark::DoNotOptimize(after.data());
    benchmark::ClobberMemory();
  }
  state.counters["iterations"] = 0;  // (every case reports the same counters, for CSV)
  state.counters["solved"] = 1;
}

// `warm`: from the paper's solution, as the page runs it; else from zero.
void complementarity(benchmark::State& state, const std::string& kind, me::LcpAlgorithm algorithm,
                     bool warm) {
  const mp::Configuration c = configuration(kind);
  me::ComplementarityOptions options;
  options.algorithm = algorithm;
  int iterations = 0;
  bool solved = true;
  for (auto _ : state) {
    const me::Paper p = me::paper(c, {});
    const me::ComplementaritySolution s =
        warm ? me::solve_complementarity(p.system, p.solution, options)
             : me::solve_complementarity(p.system, options);
    std::vector<mp::Body> after = c.after(s.Fdt);
    benchmark::DoNotOptimize(after.data());
    benchmark::ClobberMemory();
    iterations = s.iterations;
    solved = s.status == me::LcpStatus::solved;
  }
  state.counters["iterations"] = iterations;
  state.counters["solved"] = solved ? 1 : 0;
}

void friction(benchmark::State& state, const std::string& kind) {
  const mp::Configuration c = configuration(kind);
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
  state.counters["iterations"] = pivots;  // Lemke's pivots or the changes of mode
  state.counters["solved"] = solved ? 1 : 0;
}

// `rough`: mu = 0.5 at every contact, each collision by the exact rule; else the paper's formula.
void serial(benchmark::State& state, const std::string& kind, bool rough) {
  const mp::Configuration c = configuration(kind);
  me::Options options;
  options.serial.max_collisions = 1000 * static_cast<std::int64_t>(c.contacts().size());
  if (rough) {
    options.friction.assign(c.contacts().size(), 0.5);
  }
  std::int64_t collisions = 0;
  bool finished = true;
  for (auto _ : state) {
    const me::Paper p = me::paper(c, {});
    me::Outcome o = rough ? me::serial_exact(c, p, options) : me::serial(c, p, options);
    benchmark::DoNotOptimize(o.after.data());
    benchmark::ClobberMemory();
    collisions =
        static_cast<std::int64_t>(std::get<me::SerialDiagnostics>(o.solution).order.size());
    finished = o.finished;
  }
  state.counters["iterations"] = static_cast<double>(collisions);  // the collisions
  state.counters["solved"] = finished ? 1 : 0;
}

void register_all() {
  for (const std::string kind : {"stack", "cradle", "pyramid", "rough_stack"}) {
    benchmark::RegisterBenchmark(("paper/" + kind).c_str(), paper, kind)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("complementarity/" + kind).c_str(), complementarity, kind,
                                 me::LcpAlgorithm::automatic, true)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("complementarity_cold/" + kind).c_str(), complementarity, kind,
                                 me::LcpAlgorithm::automatic, false)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("complementarity_lemke/" + kind).c_str(), complementarity, kind,
                                 me::LcpAlgorithm::lemke, true)
        ->Unit(benchmark::kMillisecond);
  }
  for (const std::string kind : {"stack", "rough_stack"}) {
    benchmark::RegisterBenchmark(("friction_complementarity/" + kind).c_str(), friction, kind)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("serial_friction/" + kind).c_str(), serial, kind, true)
        ->Unit(benchmark::kMillisecond);
  }
  for (const std::string kind : {"stack", "cradle"}) {
    benchmark::RegisterBenchmark(("serial/" + kind).c_str(), serial, kind, false)
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
    return 1;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
