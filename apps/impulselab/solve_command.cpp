// SPDX-License-Identifier: GPL-3.0-or-later
#include "solve_command.hpp"

#include <memory>
#include <string>
#include <vector>

#include "app.hpp"
#include "impulse/scene/json.hpp"
#include "impulse/scene/report.hpp"
#include "output.hpp"
#include "scene_input.hpp"

namespace impulselab {

namespace {

struct SolveOptions {
  std::string scene;
  std::string format = "text";
  std::string output;
  std::string method;    // overrides the scene's solver.method when given
  bool compare = false;  // --compare given: every method, or every restitution law, side by side
  std::string compare_what;  // "" or "methods": the methods; "restitution": the three laws
};

// The library resolves the scene and says what to warn about (impulse::scene::run, as for the
// page that runs the library in a browser); this writes it out.
void solve(const SolveOptions& options) {
  namespace sc = impulse::scene;
  const sc::World world = read_world(options.scene);
  const std::string source = scene_name(options.scene);
  sc::Request request;
  request.method = impulse::value_named<impulse::methods::Method>(options.method);
  if (options.compare) {
    request.compare = options.compare_what == "restitution" ? sc::Request::Compare::laws
                                                            : sc::Request::Compare::methods;
  }
  const sc::Run run = sc::run(world, source, request);
  const std::string report = options.format == "json"
                                 ? sc::report_json(run, source)
                                 : sc::text(run, source, colour_wanted(options.output));
  if (!report.empty()) {
    write_output(options.output, [&](std::FILE* out) { std::fputs(report.c_str(), out); });
  }
  print_warnings(run.warnings);
  if (!run.unfinished.empty()) {
    throw WorkFailed(run.unfinished);  // exit 1: serial collisions at their bound, and so on
  }
}

// The scene format's names of the methods, from the library's table.
std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (const auto& entry : impulse::EnumNames<impulse::methods::Method>::table) {
    names.emplace_back(entry.name);
  }
  return names;
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
          ->check(CLI::IsMember(method_names()));
  CLI::Option* compare =
      verb->add_option("--compare,-c", options->compare_what,
                       "solve the scene by all three methods and show the answers side by side "
                       "(with --format json: one result per method); --compare restitution: "
                       "the three restitution laws (newton, poisson, energetic) side by side, "
                       "each by the scene's method")
          ->expected(0, 1)
          ->excludes(method);
  verb->callback([options, compare]() {
    options->compare = compare->count() > 0;
    if (options->compare && !options->compare_what.empty() && options->compare_what != "methods" &&
        options->compare_what != "restitution") {
      throw CLI::ValidationError(
          "--compare", "expected methods or restitution, got \"" + options->compare_what + "\"");
    }
    solve(*options);
  });
}

}  // namespace impulselab
