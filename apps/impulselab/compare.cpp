// SPDX-License-Identifier: GPL-3.0-or-later
#include "compare.hpp"

#include <algorithm>
#include <cmath>

#include "app.hpp"
#include "impulse/core/error.hpp"
#include "impulse/scene/json.hpp"
#include "output.hpp"
#include "text_report.hpp"
#include "warnings.hpp"

namespace impulselab {

namespace {

namespace methods = impulse::methods;
using impulse::scene::Result;

// Rows of cells as columns as wide as their widest cell; the columns named in `text` are
// left-aligned, the others (numbers) right-aligned.
std::string table(const std::vector<std::vector<std::string>>& rows,
                  const std::vector<std::size_t>& text_columns) {
  std::vector<std::size_t> width;
  for (const auto& row : rows) {
    width.resize(std::max(width.size(), row.size()), 0);
    for (std::size_t c = 0; c < row.size(); ++c) {
      // Widths in characters: count UTF-8 lead bytes only (a dash or an ellipsis is one).
      const auto chars = static_cast<std::size_t>(
          std::count_if(row[c].begin(), row[c].end(), [](char ch) { return (ch & 0xC0) != 0x80; }));
      width[c] = std::max(width[c], chars);
    }
  }
  std::string out;
  for (const auto& row : rows) {
    std::string line("  ");
    for (std::size_t c = 0; c < row.size(); ++c) {
      const auto chars = static_cast<std::size_t>(
          std::count_if(row[c].begin(), row[c].end(), [](char ch) { return (ch & 0xC0) != 0x80; }));
      const std::string padding(width[c] - chars, ' ');
      const bool left =
          std::find(text_columns.begin(), text_columns.end(), c) != text_columns.end();
      line.append(c == 0 ? "" : "  ").append(left ? row[c] + padding : padding + row[c]);
    }
    while (!line.empty() && line.back() == ' ') {
      line.pop_back();
    }
    out.append(line).append("\n");
  }
  return out;
}

// "1 pivot", "2 pivots", "3 passes".
std::string count(std::size_t n, const std::string& noun) {
  std::string text = std::to_string(n);
  text.append(" ").append(noun);
  if (n != 1) {
    text.append(noun.ends_with("s") ? "es" : "s");
  }
  return text;
}

std::string diagnostics(const MethodOutcome& o) {
  if (!o.failure.empty()) {
    return "did not finish (see the message below)";
  }
  const Result& r = o.result;
  std::string text;
  switch (o.method) {
    case methods::Method::simultaneous:
      text.append("rank ").append(std::to_string(r.system.rank)).append(" of ");
      text.append(std::to_string(r.system.B.size())).append(", residual |A·Fdt - B| ");
      text.append(number_text(r.system.residual));
      break;
    case methods::Method::complementarity: {
      const auto& c = r.complementarity;
      const bool sweeps = c.algorithm == methods::LcpAlgorithm::projected_gauss_seidel;
      text.append(c.algorithm == methods::LcpAlgorithm::lemke ? "Lemke's pivoting, "
                  : sweeps                                    ? "projected Gauss-Seidel, "
                                                              : "active-set pivoting, ");
      text.append(count(static_cast<std::size_t>(c.iterations), sweeps ? "sweep" : "pivot"));
      text.append(", complementarity residual ").append(number_text(c.residual));
      text.append(c.status == methods::LcpStatus::solved ? "" : " (approximate)");
      break;
    }
    case methods::Method::serial: {
      const auto& d = r.serial;
      text.append(count(d.order.size(), "collision")).append(" in ");
      text.append(count(static_cast<std::size_t>(d.passes), "pass"));
      if (!d.order.empty() && d.order.size() <= 12) {
        text.append(", order");
        for (std::size_t k = 0; k < d.order.size(); ++k) {
          text.append(k == 0 ? " " : ", ").append(std::to_string(d.order[k]));
        }
      }
      break;
    }
  }
  return text;
}

}  // namespace

std::vector<MethodOutcome> solve_each_method(const impulse::scene::Scene& scene,
                                             const std::string& source) {
  std::vector<MethodOutcome> outcomes;
  for (const methods::Method method :
       {methods::Method::simultaneous, methods::Method::complementarity, methods::Method::serial}) {
    impulse::scene::Scene one = scene;
    one.method = method;
    MethodOutcome outcome;
    outcome.method = method;
    outcome.result = impulse::scene::solve(one);
    if (outcome.result.status != impulse::SolveStatus::success) {
      throw impulse::InvalidInput(
          source + ": the numbers overflow (method " + std::string(methods::to_string(method)) +
          "): A·Fdt = B or the state after the collision is not finite (masses, inertias, "
          "velocities or elasticities too extreme for double precision)");
    }
    outcome.failure = unfinished_message(outcome.result, source);
    outcomes.push_back(std::move(outcome));
  }
  return outcomes;
}

std::string comparison_text(const std::vector<MethodOutcome>& outcomes, const std::string& source,
                            bool colour) {
  const auto heading = [&](const std::string& title) {
    std::string text("\n");
    text.append(colour ? "\033[1m" : "").append(title).append(colour ? "\033[0m" : "");
    return text.append("\n");
  };
  const Result& first = outcomes.front().result;
  const int d = first.dimension;
  std::string out(colour ? "\033[1m" : "");
  out.append("Scene ").append(source).append(colour ? "\033[0m" : "");
  out.append(": dimension ").append(std::to_string(d)).append(", ");
  out.append(std::to_string(first.bodies.size()))
      .append(first.bodies.size() == 1 ? " body, " : " bodies, ");
  out.append(std::to_string(first.contacts.size()));
  out.append(first.contacts.size() == 1 ? " contact" : " contacts");
  out.append("; three methods side by side\n");
  out.append(
      "  simultaneous: the paper's, every contact at once (A·Fdt = B)\n"
      "  complementarity: impulses only push (Fdt >= 0, A·Fdt - B >= 0, one of them 0)\n"
      "  serial: one contact at a time, the fastest-approaching first\n");

  std::vector<std::string> names;
  for (const auto& o : outcomes) {
    names.emplace_back(methods::to_string(o.method));
  }
  const auto cell = [](const MethodOutcome& o, const std::string& text) {
    return o.failure.empty() ? text : std::string("-");
  };
  const auto largest = [&](auto get) {
    double scale = 0.0;
    for (const auto& o : outcomes) {
      if (o.failure.empty()) {
        scale = std::max(scale, get(o.result));
      }
    }
    return scale;
  };

  out.append(heading("Impulses Fdt (negative: the contact pulls)"));
  const double impulse_scale = largest([](const Result& r) {
    double m = 0.0;
    for (const auto& i : r.impulses) {
      m = std::max(m, std::abs(i.magnitude));
    }
    return m;
  });
  std::vector<std::vector<std::string>> rows;
  rows.push_back({"contact", "bumper", "wedge"});
  rows.back().insert(rows.back().end(), names.begin(), names.end());
  for (std::size_t v = 0; v < first.impulses.size(); ++v) {
    std::vector<std::string> row{std::to_string(v), first.impulses[v].bumper,
                                 first.impulses[v].wedge};
    for (const auto& o : outcomes) {
      row.push_back(
          cell(o, o.failure.empty() ? chopped(o.result.impulses[v].magnitude, impulse_scale) : ""));
    }
    rows.push_back(row);
  }
  out.append(table(rows, {1, 2}));

  out.append(heading("Velocities after"));
  const double velocity_scale = largest([](const Result& r) {
    double m = 0.0;
    for (const auto& b : r.bodies) {
      m = std::max(
          {m, b.before.velocity.cwiseAbs().maxCoeff(), b.after.velocity.cwiseAbs().maxCoeff()});
    }
    return m;
  });
  rows.clear();
  rows.push_back({"body", "before"});
  rows.back().insert(rows.back().end(), names.begin(), names.end());
  bool any_rigid = false;
  for (std::size_t k = 0; k < first.bodies.size(); ++k) {
    any_rigid = any_rigid || first.bodies[k].kind == impulse::scene::BodyKind::rigid;
    std::vector<std::string> row{first.bodies[k].name,
                                 vector_text(first.bodies[k].before.velocity, d, velocity_scale)};
    for (const auto& o : outcomes) {
      row.push_back(cell(o, o.failure.empty()
                                ? vector_text(o.result.bodies[k].after.velocity, d, velocity_scale)
                                : ""));
    }
    rows.push_back(row);
  }
  out.append(table(rows, {0}));
  if (any_rigid) {
    out.append(heading("Angular velocities after (rigid bodies)"));
    const double spin_scale = largest([](const Result& r) {
      double m = 0.0;
      for (const auto& b : r.bodies) {
        m = std::max({m, std::abs(b.before.angular_velocity), std::abs(b.after.angular_velocity)});
      }
      return m;
    });
    rows.clear();
    rows.push_back({"body", "before"});
    rows.back().insert(rows.back().end(), names.begin(), names.end());
    for (std::size_t k = 0; k < first.bodies.size(); ++k) {
      if (first.bodies[k].kind != impulse::scene::BodyKind::rigid) {
        continue;
      }
      std::vector<std::string> row{first.bodies[k].name,
                                   chopped(first.bodies[k].before.angular_velocity, spin_scale)};
      for (const auto& o : outcomes) {
        row.push_back(cell(o, o.failure.empty()
                                  ? chopped(o.result.bodies[k].after.angular_velocity, spin_scale)
                                  : ""));
      }
      rows.push_back(row);
    }
    out.append(table(rows, {0}));
  }

  out.append(heading("Approach speeds after (> 0: the contact still closes)"));
  const double approach_scale = largest([](const Result& r) {
    double m = 0.0;
    for (const auto& c : r.contacts) {
      m = std::max({m, std::abs(c.approach_before), std::abs(c.approach_after)});
    }
    return m;
  });
  rows.clear();
  rows.push_back({"contact", "before"});
  rows.back().insert(rows.back().end(), names.begin(), names.end());
  for (std::size_t v = 0; v < first.contacts.size(); ++v) {
    std::vector<std::string> row{std::to_string(v),
                                 chopped(first.contacts[v].approach_before, approach_scale)};
    for (const auto& o : outcomes) {
      row.push_back(cell(o, o.failure.empty()
                                ? chopped(o.result.contacts[v].approach_after, approach_scale)
                                : ""));
    }
    rows.push_back(row);
  }
  out.append(table(rows, {}));

  out.append(heading("Totals (momentum leaves out static bodies)"));
  const double energy_scale =
      largest([](const Result& r) { return std::max(r.energy_before, r.energy_after); });
  const double momentum_scale = largest([](const Result& r) {
    return std::max(r.momentum_before.cwiseAbs().maxCoeff(),
                    r.momentum_after.cwiseAbs().maxCoeff());
  });
  rows.clear();
  rows.push_back({"", "before"});
  rows.back().insert(rows.back().end(), names.begin(), names.end());
  std::vector<std::string> energy{"kinetic energy", chopped(first.energy_before, energy_scale)};
  std::vector<std::string> change{"energy change", ""};
  std::vector<std::string> momentum{"momentum",
                                    vector_text(first.momentum_before, d, momentum_scale)};
  for (const auto& o : outcomes) {
    energy.push_back(cell(o, chopped(o.result.energy_after, energy_scale)));
    change.push_back(cell(o, chopped(o.result.energy_change, energy_scale)));
    momentum.push_back(cell(o, vector_text(o.result.momentum_after, d, momentum_scale)));
  }
  rows.push_back(energy);
  rows.push_back(change);
  rows.push_back(momentum);
  out.append(table(rows, {0}));

  out.append(heading("How each method got there"));
  rows.clear();
  for (const auto& o : outcomes) {
    rows.push_back({std::string(methods::to_string(o.method)) + ":", diagnostics(o)});
  }
  out.append(table(rows, {0, 1}));
  return out;
}

nlohmann::ordered_json comparison_json(const std::vector<MethodOutcome>& outcomes) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& o : outcomes) {
    const std::string name(methods::to_string(o.method));
    if (o.failure.empty()) {
      nlohmann::ordered_json result = impulse::scene::to_json(o.result);
      if (!result.contains("method")) {
        result["method"] = name;  // the paper's report names no method; here every one does
      }
      out[name] = std::move(result);
    } else {
      out[name] = {{"method", name}, {"error", o.failure}};
    }
  }
  return out;
}

void compare_methods(const impulse::scene::Scene& scene, const std::string& source,
                     const std::string& format, const std::string& output) {
  const std::vector<MethodOutcome> outcomes = solve_each_method(scene, source);
  const std::string text = format == "json"
                               ? comparison_json(outcomes).dump(2) + "\n"
                               : comparison_text(outcomes, source, colour_wanted(output));
  write_output(output, [&](std::FILE* out) { std::fputs(text.c_str(), out); });
  // The system A·Fdt = B is the same for every method: one warning about its conditioning.
  for (const MethodOutcome& o : outcomes) {
    if (o.failure.empty()) {
      print_warnings(solve_warnings(o.result, source));
      break;
    }
  }
  std::string failures;
  for (const MethodOutcome& o : outcomes) {
    if (o.failure.empty()) {
      print_impulse_warnings(o.result, std::string(methods::to_string(o.method)) + ": ");
    } else {
      failures.append(failures.empty() ? "" : "\n").append(o.failure);
    }
  }
  if (!failures.empty()) {
    throw WorkFailed(failures);
  }
}

}  // namespace impulselab
