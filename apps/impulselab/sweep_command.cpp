// SPDX-License-Identifier: GPL-3.0-or-later
#include "sweep_command.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app.hpp"
#include "impulse/core/error.hpp"
#include "impulse/scene/run.hpp"
#include "output.hpp"
#include "scene_input.hpp"

namespace impulselab {

namespace {

// Within rounding: how far (in steps) TO may miss the grid and still count as on it.
constexpr double grid_tolerance = 1e-9;

[[noreturn]] void refuse(std::string_view option, std::string_view text, std::string_view why) {
  std::string message(option);
  message.append(" ").append(text).append(": ").append(why);
  throw UsageError(message);
}

double parse_number(std::string_view option, std::string_view whole, std::string_view part,
                    const char* name) {
  double value = 0.0;
  const char* first = part.data();
  const char* last = part.data() + part.size();
  const auto [end, error] = std::from_chars(first, last, value);
  if (part.empty() || error != std::errc{} || end != last) {
    refuse(option, whole,
           std::string(name) + " must be a number, got \"" + std::string(part) + "\"");
  }
  if (!std::isfinite(value)) {
    refuse(option, whole, std::string(name) + " must be finite, got " + std::string(part));
  }
  return value;
}

struct SweepOptions {
  std::string scene;
  std::string elasticity;
  std::string output;
};

std::string csv_number(double value) {
  return impulse::format_number(value + 0.0);  // shortest text that reads back; no "-0"
}

// The scene at elasticity e (scene::run): a scene whose solver.method is serial must end its
// collisions within their bound.
impulse::scene::Run run_at(const impulse::scene::World& world, double e,
                           const std::string& source) {
  impulse::scene::Run run = impulse::scene::run(world, source, {.elasticity = e});
  if (!run.unfinished.empty()) {
    throw WorkFailed(run.unfinished);
  }
  return run;
}

void sweep(const SweepOptions& options) {
  const Range range = parse_range(options.elasticity);
  const std::string source = scene_name(options.scene);
  const impulse::scene::World world = read_world(options.scene);
  // Impulses are linear in the elasticity and energies quadratic: if both ends of the range are
  // finite, so is every value between, and nothing is written before the ends are known good;
  // their results are the first and last rows. A does not depend on the elasticity: the first
  // row's warning about its conditioning serves every row.
  const impulse::scene::Run first = run_at(world, range.at(0), source);
  const std::optional<impulse::scene::Run> last =
      range.count > 1 ? std::optional(run_at(world, range.at(range.count - 1), source))
                      : std::nullopt;
  const auto row_result = [&](std::size_t i) {
    if (i == 0) {
      return first.results.front();
    }
    return last && i + 1 == range.count ? last->results.front()
                                        : run_at(world, range.at(i), source).results.front();
  };

  const std::size_t contacts = world.scene().contacts.size();
  write_output(options.output, [&](std::FILE* out) {
    std::string header("elasticity,energy_after,energy_change");
    for (std::size_t v = 0; v < contacts; ++v) {
      header.append(",impulse_").append(std::to_string(v));
    }
    for (std::size_t v = 0; v < contacts; ++v) {
      header.append(",approach_after_").append(std::to_string(v));
    }
    std::fputs(header.append("\n").c_str(), out);
    std::string row;
    for (std::size_t i = 0; i < range.count; ++i) {
      const double e = range.at(i);
      const impulse::scene::Result r = row_result(i);
      row.assign(csv_number(e));
      row.append(",").append(csv_number(r.energy_after));
      row.append(",").append(csv_number(r.energy_change));
      for (const auto& impulse : r.impulses) {
        row.append(",").append(csv_number(impulse.magnitude));
      }
      for (const auto& contact : r.contacts) {
        row.append(",").append(csv_number(contact.approach_after));
      }
      row.append("\n");
      if (std::fputs(row.c_str(), out) < 0) {
        return;  // write_output reports the stream's error
      }
    }
  });
  print_warnings(first.warnings);
}

}  // namespace

double Range::at(std::size_t i) const {
  if (i + 1 == count &&
      std::abs(from + static_cast<double>(i) * step - to) <= grid_tolerance * step) {
    return to;
  }
  return std::min(from + static_cast<double>(i) * step, to);  // never past TO by a rounding
}

Range parse_range(std::string_view text, std::string_view option) {
  const std::size_t first = text.find(':');
  const std::size_t second = first == std::string_view::npos ? first : text.find(':', first + 1);
  if (second == std::string_view::npos || text.find(':', second + 1) != std::string_view::npos) {
    refuse(option, text, "expected FROM:TO:STEP, three numbers (e.g. 0:3:0.05)");
  }
  Range range;
  range.from = parse_number(option, text, text.substr(0, first), "FROM");
  range.to = parse_number(option, text, text.substr(first + 1, second - first - 1), "TO");
  range.step = parse_number(option, text, text.substr(second + 1), "STEP");
  if (range.from < 0.0) {
    refuse(option, text, "FROM must be at least 0 (an elasticity is not negative)");
  }
  if (range.from > range.to) {
    refuse(option, text, "FROM must not be greater than TO");
  }
  if (!(range.step > 0.0)) {
    refuse(option, text, "STEP must be positive");
  }
  // The number of whole steps from FROM to TO, counting TO when it is within rounding of the grid.
  // The quotient carries a rounding relative to its size, hence a tolerance relative to it.
  const double steps = (range.to - range.from) / range.step;
  const double nearest = std::round(steps);
  const double whole = std::abs(steps - nearest) <= grid_tolerance * std::max(1.0, steps)
                           ? nearest
                           : std::floor(steps);
  if (!(whole + 1.0 <= static_cast<double>(max_sweep_rows))) {
    std::string why("gives ");
    why.append(std::isfinite(whole) ? impulse::format_number(whole + 1.0) : "too many");
    why.append(" values; a sweep writes at most ").append(std::to_string(max_sweep_rows));
    refuse(option, text, why);
  }
  range.count = static_cast<std::size_t>(whole) + 1;
  return range;
}

void add_sweep_command(CLI::App& app) {
  auto options = std::make_shared<SweepOptions>();
  CLI::App* verb = app.add_subcommand(
      "sweep",
      "Solve the scene at each elasticity of a range and write one CSV row each: elasticity, "
      "energy_after, energy_change, impulse_0.., approach_after_0.. (one per contact). Every "
      "body collides at the swept elasticity: the bodies' own elasticities and the scene's "
      "default are overridden.");
  verb->add_option("scene", options->scene, "the scene file (JSON); - for standard input")
      ->required();
  verb->add_option("--elasticity,-e", options->elasticity,
                   "FROM:TO:STEP, e.g. 0:3:0.05 (TO included when on the grid; FROM >= 0; at "
                   "most 1000000 values)")
      ->required();
  verb->add_option("--output,-o", options->output,
                   "write the CSV here instead of standard output (atomically: all or nothing)");
  verb->callback([options]() { sweep(*options); });
}

}  // namespace impulselab
