// SPDX-License-Identifier: GPL-3.0-or-later
#include "solve_command.hpp"

#include <memory>
#include <string>

#include "app.hpp"
#include "compare.hpp"
#include "impulse/core/error.hpp"
#include "impulse/scene/json.hpp"
#include "output.hpp"
#include "text_report.hpp"
#include "warnings.hpp"

namespace impulselab {

namespace {

struct SolveOptions {
  std::string scene;
  std::string format = "text";
  std::string output;
  std::string method;    // overrides the scene's solver.method when given
  bool compare = false;  // every method, side by side
};

void solve(const SolveOptions& options) {
  impulse::scene::Scene scene = read_scene(options.scene);
  if (const auto method = impulse::methods::method_named(options.method)) {
    scene.method = *method;
  }
  if (options.compare) {
    compare_methods(scene, scene_name(options.scene), options.format, options.output);
    return;
  }
  const impulse::scene::Result result = impulse::scene::solve(scene);
  if (result.status != impulse::SolveStatus::success) {
    // Every number of the scene is a valid double, but their products or sums are not: the
    // input is beyond what double precision can solve, so it is refused like other bad input.
    throw impulse::InvalidInput(
        scene_name(options.scene) +
        ": the numbers overflow: A·Fdt = B or the state after the collision is not finite "
        "(masses, inertias, velocities or elasticities too extreme for double precision)");
  }
  require_finished(result, scene_name(options.scene));  // serial collisions within their bound
  print_impulse_warnings(result);                       // negative impulses, approximate answers
  const std::string text = options.format == "json" ? impulse::scene::to_json(result).dump(2) + "\n"
                                                    : text_report(result, scene_name(options.scene),
                                                                  colour_wanted(options.output));
  write_output(options.output, [&](std::FILE* out) { std::fputs(text.c_str(), out); });
  print_warnings(solve_warnings(result, scene_name(options.scene)));
}

}  // namespace

void add_solve_command(CLI::App& app) {
  auto options = std::make_shared<SolveOptions>();
  CLI::App* verb = app.add_subcommand(
      "solve",
      "Solve one scene: the impulses, each body before and after, energy, momentum, each "
      "contact's approach speed, and the system A·Fdt = B with its rank and residual.");
  verb->add_option("scene", options->scene,
                   "the scene file (JSON, see the scene format); - for "
                   "standard input")
      ->required();
  verb->add_option("--format,-f", options->format, "text (for people, the default) or json")
      ->check(CLI::IsMember({"text", "json"}));
  verb->add_option("--output,-o", options->output,
                   "write here instead of standard output (atomically: all or nothing)");
  CLI::Option* method =
      verb->add_option("--method,-m", options->method,
                       "how to find the impulses, instead of the scene's solver.method: "
                       "simultaneous (the paper's linear system), complementarity (impulses "
                       "only push) or serial (one contact at a time)")
          ->check(CLI::IsMember({"simultaneous", "complementarity", "serial"}));
  verb->add_flag("--compare,-c", options->compare,
                 "solve the scene by all three methods and show the answers side by side "
                 "(with --format json: one result per method)")
      ->excludes(method);
  verb->callback([options]() { solve(*options); });
}

}  // namespace impulselab
