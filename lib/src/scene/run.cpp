// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/scene/run.hpp"

#include <limits>
#include <optional>
#include <utility>

#include "impulse/core/error.hpp"
#include "impulse/core/text.hpp"
#include "impulse/methods/resolve.hpp"
#include "impulse/scene/report.hpp"

namespace impulse::scene {

namespace {

// The library's refusal of what was asked (a method or a law that cannot take the scene, an
// elasticity the exact rule cannot take), naming the scene first and what was asked last.
template <typename Work>
auto refusing(std::string_view source, std::string_view asked, const Work& work) {
  try {
    return work();
  } catch (const InvalidInput& e) {
    std::string message(source);
    message.append(": ").append(e.what()).append(asked);
    throw InvalidInput(message);
  }
}

// Every number of the scene is a valid double, but their products or sums are not: the input is
// beyond what double precision can solve, so it is refused like other bad input.
void refuse_overflow(const Result& result, std::string_view source, std::string_view where,
                     bool explained) {
  if (result.status == SolveStatus::success) {
    return;
  }
  std::string message(source);
  message.append(": the numbers overflow").append(where);
  message.append(": A·Fdt = B or the state after the collision is not finite");
  if (explained) {
    message.append(
        " (masses, inertias, velocities or elasticities too extreme for double precision)");
  }
  throw InvalidInput(message);
}

// What a run of one method tells of its result: refused when its numbers overflow, why it did not
// finish, and the warnings (a row of a sweep: the system's alone).
Run told(Result result, std::string_view source, const Request& request) {
  Run out{request, {}, {}, {}};
  out.results.push_back(std::move(result));
  const std::optional<double> e = request.elasticity;
  const std::string at = e ? " at elasticity " + format_number(*e) : "";
  const Result& r = out.results.front();
  refuse_overflow(r, source, at, !e);
  out.unfinished = unfinished_message(r, std::string(source) + at);
  if (!e && !out.unfinished.empty()) {
    return out;
  }
  if (!e) {
    out.warnings = elasticity_warnings(r, source);
    for (std::string& warning : impulse_warnings(r)) {
      out.warnings.push_back(std::move(warning));
    }
  }
  for (std::string& warning : system_warnings(r, source)) {
    out.warnings.push_back(std::move(warning));
  }
  return out;
}

// How a refusal of one method names what was asked: " (at elasticity E)" for a row of a sweep.
std::string asked(const Request& request) {
  return request.elasticity ? " (at elasticity " + format_number(*request.elasticity) + ")" : "";
}

// The warnings of results shown side by side: the elasticities' and the system's once (they and
// A·Fdt = B are the same for each), the methods left out, then each result's own with its name in
// front; and the results that did not finish.
void tell(Run& out, std::string_view source, const std::vector<std::string>& names,
          std::vector<std::string> left_out) {
  out.warnings = elasticity_warnings(out.results.front(), source);
  for (const Result& r : out.results) {
    if (r.outcome.finished) {
      for (std::string& warning : system_warnings(r, source)) {
        out.warnings.push_back(std::move(warning));
      }
      break;
    }
  }
  for (std::string& why : left_out) {
    out.warnings.push_back(std::move(why));
  }
  for (std::size_t k = 0; k < out.results.size(); ++k) {
    const Result& r = out.results[k];
    if (r.outcome.finished) {
      for (std::string& warning : impulse_warnings(r, names[k] + ": ")) {
        out.warnings.push_back(std::move(warning));
      }
    } else {
      out.unfinished.append(out.unfinished.empty() ? "" : "\n");
      out.unfinished.append(unfinished_message(r, source));
    }
  }
}

// The methods that can resolve the scene, on one solved system (with friction at several
// contacts the paper's simultaneous method cannot: it is left out, and the warnings say why). If
// fewer than two can, every method is asked, and resolve() refuses the scene with the first
// one's reason.
Run compare_methods(const World& world, std::string_view source, const Request& request) {
  std::vector<methods::Method> compared;
  std::vector<std::string> left_out;
  for (const methods::Method method : methods::all_methods) {
    const std::string why = unsupported(world, method);
    if (why.empty()) {
      compared.push_back(method);
    } else {
      left_out.push_back(std::string(name_of(method)) + ": not compared: " + why);
    }
  }
  if (compared.size() < 2) {
    compared.assign(methods::all_methods.begin(), methods::all_methods.end());
    left_out.clear();
  }
  Run out{request, refusing(source, "", [&] { return resolve(world, compared); }), {}, {}};
  std::vector<std::string> names;
  for (const Result& r : out.results) {
    names.emplace_back(name_of(r.method));
    refuse_overflow(r, source, " (method " + names.back() + ")", true);
  }
  tell(out, source, names, std::move(left_out));
  return out;
}

// The scene by its own method once for each restitution law.
Run compare_laws(const World& world, std::string_view source, const Request& request) {
  Run out{request, {}, {}, {}};
  std::vector<std::string> names;
  for (const auto& law : EnumNames<friction::RestitutionLaw>::table) {
    names.emplace_back(law.name);
    Scene scene = world.scene();
    scene.restitution = law.value;
    out.results.push_back(refusing(source,
                                   " (--compare restitution, the law \"" + names.back() + "\")",
                                   [&] { return resolve(World(std::move(scene))); }));
    refuse_overflow(out.results.back(), source, "", true);
  }
  tell(out, source, names, {});
  return out;
}

}  // namespace

struct RunInSlices::State {
  // @p owned the world when the run owns it, else @p given (which outlives the run).
  State(std::optional<World> owned, const World* given, std::string_view s, const Request& r)
      : own(std::move(owned)), world(own ? &*own : given), source(s), request(r) {
    if (request.compare != Request::Compare::nothing) {
      return;  // a comparison runs whole when finished
    }
    if (request.elasticity) {
      // A row of a sweep: every body at its elasticity.
      own = refusing(source, asked(request),
                     [&] { return world->with_elasticity(*request.elasticity); });
      world = &*own;
    }
    resolving.emplace(refusing(source, asked(request), [&] {
      return Resolving(*world, request.method.value_or(world->scene().method));
    }));
  }
  std::optional<World> own;
  const World* world;
  std::string source;
  Request request;
  std::optional<Resolving> resolving;  // one method's, on *world
};

RunInSlices::RunInSlices(const World& world, std::string_view source, const Request& request)
    : state_(std::make_unique<State>(std::nullopt, &world, source, request)) {}

RunInSlices::RunInSlices(World&& world, std::string_view source, const Request& request)
    : state_(std::make_unique<State>(std::move(world), nullptr, source, request)) {}

RunInSlices::~RunInSlices() = default;
RunInSlices::RunInSlices(RunInSlices&&) noexcept = default;
RunInSlices& RunInSlices::operator=(RunInSlices&&) noexcept = default;

bool RunInSlices::advance(std::int64_t collisions) {
  State& s = *state_;
  return !s.resolving ||
         refusing(s.source, asked(s.request), [&] { return s.resolving->advance(collisions); });
}

std::int64_t RunInSlices::collisions() const {
  return state_->resolving ? state_->resolving->collisions() : 0;
}

std::int64_t RunInSlices::bound() const {
  return state_->resolving ? state_->resolving->bound() : 0;
}

Run RunInSlices::finish() {
  State& s = *state_;
  switch (s.request.compare) {
    case Request::Compare::methods:
      return compare_methods(*s.world, s.source, s.request);
    case Request::Compare::laws:
      return compare_laws(*s.world, s.source, s.request);
    case Request::Compare::nothing:
      break;
  }
  return told(refusing(s.source, asked(s.request), [&] { return s.resolving->finish(); }), s.source,
              s.request);
}

Run run(const World& world, std::string_view source, const Request& request) {
  RunInSlices slices(world, source, request);
  slices.advance(std::numeric_limits<std::int64_t>::max());
  return slices.finish();
}

}  // namespace impulse::scene
