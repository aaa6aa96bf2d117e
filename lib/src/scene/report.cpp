// SPDX-License-Identifier: GPL-3.0-or-later
#include "impulse/scene/report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "impulse/core/error.hpp"
#include "impulse/core/text.hpp"

namespace impulse::scene {

namespace {

// The largest magnitude among the values `get` picks, over `items`.
template <typename Items, typename Get>
double largest(const Items& items, Get get) {
  double scale = 0.0;
  for (const auto& item : items) {
    scale = std::max(scale, get(item));
  }
  return scale;
}

std::string heading(std::string_view title, bool colour) {
  std::string text("\n");
  text.append(colour ? "\033[1m" : "").append(title).append(colour ? "\033[0m" : "");
  return text.append("\n");
}

// "Scene s.json: dimension 2, 2 bodies, 1 contact".
std::string scene_line(const Result& r, std::string_view source, bool colour) {
  std::string out(colour ? "\033[1m" : "");
  out.append("Scene ").append(source).append(colour ? "\033[0m" : "");
  out.append(": dimension ").append(std::to_string(r.dimension)).append(", ");
  out.append(counted(r.bodies.size(), "body", "bodies")).append(", ");
  out.append(counted(r.contacts.size(), "contact", "contacts"));
  return out;
}

// The largest speeds, momenta, … of a result, for chopped().
double impulse_scale(const Result& r) {
  return largest(r.impulses, [](const ImpulseReport& i) { return std::abs(i.magnitude); });
}
double velocity_scale(const Result& r) {
  return largest(r.bodies, [](const BodyReport& b) {
    return std::max(b.before.velocity.cwiseAbs().maxCoeff(),
                    b.after.velocity.cwiseAbs().maxCoeff());
  });
}
double spin_scale(const Result& r) {
  return largest(r.bodies, [](const BodyReport& b) {
    return std::max(std::abs(b.before.angular_velocity), std::abs(b.after.angular_velocity));
  });
}
double approach_scale(const Result& r) {
  return largest(r.contacts, [](const ContactReport& c) {
    return std::max(std::abs(c.approach_before), std::abs(c.approach_after));
  });
}
double momentum_total_scale(const Result& r) {
  return std::max(r.momentum_before.cwiseAbs().maxCoeff(), r.momentum_after.cwiseAbs().maxCoeff());
}

// A method's per-contact value v of a column, as text.
std::string column_cell(const methods::ContactColumn& column, std::size_t v) {
  if (const auto* numbers = std::get_if<std::vector<double>>(&column.values)) {
    const double scale = largest(*numbers, [](double x) { return std::abs(x); });
    return v < numbers->size() ? chopped((*numbers)[v], scale) : "";
  }
  const auto& words = std::get<std::vector<std::string>>(column.values);
  return v < words.size() ? words[v] : "";
}

bool any_rigid(const Result& r) {
  return std::any_of(r.bodies.begin(), r.bodies.end(),
                     [](const BodyReport& b) { return b.kind == BodyKind::rigid; });
}

// The system A·Fdt = B: its rank, residual and diagnostics, then A (up to 10 contacts), the
// method's impulses and B.
std::string system_text(const Result& r, double impulses_scale, bool colour) {
  const methods::Outcome& o = r.outcome;
  std::string out;
  const Solution& s = r.system;
  const auto n = static_cast<std::size_t>(s.B.size());
  out.append(heading("System A·Fdt = B", colour));
  out.append("  ").append(counted(n, "equation", "equations"));
  out.append(", rank ").append(std::to_string(s.rank));
  out.append(", residual |A·Fdt - B| = ").append(number_text(o.residual)).append("\n");
  out.append("  ").append(s.dependent ? "dependent (many solutions; the policy picks one)"
                                      : "independent (one solution)");
  out.append(", ").append(s.consistent ? "consistent" : "inconsistent");
  out.append(", policy ").append(name_of(s.options.dependent));
  out.append(", condition estimate ").append(number_text(s.condition_estimate)).append("\n");
  if (!s.dropped.empty()) {
    out.append("  equations dropped:");
    for (const auto v : s.dropped) {
      out.append(" ").append(std::to_string(v));
    }
    out.append("\n");
  }
  const bool has_A = s.A.size() > 0 && static_cast<std::size_t>(s.A.rows()) == n;
  if (!has_A) {
    out.append("  A was not formed by the solver; B and Fdt:\n");
  } else if (n > 10) {
    out.append("  A is ").append(std::to_string(n)).append(" x ").append(std::to_string(n));
    out.append(": too large to show here (--format json has it); B and Fdt:\n");
  }
  std::vector<std::string> header;
  std::vector<bool> left;
  if (has_A && n <= 10) {
    for (std::size_t c = 0; c < n; ++c) {
      header.push_back(c == 0 ? "A" : "");
      left.push_back(false);
    }
    header.emplace_back("|");
    left.push_back(true);
  }
  header.insert(header.end(), {"Fdt", "|", "B"});
  left.insert(left.end(), {false, true, false});
  TextTable system(header, left);
  const double A_scale = has_A ? s.A.cwiseAbs().maxCoeff() : 0.0;
  const double B_scale = n > 0 ? s.B.cwiseAbs().maxCoeff() : 0.0;
  for (std::size_t row = 0; row < n; ++row) {
    const auto i = static_cast<Eigen::Index>(row);
    std::vector<std::string> cells;
    if (has_A && n <= 10) {
      for (std::size_t c = 0; c < n; ++c) {
        cells.push_back(chopped(s.A(i, static_cast<Eigen::Index>(c)), A_scale));
      }
      cells.emplace_back("|");
    }
    cells.insert(cells.end(), {chopped(o.Fdt(i), impulses_scale), "|", chopped(s.B(i), B_scale)});
    system.add(cells);
  }
  out.append(system.render());
  return out;
}

}  // namespace

std::string text_report(const Result& r, std::string_view source, bool colour) {
  const int d = r.dimension;
  const methods::Outcome& o = r.outcome;
  std::string out = scene_line(r, source, colour);
  out.append("\n");
  out.append("Method: ").append(name_of(r.method)).append(" (");
  out.append(row_of(r.method).description).append(")\n");
  for (const std::string& line : o.details) {
    out.append("  ").append(line).append("\n");
  }
  for (const std::string& note : r.notes) {
    out.append("Note: ").append(note).append("\n");
  }

  const double impulses_scale = impulse_scale(r);
  const double velocities_scale = velocity_scale(r);
  const double momentum_scale =
      std::max(largest(r.bodies,
                       [](const BodyReport& b) {
                         return std::max(b.before.momentum.cwiseAbs().maxCoeff(),
                                         b.after.momentum.cwiseAbs().maxCoeff());
                       }),
               momentum_total_scale(r));
  const double spins_scale = spin_scale(r);
  const double angular_momentum_scale = largest(r.bodies, [](const BodyReport& b) {
    return std::max(std::abs(b.before.angular_momentum), std::abs(b.after.angular_momentum));
  });
  const double energy_scale = std::max(r.energy_before, r.energy_after);
  const double approaches_scale = approach_scale(r);

  out.append(heading(o.on_bumper.empty()
                         ? "Impulses (Fdt at each contact; the bumper receives -normal * Fdt)"
                         : "Impulses (Fdt: the normal impulse at each contact; the bumper "
                           "receives -normal * Fdt + tangent * tangential Fdt, tangent = "
                           "[-normal_y, normal_x])",
                     colour));
  std::vector<std::string> impulse_header{"contact", "bumper", "wedge", "Fdt", "on bumper"};
  std::vector<bool> impulse_left{false, true, true, false, false};
  for (const methods::ContactColumn& column : o.per_contact) {
    impulse_header.push_back(column.heading);
    impulse_left.push_back(std::holds_alternative<std::vector<std::string>>(column.values));
  }
  TextTable impulses(impulse_header, impulse_left);
  for (std::size_t v = 0; v < r.impulses.size(); ++v) {
    const ImpulseReport& i = r.impulses[v];
    std::vector<std::string> row{std::to_string(i.contact), i.bumper, i.wedge,
                                 chopped(i.magnitude, impulses_scale),
                                 vector_text(i.on_bumper, d, impulses_scale)};
    for (const methods::ContactColumn& column : o.per_contact) {
      row.push_back(column_cell(column, v));
    }
    impulses.add(std::move(row));
  }
  out.append(impulses.render());

  out.append(heading("Bodies", colour));
  TextTable bodies(
      {"body", "kind", "velocity before", "velocity after", "momentum before", "momentum after"},
      {true, true});
  for (const BodyReport& b : r.bodies) {
    bodies.add({b.name, std::string(name_of(b.kind)),
                vector_text(b.before.velocity, d, velocities_scale),
                vector_text(b.after.velocity, d, velocities_scale),
                vector_text(b.before.momentum, d, momentum_scale),
                vector_text(b.after.momentum, d, momentum_scale)});
  }
  out.append(bodies.render());
  if (any_rigid(r)) {
    out.append(heading("Rotation of the rigid bodies", colour));
    TextTable rotation(
        {"body", "angular velocity before", "after", "angular momentum before", "after"}, {true});
    for (const BodyReport& b : r.bodies) {
      if (b.kind == BodyKind::rigid) {
        rotation.add({b.name, chopped(b.before.angular_velocity, spins_scale),
                      chopped(b.after.angular_velocity, spins_scale),
                      chopped(b.before.angular_momentum, angular_momentum_scale),
                      chopped(b.after.angular_momentum, angular_momentum_scale)});
      }
    }
    out.append(rotation.render());
  }

  out.append(heading("Totals (momentum leaves out static bodies)", colour));
  TextTable totals({"", "before", "after", "change"}, {true});
  totals.add({"kinetic energy", chopped(r.energy_before, energy_scale),
              chopped(r.energy_after, energy_scale), chopped(r.energy_change, energy_scale)});
  const Eigen::Vector2d momentum_change = r.momentum_after - r.momentum_before;
  totals.add({"momentum", vector_text(r.momentum_before, d, momentum_scale),
              vector_text(r.momentum_after, d, momentum_scale),
              vector_text(momentum_change, d, momentum_scale)});
  out.append(totals.render());

  out.append(heading("Contacts (approach: sum of both normal velocities, > 0 closing)", colour));
  TextTable contacts({"contact", "bumper", "wedge", "approach before", "approach after"},
                     {false, true, true});
  for (std::size_t v = 0; v < r.contacts.size(); ++v) {
    contacts.add({std::to_string(v), r.impulses[v].bumper, r.impulses[v].wedge,
                  chopped(r.contacts[v].approach_before, approaches_scale),
                  chopped(r.contacts[v].approach_after, approaches_scale)});
  }
  out.append(contacts.render());

  return out.append(system_text(r, impulses_scale, colour));
}

namespace {

// The columns of a comparison: each result's name and what it is, in a legend.
struct Compared {
  std::string_view what;                 // "methods", "restitution laws"
  std::vector<std::string> names;        // one per result, the column headings
  std::vector<std::string_view> legend;  // one per result, after its name
  std::string_view how = "How each method got there";
};

// The per-contact column of a result named `key`, if its method added one.
const methods::ContactColumn* column_of(const Result& r, std::string_view key) {
  for (const methods::ContactColumn& column : r.outcome.per_contact) {
    if (column.key == key) {
      return &column;
    }
  }
  return nullptr;
}

// Results in columns, one per result after the first result's own: "-" in every cell of a
// result that did not finish, and scales over the results that did.
struct Columns {
  std::span<const Result> results;
  const std::vector<std::string>& names;
  bool colour;

