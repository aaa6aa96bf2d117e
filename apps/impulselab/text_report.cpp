// SPDX-License-Identifier: GPL-3.0-or-later
#include "text_report.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

namespace impulselab {

namespace {

using impulse::scene::BodyKind;
using impulse::scene::Result;

// A table of text cells: columns as wide as their widest cell, numbers right-aligned.
class Table {
 public:
  explicit Table(std::vector<std::string> header, std::vector<bool> numeric)
      : numeric_(std::move(numeric)) {
    rows_.push_back(std::move(header));
  }
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }

  std::string render(const std::string& indent) const {
    std::vector<std::size_t> width(rows_.front().size(), 0);
    for (const auto& row : rows_) {
      for (std::size_t c = 0; c < row.size(); ++c) {
        width[c] = std::max(width[c], row[c].size());
      }
    }
    std::string text;
    for (const auto& row : rows_) {
      std::string line(indent);
      for (std::size_t c = 0; c < row.size(); ++c) {
        const std::string padding(width[c] - row[c].size(), ' ');
        const bool right = c < numeric_.size() && numeric_[c];
        line.append(c == 0 ? "" : "  ");
        line.append(right ? padding + row[c] : row[c] + padding);
      }
      while (!line.empty() && line.back() == ' ') {
        line.pop_back();
      }
      text.append(line).append("\n");
    }
    return text;
  }

 private:
  std::vector<bool> numeric_;
  std::vector<std::vector<std::string>> rows_;
};

// The largest magnitude among the values `get` picks, over `items`.
template <typename Items, typename Get>
double largest(const Items& items, Get get) {
  double scale = 0.0;
  for (const auto& item : items) {
    scale = std::max(scale, get(item));
  }
  return scale;
}

std::string plural(std::size_t count, const char* one, const char* many) {
  std::string text = std::to_string(count);
  text.append(" ").append(count == 1 ? one : many);
  return text;
}

// The method's line (issue 9) and, for the two that are not the paper's, its diagnostics.
std::string method_text(const Result& r) {
  namespace methods = impulse::methods;
  std::string out("Method: ");
  out.append(methods::to_string(r.method));
  switch (r.method) {
    case methods::Method::simultaneous:
      out.append(" (the paper's: every contact at once, A·Fdt = B)\n");
      break;
    case methods::Method::complementarity: {
      const methods::ComplementaritySolution& c = r.complementarity;
      out.append(
          " (impulses only push: Fdt >= 0 and A·Fdt - B >= 0, one of them 0 at each "
          "contact)\n  ");
      const auto count = static_cast<std::size_t>(c.iterations);
      switch (c.algorithm) {
        case methods::LcpAlgorithm::lemke:
          out.append("Lemke's pivoting, ").append(plural(count, "pivot", "pivots"));
          break;
        case methods::LcpAlgorithm::projected_gauss_seidel:
          out.append("projected Gauss-Seidel, ").append(plural(count, "sweep", "sweeps"));
          break;
        case methods::LcpAlgorithm::active_set:
        case methods::LcpAlgorithm::automatic:
          out.append("active-set pivoting, ").append(plural(count, "pivot", "pivots"));
          break;
      }
      out.append(c.status == methods::LcpStatus::solved ? "" : " (approximate)");
      out.append(", complementarity residual ").append(number_text(c.residual));
      out.append(c.least_norm ? ", the least-norm solution\n" : "\n");
      out.append("  slack A·Fdt - B (0 where a contact pushes):");
      for (Eigen::Index v = 0; v < c.w.size(); ++v) {
        out.append(v == 0 ? " " : ", ").append(chopped(c.w(v), c.scale));
      }
      out.append("\n");
      break;
    }
    case methods::Method::serial: {
      const methods::SerialDiagnostics& d = r.serial;
      out.append(
          " (one contact at a time, the fastest-approaching first, until none "
          "approaches)\n  ");
      out.append(plural(d.order.size(), "collision", "collisions")).append(" in ");
      out.append(plural(static_cast<std::size_t>(d.passes), "pass", "passes"));
      out.append(" (bound ").append(std::to_string(d.max_collisions)).append(")");
      if (!d.order.empty()) {
        out.append("; contacts in turn:");
        constexpr std::size_t shown = 40;
        for (std::size_t k = 0; k < d.order.size() && k < shown; ++k) {
          out.append(k == 0 ? " " : ", ").append(std::to_string(d.order[k]));
        }
        if (d.order.size() > shown) {
          out.append(", … (--format json lists all)");
        }
      }
      out.append("\n");
      break;
    }
  }
  return out;
}

}  // namespace

std::string number_text(double value) {
  std::array<char, 32> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.6g", value + 0.0);  // + 0.0: no "-0"
  return buffer.data();
}

