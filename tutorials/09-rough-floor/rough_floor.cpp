// SPDX-License-Identifier: GPL-3.0-or-later
// Lab 9: a rough floor (beyond the paper). A uniform rod is dropped at an angle onto a static
// floor with Coulomb friction and strikes it with its lower end. The library follows the
// collision through the normal impulse (impulse::friction: Routh's method) with each of the three
// laws of restitution. The lab records
//   the kinetic energy after, and the impulses, against the coefficient of friction mu, for the
//   three laws (Newton's gains energy for a range of mu: Kane and Levinson's paradox);
//   Routh's diagrams: the contact's slip and separation against the normal impulse, drawn through
//   the corners (phase ends) the library reports, for three cases: the slip stops and the contact
//   sticks, the slip reverses, the contact slides throughout.
//
// Usage: lab09 [OUTPUT_DIR] [NAME=VALUE ...]
//   writes rough-floor.csv, laws.csv, routh-1.csv .. routh-3.csv and routh-1-ends.csv ..
//   routh-3-ends.csv there. NAME=VALUE changes the rod or the floor (defaults in brackets):
//   mass [1], length [1], inertia [mass length^2 / 12], angle [45] (degrees between the rod and
//   the floor; the centre is up and to the right of the lower end), vx [0.7], vy [-1] (the
//   centre's velocity), spin [0] (counter-clockwise), elasticity [1.9], mu [0.8] (the case of
//   the table, and the first of Routh's diagrams), mu_low [0.3] (the second), vx_fast [2] (the
//   third: mu_low with the rod thrown sideways at vx_fast), mu_max [1.5] (the sweep's end).
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <impulse/impulse.hpp>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "lab.hpp"

namespace {

namespace friction = impulse::friction;
namespace mp = impulse::multipoint;
using Eigen::Vector2d;
using friction::RestitutionLaw;

constexpr RestitutionLaw laws[] = {RestitutionLaw::newton, RestitutionLaw::poisson,
                                   RestitutionLaw::energetic};

// A bad argument: the program exits 2 with this message.
struct BadArgument : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A number as the messages show it.
std::string text(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

// The lab's numbers, each of which NAME=VALUE may change.
struct Setup {
  std::map<std::string, double, std::less<>> values = {
      {"mass", 1.0},   {"length", 1.0},  {"angle", 45.0},     {"vx", 0.7},
      {"vy", -1.0},    {"spin", 0.0},    {"elasticity", 1.9}, {"mu", 0.8},
      {"mu_low", 0.3}, {"vx_fast", 2.0}, {"mu_max", 1.5},     {"inertia", std::nan("")}};

  [[nodiscard]] double operator[](std::string_view name) const { return values.find(name)->second; }
};

// The first argument is the output folder unless it reads NAME=VALUE.
bool has_output_dir(int argc, char** argv) {
  return argc > 1 && std::string_view(argv[1]).find('=') == std::string_view::npos;
}

Setup read_arguments(int argc, char** argv) {
  Setup setup;
  for (int i = has_output_dir(argc, argv) ? 2 : 1; i < argc; ++i) {
    const std::string_view argument = argv[i];
    const std::size_t equals = argument.find('=');
    const std::string place = "argument " + std::to_string(i) + " (" + std::string(argument) + ")";
    if (equals == std::string_view::npos) {
      throw BadArgument(place + ": expected NAME=VALUE");
    }
    const std::string_view name = argument.substr(0, equals);
    const std::string_view number = argument.substr(equals + 1);
    const auto found = setup.values.find(name);
    if (found == setup.values.end()) {
      throw BadArgument(place +
                        ": expected one of mass, length, inertia, angle, vx, vy, spin, "
                        "elasticity, mu, mu_low, vx_fast, mu_max before '='");
    }
    double value = 0.0;
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (error != std::errc() || end != number.data() + number.size() || !std::isfinite(value)) {
      throw BadArgument(place + ": expected a finite number after '='");
    }
    found->second = value;
  }
  if (std::isnan(setup["inertia"])) {
    setup.values["inertia"] = setup["mass"] * setup["length"] * setup["length"] / 12;
  }
  const auto require = [&](std::string_view name, bool ok, const char* what) {
    if (!ok) {
      throw BadArgument(std::string(name) + " = " + text(setup[name]) + ": expected " + what);
    }
  };
  require("mass", setup["mass"] > 0, "a positive number");
  require("length", setup["length"] > 0, "a positive number");
  require("inertia", setup["inertia"] > 0, "a positive number");
  require("angle", setup["angle"] >= 0 && setup["angle"] <= 90, "an angle from 0 to 90 degrees");
  require("mu_max", setup["mu_max"] > 0, "a positive number");
  return setup;
}

// The rod: its lower end at the origin on the floor, its centre half a length away along the
// angle, moving at (vx, vy) and spinning at `spin`.
impulse::rigid_2d::RigidBody rod(const Setup& s, double vx) {
  const double theta = s["angle"] * std::numbers::pi / 180.0;
  const double half = 0.5 * s["length"];
  return {s["mass"],
          s["inertia"],
          {half * std::cos(theta), half * std::sin(theta)},
          {s["mass"] * vx, s["mass"] * s["vy"]},
          s["inertia"] * s["spin"]};
}

// The floor is static; the rod is the bumper, its outward normal at the lower end points down,
// so the tangent [-n_y, n_x] is +x: the slip is the end's velocity along +x and the tangential
// impulse on the rod points along +x.
const Vector2d end_point(0.0, 0.0);
const Vector2d down(0.0, -1.0);

friction::Collision strike(const impulse::rigid_2d::RigidBody& r, double mu, double e,
                           RestitutionLaw law) {
  friction::Collision c =
      friction::collide(r, mp::StaticBody{}, end_point, down, {mu, impulse::Elasticity(e), law});
  if (c.impulse.status != friction::ContactStatus::resolved) {
    throw BadArgument(std::string("the collision was not resolved (") +
                      std::string(friction::to_string(c.impulse.status)) +
                      "): the rod's lower end must move down into the floor");
  }
  return c;
}

double energy(const friction::Collision& c) {
  return mp::kinetic_energy(c.after.bumper);
}

// "slip until 0.2, stick until 0.925": the phases and the normal impulse at which each ended.
std::string phases(const friction::ContactImpulse& impulse) {
  std::string list;
  for (const friction::Phase& p : impulse.phases()) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%s%s until %.10g", list.empty() ? "" : ", ",
                  std::string(friction::to_string(p.regime)).c_str(), p.end);
    list += buffer;
  }
  return list;
}

