// SPDX-License-Identifier: GPL-3.0-or-later
// The one door from the interactive page into the library (embind): a scene's text in, the
// library's own answer out. It calls exactly what `impulselab solve --format json` calls
// (scene::solve_to_json: the scene reader, scene::run, the JSON report), so that the page's
// numbers are the command line's numbers. Everything else the page shows that is not in that
// report (each body's motion before the collision, its kinetic energy before and after) comes
// from the same solved result, never from JavaScript.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "impulse/core/error.hpp"
#include "impulse/scene/json.hpp"

namespace {

using emscripten::val;
namespace scene = impulse::scene;

// How the library's messages name the scene; the page shows them without it, as the place in
// the scene is what the reader needs (the command line puts the file name there).
constexpr std::string_view source = "scene";

std::string without_source(std::string_view message) {
  const std::string prefix = std::string(source) + ": ";
  if (message.substr(0, prefix.size()) == prefix) {
    message.remove_prefix(prefix.size());
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

val strings(const std::vector<std::string>& lines) {
  val array = val::array();
  for (const std::string& line : lines) {
    array.call<void>("push", line);
  }
  return array;
}

// Solves the scene whose text is @p text (a string or, for bytes that are not UTF-8, a
// Uint8Array) and returns {result, details, warnings, error}: `result` the text that
// `impulselab solve --format json` prints, or "" when the command line would print nothing;
// `error` the command line's message without "impulselab: error: <file>: ", or "".
val solve_scene(const std::string& text) {
  val out = val::object();
  std::string result_text;
  std::string details_text;
  std::vector<std::string> warnings;
  std::string error;
  try {
    // `impulselab solve --format json`'s path: the world read and checked, resolved once, and the
    // library's own report, refusals and warnings.
    const scene::JsonRun solved = scene::solve_to_json(text, source);
    if (!solved.run.unfinished.empty()) {
      throw impulse::InvalidInput(solved.run.unfinished);  // the command line's exit 1
    }
    for (const std::string& line : solved.run.warnings) {
      warnings.push_back(without_source(line));
    }
    result_text = solved.report;
    details_text = details_json(solved.run.results.front()).dump();
  } catch (const impulse::InvalidInput& e) {
    error = without_source(e.what());
  } catch (const std::exception& e) {
    error = std::string("internal error (please report it): ") + e.what();
  }
  out.set("result", result_text);
  out.set("details", details_text);
  out.set("warnings", strings(warnings));
  out.set("error", error);
  return out;
}

}  // namespace

EMSCRIPTEN_BINDINGS(impulselab) {
  emscripten::function("solveScene", &solve_scene);
}
