// SPDX-License-Identifier: GPL-3.0-or-later
#include "warnings.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "app.hpp"
#include "text_report.hpp"

namespace impulselab {

namespace {

namespace methods = impulse::methods;

std::string contact_name(const impulse::scene::Result& result, std::size_t v) {
  std::string text("contact ");
  text.append(std::to_string(v)).append(" (").append(result.impulses[v].bumper);
  text.append("\u2013").append(result.impulses[v].wedge).append(")");
  return text;
}

// Two significant digits: an order of magnitude is what the reader needs.
std::string rounded(double value) {
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), "%.2g", value);
  return text.data();
}

}  // namespace

std::vector<std::string> impulse_warnings(const impulse::scene::Result& result,
                                          std::string_view prefix) {
  std::vector<std::string> lines;
  double largest = 0.0;
  for (const auto& i : result.impulses) {
    largest = std::max(largest, std::abs(i.magnitude));
  }
  for (std::size_t v = 0; v < result.impulses.size(); ++v) {
    const double magnitude = result.impulses[v].magnitude;
    if (magnitude < -rounding_noise * largest) {
      std::string line(prefix);
      line.append(contact_name(result, v)).append(": negative impulse ");
      line.append(number_text(magnitude)).append(" (the contact pulls)");
      lines.push_back(line);
    }
  }
  if (result.method == methods::Method::complementarity) {
    const methods::ComplementaritySolution& c = result.complementarity;
    const std::string residual = number_text(c.residual);
    const std::string scale = number_text(c.scale);
    std::string line(prefix);
    if (c.status == methods::LcpStatus::iteration_limit) {
      line.append("complementarity: projected Gauss-Seidel stopped after ");
      line.append(std::to_string(c.iterations))
          .append(" sweeps with the complementarity residual ");
      line.append(residual).append(" against a scale of ").append(scale);
      line.append(": the impulses are approximate");
      lines.push_back(line);
    } else if (c.status == methods::LcpStatus::inaccurate) {
      line.append(
          "complementarity: rounding left Lemke's pivoting at the complementarity residual ");
      line.append(residual).append(" against a scale of ").append(scale);
      line.append(": the impulses are approximate");
      lines.push_back(line);
    }
  }
  return lines;
}

void print_impulse_warnings(const impulse::scene::Result& result, std::string_view prefix) {
  print_warnings(impulse_warnings(result, prefix));
}

std::string unfinished_message(const impulse::scene::Result& result, const std::string& source) {
  if (impulse::scene::finished(result)) {
    return "";
  }
  std::string message(source);
  if (result.method == methods::Method::serial) {
    const methods::SerialDiagnostics& d = result.serial;
    message.append(": serial collisions did not end: after ");
    message.append(std::to_string(d.order.size())).append(" collisions (the bound: ");
    message.append("solver.max_collisions, by default ");
    message.append(std::to_string(methods::collisions_per_contact)).append(" per contact), ");
    if (d.still_approaching >= 0 &&
        static_cast<std::size_t>(d.still_approaching) < result.impulses.size()) {
      message.append(contact_name(result, static_cast<std::size_t>(d.still_approaching)));
      message.append(" still approaches at ").append(number_text(d.approach_left));
    } else {
      message.append("a contact still approaches");
    }
    message.append(
        ". Below elasticity 2 the same contacts can collide again and again without end "
        "(inelastic collapse), and a light body between heavy ones needs many collisions: "
        "raise \"max_collisions\" in the scene's \"solver\", or choose another method");
  } else {
    message.append(
        ": complementarity: no impulses that only push satisfy A·Fdt >= B (Lemke's pivoting "
        "ended on a ray)");
  }
  return message;
}

void require_finished(const impulse::scene::Result& result, const std::string& source) {
  const std::string message = unfinished_message(result, source);
  if (!message.empty()) {
    throw WorkFailed(message);
  }
}

std::vector<std::string> solve_warnings(const impulse::scene::Result& result,
                                        std::string_view source) {
  std::vector<std::string> warnings;
  const impulse::Solution& s = result.system;
  // Infinity means A = 0 (no body can move along any normal): nothing is solved, nothing to warn.
  if (s.condition_estimate > ill_conditioned &&
      s.condition_estimate < std::numeric_limits<double>::infinity()) {
    const double relative = s.condition_estimate * std::numeric_limits<double>::epsilon();
    std::string line(source);
    line.append(": the system A·Fdt = B is ill-conditioned: condition estimate ")
        .append(rounded(s.condition_estimate))
        .append(s.rank_estimated ? " (estimated)" : "")
        .append(", above ")
        .append(rounded(ill_conditioned))
        .append("; rounding may change the impulses by about ")
        .append(relative < 1.0 ? rounded(relative) + " of their size" : "as much as their size")
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
        .append(rounded(s.residual))
        .append(" against |B| = ")
        .append(rounded(impulse::detail::quiet_norm(s.B)))
        .append(
            "): the scene's numbers are beyond what double precision resolves (masses or "
            "moments of inertia too far apart); do not trust this report");
    warnings.push_back(std::move(line));
  }
  return warnings;
}

void print_warnings(const std::vector<std::string>& warnings) {
  for (const std::string& warning : warnings) {
    std::fprintf(stderr, "impulselab: warning: %s\n", warning.c_str());
  }
}

}  // namespace impulselab