  [[nodiscard]] std::string cell(const Result& r, const std::string& text) const {
    return r.outcome.finished ? text : std::string("-");
  }
  template <typename Get>
  [[nodiscard]] double scale_of(Get get) const {
    double scale = 0.0;
    for (const Result& r : results) {
      if (r.outcome.finished) {
        scale = std::max(scale, get(r));
      }
    }
    return scale;
  }
  [[nodiscard]] std::vector<std::string> header(std::vector<std::string> first_columns) const {
    first_columns.insert(first_columns.end(), names.begin(), names.end());
    return first_columns;
  }
};

// The impulses, and with friction the tangential impulses and how each contact ended.
std::string impulses_side_by_side(const Columns& c) {
  const Result& first = c.results.front();
  std::string out;
  out.append(heading("Impulses Fdt (negative: the contact pulls)", c.colour));
  const double impulses_scale = c.scale_of(impulse_scale);
  TextTable impulses(c.header({"contact", "bumper", "wedge"}), {false, true, true});
  for (std::size_t v = 0; v < first.impulses.size(); ++v) {
    std::vector<std::string> row{std::to_string(v), first.impulses[v].bumper,
                                 first.impulses[v].wedge};
    for (const Result& r : c.results) {
      row.push_back(c.cell(r, chopped(r.impulses[v].magnitude, impulses_scale)));
    }
    impulses.add(std::move(row));
  }
  out.append(impulses.render());
  // With friction: the tangential impulses, and how each contact ended.
  if (std::any_of(c.results.begin(), c.results.end(),
                  [](const Result& r) { return column_of(r, "tangential") != nullptr; })) {
    out.append(
        heading("Tangential impulses (on the bumper, along [-normal_y, normal_x]) and how "
                "each contact ended",
                c.colour));
    TextTable tangential(c.header({"contact"}), {false});
    for (std::size_t v = 0; v < first.impulses.size(); ++v) {
      std::vector<std::string> row{std::to_string(v)};
      for (const Result& r : c.results) {
        const methods::ContactColumn* t = column_of(r, "tangential");
        const methods::ContactColumn* slip = column_of(r, "slip");
        row.push_back(c.cell(r, t == nullptr ? std::string("0")
                                             : column_cell(*t, v) + " (" +
                                                   (slip ? column_cell(*slip, v) : "") + ")"));
      }
      tangential.add(std::move(row));
    }
    out.append(tangential.render());
  }

  return out;
}

// The velocities, spins and approach speeds after.
std::string motion_side_by_side(const Columns& c) {
  const Result& first = c.results.front();
  const int d = first.dimension;
  std::string out;
  out.append(heading("Velocities after", c.colour));
  const double velocities_scale = c.scale_of(velocity_scale);
  TextTable velocities(c.header({"body", "before"}), {true});
  for (std::size_t k = 0; k < first.bodies.size(); ++k) {
    std::vector<std::string> row{first.bodies[k].name,
                                 vector_text(first.bodies[k].before.velocity, d, velocities_scale)};
    for (const Result& r : c.results) {
      row.push_back(c.cell(r, vector_text(r.bodies[k].after.velocity, d, velocities_scale)));
    }
    velocities.add(std::move(row));
  }
  out.append(velocities.render());
  if (any_rigid(first)) {
    out.append(heading("Angular velocities after (rigid bodies)", c.colour));
    const double spins_scale = c.scale_of(spin_scale);
    TextTable spins(c.header({"body", "before"}), {true});
    for (std::size_t k = 0; k < first.bodies.size(); ++k) {
      if (first.bodies[k].kind != BodyKind::rigid) {
        continue;
      }
      std::vector<std::string> row{first.bodies[k].name,
                                   chopped(first.bodies[k].before.angular_velocity, spins_scale)};
      for (const Result& r : c.results) {
        row.push_back(c.cell(r, chopped(r.bodies[k].after.angular_velocity, spins_scale)));
      }
      spins.add(std::move(row));
    }
    out.append(spins.render());
  }

  out.append(heading("Approach speeds after (> 0: the contact still closes)", c.colour));
  const double approaches_scale = c.scale_of(approach_scale);
  TextTable approaches(c.header({"contact", "before"}), {});
  for (std::size_t v = 0; v < first.contacts.size(); ++v) {
    std::vector<std::string> row{std::to_string(v),
                                 chopped(first.contacts[v].approach_before, approaches_scale)};
    for (const Result& r : c.results) {
      row.push_back(c.cell(r, chopped(r.contacts[v].approach_after, approaches_scale)));
    }
    approaches.add(std::move(row));
  }
  out.append(approaches.render());

  return out;
}

// Energy and momentum, and how each result got there.
std::string totals_side_by_side(const Columns& c, std::string_view how_title) {
  const Result& first = c.results.front();
  const int d = first.dimension;
  std::string out;
  out.append(heading("Totals (momentum leaves out static bodies)", c.colour));
  const double energy_scale =
      c.scale_of([](const Result& r) { return std::max(r.energy_before, r.energy_after); });
  const double momentum_scale = c.scale_of(momentum_total_scale);
  TextTable totals(c.header({"", "before"}), {true});
  std::vector<std::string> energy{"kinetic energy", chopped(first.energy_before, energy_scale)};
  std::vector<std::string> change{"energy change", ""};
  std::vector<std::string> momentum{"momentum",
                                    vector_text(first.momentum_before, d, momentum_scale)};
  for (const Result& r : c.results) {
    energy.push_back(c.cell(r, chopped(r.energy_after, energy_scale)));
    change.push_back(c.cell(r, chopped(r.energy_change, energy_scale)));
    momentum.push_back(c.cell(r, vector_text(r.momentum_after, d, momentum_scale)));
  }
  totals.add(std::move(energy));
  totals.add(std::move(change));
  totals.add(std::move(momentum));
  out.append(totals.render());

  out.append(heading(how_title, c.colour));
  TextTable how({}, {true, true});
  for (std::size_t k = 0; k < c.results.size(); ++k) {
    const Result& r = c.results[k];
    how.add({c.names[k] + ":",
             r.outcome.finished ? r.outcome.summary : "did not finish (see the message below)"});
  }
  out.append(how.render());
  return out;
}

std::string compared_text(std::span<const Result> results, std::string_view source, bool colour,
                          const Compared& compared) {
  const Result& first = results.front();
  std::string out = scene_line(first, source, colour);
  out.append("; ").append(results.size() == 3 ? "three" : std::to_string(results.size()));
  out.append(" ").append(compared.what).append(" side by side\n");
  for (std::size_t k = 0; k < results.size(); ++k) {
    out.append("  ").append(compared.names[k]).append(": ");
    out.append(compared.legend[k]).append("\n");
  }
  for (const std::string& note : first.notes) {
    out.append("Note: ").append(note).append("\n");
  }
  const Columns columns{results, compared.names, colour};
  return out.append(impulses_side_by_side(columns))
      .append(motion_side_by_side(columns))
      .append(totals_side_by_side(columns, compared.how));
}

}  // namespace

std::string text(const Run& run, std::string_view source, bool colour) {
  const std::span<const Result> results = run.results;
  Compared compared{"methods", {}, {}};
  switch (run.request.compare) {
    case Request::Compare::nothing:
      return results.front().outcome.finished ? text_report(results.front(), source, colour) : "";
    case Request::Compare::methods:
      for (const Result& r : results) {
        compared.names.emplace_back(name_of(r.method));
        compared.legend.push_back(row_of(r.method).brief);
      }
      break;
    case Request::Compare::laws:
      compared = {"restitution laws", {}, {}, "How each law got there"};
      for (const auto& law : EnumNames<friction::RestitutionLaw>::table) {
        compared.names.emplace_back(law.name);
        compared.legend.push_back(law.definition);
      }
      break;
  }
  return compared_text(results, source, colour, compared);
}

std::vector<std::string> impulse_warnings(const Result& result, std::string_view prefix) {
  std::vector<std::string> lines;
  const double scale = impulse_scale(result);
  for (const ImpulseReport& i : result.impulses) {
    if (i.magnitude < -rounding_noise * scale) {
      std::string line(prefix);
      line.append("contact ").append(std::to_string(i.contact)).append(" (").append(i.bumper);
      line.append("\u2013").append(i.wedge).append("): negative impulse ");
      line.append(number_text(i.magnitude)).append(" (the contact pulls)");
      lines.push_back(std::move(line));
    }
  }
  for (const std::string& warning : result.outcome.warnings) {
    lines.push_back(std::string(prefix).append(warning));
  }
  return lines;
}

std::vector<std::string> system_warnings(const Result& result, std::string_view source) {
  std::vector<std::string> warnings;
  const Solution& s = result.system;
  // Infinity means A = 0 (no body can move along any normal): nothing is solved, nothing to warn.
  if (s.condition_estimate > ill_conditioned &&
      s.condition_estimate < std::numeric_limits<double>::infinity()) {
    const double relative = s.condition_estimate * std::numeric_limits<double>::epsilon();
    std::string line(source);
    line.append(": the system A·Fdt = B is ill-conditioned: condition estimate ")
        .append(rounded_text(s.condition_estimate))
        .append(s.rank_estimated ? " (estimated)" : "")
        .append(", above ")
        .append(rounded_text(ill_conditioned))
        .append("; rounding may change the impulses by about ")
        .append(relative < 1.0 ? rounded_text(relative) + " of their size"
                               : "as much as their size")
        .append(" (the velocities after are less affected)");
    if (s.rank_estimated) {
      // The sparse method's estimate comes from shifted pivots and can be far below the truth;
      // on hostile scenes its impulses were measured off by up to their whole size at estimates
      // of 1e9 (docs/pages/accuracy.md).
      line.append(
          "; the sparse method's estimate can be far below the true condition, and its "
          "impulses were seen off by up to their whole size on such scenes");
    }
    warnings.push_back(std::move(line));
  }
  // A system assembled from bodies always has a solution (B lies in the range of A); a residual
  // beyond the consistency tolerance means rounding lost part of it.
  if (!s.consistent) {
    std::string line(source);
    line.append(": the impulses found do not satisfy A·Fdt = B (residual ")
        .append(rounded_text(s.residual))
        .append(" against |B| = ")
        .append(rounded_text(impulse::detail::quiet_norm(s.B)))
        .append(
            "): the scene's numbers are beyond what double precision resolves (masses or "
            "moments of inertia too far apart); do not trust this report");
    warnings.push_back(std::move(line));
  }
  return warnings;
}

std::vector<std::string> elasticity_warnings(const Result& result, std::string_view source) {
  std::vector<std::string> warnings;
  bool default_named = false;  // the scene's default is named once, whoever collides at it
  for (std::size_t k = 0; k < result.bodies.size(); ++k) {
    const BodyReport& body = result.bodies[k];
    if (body.kind == BodyKind::static_body || (body.elasticity >= 1.0 && body.elasticity <= 2.0) ||
        (!body.own_elasticity && default_named)) {
      continue;
    }
    default_named = default_named || !body.own_elasticity;
    std::string line(source);
    line.append(": ")
        .append(body.own_elasticity ? "bodies[" + std::to_string(k) + "].elasticity"
                                    : std::string("elasticity"))
        .append(": ")
        .append(format_number(body.elasticity));
    if (body.elasticity > 2.0) {
      line.append(" is above 2 (perfectly elastic): a collision at it creates kinetic energy");
    } else {
      line.append(
          " is below 1 (perfectly inelastic): bodies that collide at it still approach each "
          "other after the impulse (the elasticity is 1 + the coefficient of restitution)");
    }
    warnings.push_back(std::move(line));
  }
  return warnings;
}

std::string unfinished_message(const Result& result, std::string_view source) {
  if (result.outcome.finished) {
    return "";
  }
  return std::string(source).append(": ").append(result.outcome.unfinished);
}

}  // namespace impulse::scene