// A name for a case of Routh's diagram, from the phases the library found (no commas: it is a
// CSV column's name, which gnuplot uses as the curve's title).
std::string outcome_words(const friction::ContactImpulse& impulse) {
  if (impulse.phase_count == 1) {
    return impulse.outcome == friction::Slip::stick ? "sticks throughout" : "slides throughout";
  }
  return impulse.outcome == friction::Slip::stick ? "slides then sticks" : "slides then reverses";
}

// One of Routh's diagrams: the path of (P_n, P_t, u_n, u_t) through the corners the library
// reports, followed as far as the law that ends last, and where each law ends.
void routh(const std::filesystem::path& out, int number, const Setup& s, double mu, double vx) {
  const auto r = rod(s, vx);
  std::vector<friction::Collision> ends;
  std::size_t longest = 0;
  for (const RestitutionLaw law : laws) {
    ends.push_back(strike(r, mu, s["elasticity"], law));
    if (ends.back().impulse.normal > ends[longest].impulse.normal) {
      longest = ends.size() - 1;
    }
  }
  const friction::ContactImpulse& path = ends[longest].impulse;
  char label[128];
  std::snprintf(label, sizeof label, "mu = %g and v_x = %g: %s", mu, vx,
                outcome_words(path).c_str());
  const std::string name = "routh-" + std::to_string(number);
  {
    lab::Csv csv(out / (name + ".csv"), {"normal", "tangential", "separation", "slip", label});
    csv.row({0.0, 0.0, path.u_before.x(), path.u_before.y(), mu});
    for (const friction::Phase& p : path.phases()) {
      csv.row({p.end, p.tangential, p.u.x(), p.u.y(), mu});
    }
  }
  lab::Csv csv(out / (name + "-ends.csv"),
               {"law", "normal", "tangential", "separation", "slip", "compression", "energy"});
  std::printf("  %s (compression ended at %.10g):\n", label, ends[0].impulse.compression);
  for (std::size_t k = 0; k < ends.size(); ++k) {
    const friction::ContactImpulse& i = ends[k].impulse;
    csv.row({static_cast<double>(k), i.normal, i.tangential, i.u_after.x(), i.u_after.y(),
             i.compression, energy(ends[k])});
    std::printf("    %-10s %s\n", std::string(impulse::name_of(laws[k])).c_str(),
                phases(i).c_str());
  }
}

}  // namespace

