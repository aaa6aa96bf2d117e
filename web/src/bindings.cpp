// SPDX-License-Identifier: GPL-3.0-or-later
// The one door from the interactive page into the library (embind): a scene's text in, the
// library's own answer out. It calls exactly what `impulselab solve --format json` calls
// (scene::solve_to_json: the scene reader, scene::run, the JSON report), so that the page's
// numbers are the command line's numbers. Everything else the page shows that is not in that
// report (each body's motion before the collision, its kinetic energy before and after) comes
// from the same solved result, never from JavaScript.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "impulse/core/error.hpp"
#include "impulse/scene/json.hpp"
#include "impulse/scene/run.hpp"
#include "impulse/scene/scene.hpp"

namespace {

using emscripten::val;
namespace scene = impulse::scene;

// How the library's messages name the scene; the page shows them without it, as the place in
// the scene is what the reader needs (the command line puts the file name there).
constexpr std::string_view source = "scene";

// The message without the scene's name in front ("scene: " or, for a row of a sweep, "scene "
// before "at elasticity E: ").
std::string without_source(std::string_view message) {
  const std::string prefix = std::string(source) + ": ";
  if (message.substr(0, prefix.size()) == prefix) {
    message.remove_prefix(prefix.size());
  } else if (message.substr(0, source.size() + 1) == std::string(source) + " ") {
    message.remove_prefix(source.size() + 1);
  }
  return std::string(message);
}

nlohmann::ordered_json vector_json(const Eigen::Vector2d& v) {
  return {v.x(), v.y()};
}

nlohmann::ordered_json motion_json(const scene::Motion& m) {
  return {{"velocity", vector_json(m.velocity)},
          {"momentum", vector_json(m.momentum)},
          {"angular_velocity", m.angular_velocity},
          {"angular_momentum", m.angular_momentum}};
}

// What the page draws besides the command line's report, from the same result: every body's
// kind, its motion before and after (vectors always [x, y], also in 1D) and its kinetic energy.
nlohmann::ordered_json details_json(const scene::Result& result) {
  nlohmann::ordered_json bodies = nlohmann::ordered_json::array();
  for (const scene::BodyReport& body : result.bodies) {
    bodies.push_back({{"name", body.name},
                      {"kind", std::string(impulse::name_of(body.kind))},
                      {"before", motion_json(body.before)},
                      {"after", motion_json(body.after)},
                      {"energy_before", body.energy_before},
                      {"energy_after", body.energy_after}});
  }
  return {{"dimension", result.dimension}, {"bodies", bodies}};
}

// A text of the library's (UTF-8) as a JavaScript string, decoded by the engine's TextDecoder
// from the module's memory at once: embind's own conversion of a std::string first looks at it a
// byte at a time, which for the report of a 100-contact scene (about 190 KB) was a sixth of the
// time of the page's solve.
val js_text(const std::string& s) {
  static const val decoder = val::global("TextDecoder").new_();
  return decoder.call<val>("decode",
                           val(emscripten::typed_memory_view(
                               s.size(), reinterpret_cast<const std::uint8_t*>(s.data()))));
}

val strings(const std::vector<std::string>& lines) {
  val array = val::array();
  for (const std::string& line : lines) {
    array.call<void>("push", line);
  }
  return array;
}

// The page's answer for a scene: {result, details, warnings, error}, `result` the text that
// `impulselab solve --format json` prints, or "" when the command line would print nothing;
// `error` the command line's message without "impulselab: error: <file>: ", or "". @p work
// gives the command line's run and report, or nothing while serial collisions are still running
// (then {pending: true, collisions, bound}).
template <typename Work>
val answer(Work&& work) {
  val out = val::object();
  std::string result_text;
  std::string details_text;
  std::vector<std::string> warnings;
  std::string error;
  try {
    const std::optional<scene::JsonRun> solved = work();
    if (!solved) {
      return val::null();
    }
    if (!solved->run.unfinished.empty()) {
      throw impulse::InvalidInput(solved->run.unfinished);  // the command line's exit 1
    }
    for (const std::string& line : solved->run.warnings) {
      warnings.push_back(without_source(line));
    }
    result_text = solved->report;
    details_text = details_json(solved->run.results.front()).dump();
  } catch (const impulse::InvalidInput& e) {
    error = without_source(e.what());
  } catch (const std::exception& e) {
    error = std::string("internal error (please report it): ") + e.what();
  }
  out.set("pending", false);
  out.set("result", js_text(result_text));
  out.set("details", js_text(details_text));
  out.set("warnings", strings(warnings));
  out.set("error", error);
  return out;
}

// Solves the scene whose text is @p text (a string or, for bytes that are not UTF-8, a
// Uint8Array) the way `impulselab solve --format json` does (scene::solve_to_json: the world
// read and checked, resolved once, the library's own report, refusals and warnings): answer().
val solve_scene(const std::string& text) {
  return answer([&] { return std::optional<scene::JsonRun>(scene::solve_to_json(text, source)); });
}

// The scene being solved in slices (one at a time: a new one replaces it).
std::optional<scene::RunInSlices> in_progress;

// Advances the scene in progress by at most @p collisions serial collisions: its answer when
// they have ended (or it was refused), else {pending: true, collisions, bound}.
val solve_advance(double collisions) {
  if (!in_progress) {
    val out = val::object();
    out.set("pending", false);
    out.set("error", std::string("internal error (please report it): no scene is being solved"));
    return out;
  }
  val out = answer([&]() -> std::optional<scene::JsonRun> {
    if (!in_progress->advance(static_cast<std::int64_t>(collisions))) {
      return std::nullopt;
    }
    scene::Run run = in_progress->finish();
    std::string report = scene::report_json(run, source);
    return scene::JsonRun{std::move(run), std::move(report)};
  });
  if (out.isNull()) {
    out = val::object();
    out.set("pending", true);
    out.set("collisions", static_cast<double>(in_progress->collisions()));
    out.set("bound", static_cast<double>(in_progress->bound()));
    return out;
  }
  in_progress.reset();
  return out;
}

// solveScene in slices, for a page that must draw every frame: the scene read and checked, and
// at most @p collisions of its serial collisions run (any other method runs whole); then
// solveAdvance until the answer is not pending. Ended, the answer is exactly solveScene's.
val solve_begin(const std::string& text, double collisions) {
  in_progress.reset();
  bool started = false;
  val refused = answer([&]() -> std::optional<scene::JsonRun> {
    in_progress.emplace(scene::parse_world(text, source), source);
    started = true;
    return std::nullopt;
  });
  return started ? solve_advance(collisions) : refused;
}

// `impulselab solve --compare --format json` (@p what "methods", or "") or `--compare
// restitution` ("restitution"): {result, warnings, unfinished, error}, `result` the text it
// prints, `unfinished` why a method did not finish (the command line's exit 1), `error` its
// refusal.
val compare_scene(const std::string& text, const std::string& what) {
  val out = val::object();
  std::string error;
  std::string result_text;
  scene::Run run;
  try {
    const scene::Request request{.compare = what == "restitution"
                                                ? scene::Request::Compare::laws
                                                : scene::Request::Compare::methods};
    run = scene::run(scene::parse_world(text, source), source, request);
    result_text = scene::report_json(run, source);
  } catch (const impulse::InvalidInput& e) {
    error = without_source(e.what());
  } catch (const std::exception& e) {
    error = std::string("internal error (please report it): ") + e.what();
  }
  std::vector<std::string> warnings;
  for (const std::string& line : run.warnings) {
    warnings.push_back(without_source(line));
  }
  out.set("result", js_text(result_text));
  out.set("warnings", strings(warnings));
  out.set("unfinished", without_source(run.unfinished));
  out.set("error", error);
  return out;
}

// `impulselab sweep` at the elasticities @p elasticities (the page lays out FROM:TO:STEP as the
// command line does; an array of numbers): {rows, error}, `rows` a JSON array with one row per
// elasticity, the CSV's columns [elasticity, energy_after, energy_change, impulse_0..,
// approach_after_0..]; `error` why the scene or an elasticity was refused (every body collides at
// the swept elasticity). Each row is scene::run at its elasticity, as the command line's sweep.
val sweep_scene(const std::string& text, const val& elasticities) {
  val out = val::object();
  std::string error;
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  try {
    const scene::World world = scene::parse_world(text, source);
    for (const double e : emscripten::vecFromJSArray<double>(elasticities)) {
      const scene::Run run = scene::run(world, source, {.elasticity = e});
      if (!run.unfinished.empty()) {
        throw impulse::InvalidInput(run.unfinished);
      }
      const scene::Result& r = run.results.front();
      nlohmann::ordered_json row = {e, r.energy_after, r.energy_change};
      for (const scene::ImpulseReport& impulse : r.impulses) {
        row.push_back(impulse.magnitude);
      }
      for (const scene::ContactReport& contact : r.contacts) {
        row.push_back(contact.approach_after);
      }
      rows.push_back(std::move(row));
    }
  } catch (const impulse::InvalidInput& e) {
    error = without_source(e.what());
    rows = nlohmann::ordered_json::array();
  } catch (const std::exception& e) {
    error = std::string("internal error (please report it): ") + e.what();
    rows = nlohmann::ordered_json::array();
  }
  out.set("rows", js_text(rows.dump()));
  out.set("error", error);
  return out;
}

// Serial collisions one at a time: the scene resolved by serial collisions stopped after @p k
// collisions (its `solver.max_collisions` set to @p k; 0, the format's default bound, is the
// whole run). {step, error}: `step` a JSON
// object: the contact of collision k, the impulses summed so far at every contact, each body's
// velocity ([x, y]) and spin after it, the kinetic energy after it, and whether the collisions
// had ended by then (`finished`: fewer than k were needed).
val serial_step(const std::string& text, int k) {
  val out = val::object();
  std::string error;
  nlohmann::ordered_json step;
  try {
    scene::Scene cut = scene::parse_scene(text, source);
    cut.method = impulse::methods::Method::serial;
    cut.serial.max_collisions = k;
    const scene::Result r = scene::resolve(scene::World(std::move(cut)));
    const auto* diagnostics = std::get_if<impulse::methods::SerialDiagnostics>(&r.outcome.solution);
    nlohmann::ordered_json velocities = nlohmann::ordered_json::array();
    nlohmann::ordered_json spins = nlohmann::ordered_json::array();
    for (const scene::BodyReport& body : r.bodies) {
      velocities.push_back(vector_json(body.after.velocity));
      spins.push_back(body.after.angular_velocity);
    }
    const bool any = diagnostics != nullptr && !diagnostics->order.empty();
    step = {{"contact", any ? diagnostics->order.back() : -1},
            {"collisions", any ? diagnostics->order.size() : 0},
            {"Fdt", std::vector<double>(r.outcome.Fdt.begin(), r.outcome.Fdt.end())},
            {"velocity", velocities},
            {"angular_velocity", spins},
            {"energy_after", r.energy_after},
            {"finished", r.outcome.finished}};
  } catch (const impulse::InvalidInput& e) {
    error = without_source(e.what());
  } catch (const std::exception& e) {
    error = std::string("internal error (please report it): ") + e.what();
  }
  out.set("step", error.empty() ? step.dump() : std::string());
  out.set("error", error);
  return out;
}

}  // namespace

EMSCRIPTEN_BINDINGS(impulselab) {
  emscripten::function("solveScene", &solve_scene);
  emscripten::function("solveBegin", &solve_begin);
  emscripten::function("solveAdvance", &solve_advance);
  emscripten::function("compareScene", &compare_scene);
  emscripten::function("sweepScene", &sweep_scene);
  emscripten::function("serialStep", &serial_step);
}