std::string text_report(const Result& r, const std::string& source, bool colour) {
  const int d = r.dimension;
  const auto heading = [&](const std::string& title) {
    std::string text("\n");
    text.append(colour ? "\033[1m" : "").append(title).append(colour ? "\033[0m" : "");
    return text.append("\n");
  };
  std::string out(colour ? "\033[1m" : "");
  out.append("Scene ").append(source).append(colour ? "\033[0m" : "");
  out.append(": dimension ").append(std::to_string(d)).append(", ");
  out.append(plural(r.bodies.size(), "body", "bodies")).append(", ");
  out.append(plural(r.contacts.size(), "contact", "contacts")).append("\n");
  out.append(method_text(r));

  const double impulse_scale =
      largest(r.impulses, [](const auto& i) { return std::abs(i.magnitude); });
  const double velocity_scale = largest(r.bodies, [](const auto& b) {
    return std::max(b.before.velocity.cwiseAbs().maxCoeff(),
                    b.after.velocity.cwiseAbs().maxCoeff());
  });
  const double momentum_scale = std::max(
      largest(r.bodies,
              [](const auto& b) {
                return std::max(b.before.momentum.cwiseAbs().maxCoeff(),
                                b.after.momentum.cwiseAbs().maxCoeff());
              }),
      std::max(r.momentum_before.cwiseAbs().maxCoeff(), r.momentum_after.cwiseAbs().maxCoeff()));
  const double spin_scale = largest(r.bodies, [](const auto& b) {
    return std::max(std::abs(b.before.angular_velocity), std::abs(b.after.angular_velocity));
  });
  const double angular_momentum_scale = largest(r.bodies, [](const auto& b) {
    return std::max(std::abs(b.before.angular_momentum), std::abs(b.after.angular_momentum));
  });
  const double energy_scale = std::max(r.energy_before, r.energy_after);
  const double approach_scale = largest(r.contacts, [](const auto& c) {
    return std::max(std::abs(c.approach_before), std::abs(c.approach_after));
  });

  out.append(heading("Impulses (Fdt at each contact; the bumper receives -normal * Fdt)"));
  Table impulses({"contact", "bumper", "wedge", "Fdt", "on bumper"},
                 {true, false, false, true, true});
  for (const auto& i : r.impulses) {
    impulses.add({std::to_string(i.contact), i.bumper, i.wedge, chopped(i.magnitude, impulse_scale),
                  vector_text(i.on_bumper, d, impulse_scale)});
  }
  out.append(impulses.render("  "));

  out.append(heading("Bodies"));
  Table bodies(
      {"body", "kind", "velocity before", "velocity after", "momentum before", "momentum after"},
      {false, false, true, true, true, true});
  bool any_rigid = false;
  for (const auto& b : r.bodies) {
    any_rigid = any_rigid || b.kind == BodyKind::rigid;
    bodies.add({b.name, std::string(impulse::scene::to_string(b.kind)),
                vector_text(b.before.velocity, d, velocity_scale),
                vector_text(b.after.velocity, d, velocity_scale),
                vector_text(b.before.momentum, d, momentum_scale),
                vector_text(b.after.momentum, d, momentum_scale)});
  }
  out.append(bodies.render("  "));
  if (any_rigid) {
    out.append(heading("Rotation of the rigid bodies"));
    Table rotation({"body", "angular velocity before", "after", "angular momentum before", "after"},
                   {false, true, true, true, true});
    for (const auto& b : r.bodies) {
      if (b.kind == BodyKind::rigid) {
        rotation.add({b.name, chopped(b.before.angular_velocity, spin_scale),
                      chopped(b.after.angular_velocity, spin_scale),
                      chopped(b.before.angular_momentum, angular_momentum_scale),
                      chopped(b.after.angular_momentum, angular_momentum_scale)});
      }
    }
    out.append(rotation.render("  "));
  }

  out.append(heading("Totals (momentum leaves out static bodies)"));
  Table totals({"", "before", "after", "change"}, {false, true, true, true});
  totals.add({"kinetic energy", chopped(r.energy_before, energy_scale),
              chopped(r.energy_after, energy_scale), chopped(r.energy_change, energy_scale)});
  const Eigen::Vector2d momentum_change = r.momentum_after - r.momentum_before;
  totals.add({"momentum", vector_text(r.momentum_before, d, momentum_scale),
              vector_text(r.momentum_after, d, momentum_scale),
              vector_text(momentum_change, d, momentum_scale)});
  out.append(totals.render("  "));

  out.append(heading("Contacts (approach: sum of both normal velocities, > 0 closing)"));
  Table contacts({"contact", "bumper", "wedge", "approach before", "approach after"},
                 {true, false, false, true, true});
  for (std::size_t v = 0; v < r.contacts.size(); ++v) {
    contacts.add({std::to_string(v), r.impulses[v].bumper, r.impulses[v].wedge,
                  chopped(r.contacts[v].approach_before, approach_scale),
                  chopped(r.contacts[v].approach_after, approach_scale)});
  }
  out.append(contacts.render("  "));

  const auto& s = r.system;
  const auto n = static_cast<std::size_t>(s.B.size());
  out.append(heading("System A·Fdt = B"));
  out.append("  ").append(plural(n, "equation", "equations"));
  out.append(", rank ").append(std::to_string(s.rank));
  out.append(", residual |A·Fdt - B| = ").append(number_text(s.residual)).append("\n");
  out.append("  ").append(s.dependent ? "dependent (many solutions; the policy picks one)"
                                      : "independent (one solution)");
  out.append(", ").append(s.consistent ? "consistent" : "inconsistent");
  out.append(", policy ").append(impulse::to_string(s.options.dependent));
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
  std::vector<bool> numeric;
  if (has_A && n <= 10) {
    for (std::size_t c = 0; c < n; ++c) {
      header.push_back(c == 0 ? "A" : "");
      numeric.push_back(true);
    }
    header.emplace_back("|");
    numeric.push_back(false);
  }
  header.insert(header.end(), {"Fdt", "|", "B"});
  numeric.insert(numeric.end(), {true, false, true});
  Table system(header, numeric);
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
    cells.insert(cells.end(), {chopped(s.Fdt(i), impulse_scale), "|", chopped(s.B(i), B_scale)});
    system.add(cells);
  }
  out.append(system.render("  "));
  return out;
}

std::string chopped(double value, double scale) {
  return number_text(std::abs(value) <= rounding_noise * scale ? 0.0 : value);
}

std::string vector_text(const Eigen::Vector2d& v, int dimension, double scale) {
  if (dimension == 1) {
    return chopped(v.x(), scale);
  }
  std::string text("[");
  text.append(chopped(v.x(), scale)).append(", ").append(chopped(v.y(), scale)).append("]");
  return text;
}

}  // namespace impulselab