int main(int argc, char** argv) try {
  const Setup s = read_arguments(argc, argv);
  const auto out =
      has_output_dir(argc, argv) ? lab::output_dir(argc, argv) : lab::output_dir(1, argv);
  const double e = s["elasticity"];
  const auto before = rod(s, s["vx"]);
  const double energy_before = mp::kinetic_energy(before);
  const friction::ContactDynamics contact =
      friction::dynamics(before, mp::StaticBody{}, end_point, down);
  // Refused before anything is printed: a rod that does not strike, or a law that cannot take
  // the elasticity or a coefficient of friction (the library's message names the value).
  if (!(contact.approach() > 0)) {
    throw BadArgument("the rod's lower end approaches the floor at " + text(contact.approach()) +
                      ": expected it to move down into the floor (change vy or spin)");
  }
  for (const RestitutionLaw law : laws) {
    for (const char* mu : {"mu", "mu_low", "mu_max"}) {
      try {
        friction::validate(friction::ContactLaw{s[mu], impulse::Elasticity(e), law});
      } catch (const impulse::InvalidInput& error) {
        throw BadArgument(std::string(mu) + " = " + text(s[mu]) + ", elasticity = " + text(e) +
                          ": " + error.what());
      }
    }
  }

  std::printf("Lab 9: a rough floor\n");
  std::printf(
      "A rod of mass %g, length %g and inertia %.10g at %g degrees strikes a static floor with "
      "its lower end;\ncentre velocity (%g, %g), spin %g, elasticity %g.\n",
      s["mass"], s["length"], s["inertia"], s["angle"], s["vx"], s["vy"], s["spin"], e);
  std::printf("W = [[%.10g, %.10g], [%.10g, %.10g]], u0 = (%.10g, %.10g)\n", contact.W(0, 0),
              contact.W(0, 1), contact.W(1, 0), contact.W(1, 1), contact.u0.x(), contact.u0.y());
  std::printf("kinetic energy before: %.10g\n\n", energy_before);

  // The table: the three laws at mu.
  {
    const double mu = s["mu"];
    std::printf("At mu = %g:\n", mu);
    std::printf("  %-10s %14s %14s %14s %14s  %s\n", "law", "P_n", "P_t", "energy after", "change",
                "phases (P_n at each end)");
    lab::Csv csv(out / "laws.csv", {"law", "mu", "normal", "tangential", "compression",
                                    "energy_before", "energy_after", "outcome"});
    for (std::size_t k = 0; k < 3; ++k) {
      const auto c = strike(before, mu, e, laws[k]);
      const double after = energy(c);
      std::printf("  %-10s %14.10g %14.10g %14.10g %+14.10g  %s\n",
                  std::string(impulse::name_of(laws[k])).c_str(), c.impulse.normal,
                  c.impulse.tangential, after, after - energy_before, phases(c.impulse).c_str());
      csv.row({static_cast<double>(k), mu, c.impulse.normal, c.impulse.tangential,
               c.impulse.compression, energy_before, after,
               static_cast<double>(static_cast<int>(c.impulse.outcome))});
    }
    std::printf("  compression ended at P_n = %.10g\n\n",
                strike(before, mu, e, RestitutionLaw::newton).impulse.compression);
  }

  // The sweep over mu; where Newton's law first gains energy on the sweep, refined by bisection.
  const int steps = 300;
  const double mu_max = s["mu_max"];
  double first_gain = std::nan("");
  {
    lab::Csv csv(out / "rough-floor.csv",
                 {"mu", "energy_before", "energy_newton", "energy_poisson", "energy_energetic",
                  "normal_newton", "normal_poisson", "normal_energetic", "tangential_newton",
                  "tangential_poisson", "tangential_energetic", "outcome_newton"});
    double previous_mu = 0.0;
    bool previous_gained = false;
    for (int i = 0; i <= steps; ++i) {
      const double mu = mu_max * i / steps;
      const auto n = strike(before, mu, e, RestitutionLaw::newton);
      const auto p = strike(before, mu, e, RestitutionLaw::poisson);
      const auto g = strike(before, mu, e, RestitutionLaw::energetic);
      csv.row({mu, energy_before, energy(n), energy(p), energy(g), n.impulse.normal,
               p.impulse.normal, g.impulse.normal, n.impulse.tangential, p.impulse.tangential,
               g.impulse.tangential, static_cast<double>(static_cast<int>(n.impulse.outcome))});
      const bool gained = energy(n) > energy_before;
      if (gained && !previous_gained && std::isnan(first_gain)) {
        if (i == 0) {
          first_gain = 0.0;
        } else {
          double lo = previous_mu;
          double hi = mu;
          for (int b = 0; b < 60; ++b) {
            const double mid = 0.5 * (lo + hi);
            (energy(strike(before, mid, e, RestitutionLaw::newton)) > energy_before ? hi : lo) =
                mid;
          }
          first_gain = 0.5 * (lo + hi);
        }
      }
      previous_mu = mu;
      previous_gained = gained;
    }
  }
  if (std::isnan(first_gain)) {
    std::printf("Newton's law gains no energy for mu from 0 to %g.\n\n", mu_max);
  } else {
    std::printf("Newton's law first gains energy at mu = %.10g (mu from 0 to %g).\n\n", first_gain,
                mu_max);
  }

  std::printf("Routh's diagrams (the phases of each law, and the normal impulse at each end):\n");
  routh(out, 1, s, s["mu"], s["vx"]);
  routh(out, 2, s, s["mu_low"], s["vx"]);
  routh(out, 3, s, s["mu_low"], s["vx_fast"]);
  std::printf("\nwrote %s and the files of Routh's diagrams\n", (out / "rough-floor.csv").c_str());
  return 0;
} catch (const BadArgument& error) {
  std::fprintf(stderr, "lab09: %s\n", error.what());
  return 2;
} catch (const impulse::InvalidInput& error) {
  std::fprintf(stderr, "lab09: %s\n", error.what());
  return 2;
}
