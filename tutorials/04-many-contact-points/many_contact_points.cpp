// SPDX-License-Identifier: GPL-3.0-or-later
// Lab 4: many contact points (sections 4 and 5). A box lands flat on two contacts, and a bead (a
// point mass) lands on two supports: one system A Fdt = B per landing. The box's system has full
// rank; the bead's on two parallel supports is dependent, solved two ways (minimum norm and
// basic); tilting the supports a little makes it regular again.
//
// Usage: lab04 [OUTPUT_DIR]   writes lever.csv and tilt.csv there.
#include <cmath>
#include <cstdio>
#include <impulse/impulse.hpp>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "lab.hpp"

namespace mp = impulse::multipoint;

namespace {

constexpr double mass = 1.0;
constexpr double speed = 1.0;  // both land falling straight down at this speed
const impulse::Elasticity elasticity(1.5);

// Two contacts with the static ground (body 0): the landing body (body 1) is each one's wedge.
std::vector<mp::Contact> two_contacts(const Eigen::Vector2d& n1, const Eigen::Vector2d& n2) {
  return {{0, 1, n1, {-1.0, 0.0}}, {0, 1, n2, {1.0, 0.0}}};
}

mp::Resolution land(const mp::Body& body, const std::vector<mp::Contact>& contacts,
                    impulse::DependentPolicy policy) {
  const std::vector<mp::Body> bodies{mp::StaticBody{}, body};
  impulse::SolverOptions options;
  options.dependent = policy;
  mp::Resolution r = mp::resolve(bodies, elasticity, contacts, options);
  if (r.solution.status != impulse::SolveStatus::success) {
    throw std::runtime_error("a landing could not be solved");
  }
  return r;
}

impulse::material_2d::PointMass bead() {
  return impulse::material_2d::from_velocity(mass, {0.0, -speed});
}

}  // namespace

int main(int argc, char** argv) {
  const auto out = lab::output_dir(argc, argv);
  const Eigen::Vector2d up(0.0, 1.0);

  // 1. A box 2 wide and 1 high lands flat on its two bottom corners, at x = -1 and x = 1. Its
  //    centre of mass sits at x = offset (a box loaded off-centre); its moment of inertia is the
  //    uniform box's, m (2^2 + 1^2) / 12. The bead lands on supports at the same two places.
  {
    lab::Csv csv(
        out / "lever.csv",
        {"offset", "box_j1", "box_j2", "box_rank", "box_vy_after", "box_spin_after", "bead_rank",
         "bead_dependent", "bead_min_norm_j1", "bead_min_norm_j2", "bead_basic_j1", "bead_basic_j2",
         "bead_min_norm_vy_after", "bead_basic_vy_after"});
    const auto contacts = two_contacts(up, up);
    for (int i = -20; i <= 20; ++i) {
      const double offset = 0.05 * i;
      impulse::rigid_2d::RigidBody box;
      box.mass = mass;
      box.inertia = mass * (4.0 + 1.0) / 12;
      box.position = {offset, 0.5};
      box.p = {0.0, -mass * speed};
      const mp::Resolution b = land(box, contacts, impulse::DependentPolicy::minimum_norm);
      const auto& box_after = std::get<impulse::rigid_2d::RigidBody>(b.after[1]);

      const mp::Resolution least = land(bead(), contacts, impulse::DependentPolicy::minimum_norm);
      const mp::Resolution basic = land(bead(), contacts, impulse::DependentPolicy::basic);
      const auto vy = [](const mp::Resolution& r) {
        return impulse::material_2d::velocity(std::get<impulse::material_2d::PointMass>(r.after[1]))
            .y();
      };
      csv.row({offset, b.solution.Fdt(0), b.solution.Fdt(1), static_cast<double>(b.solution.rank),
               impulse::rigid_2d::velocity(box_after).y(),
               impulse::rigid_2d::angular_velocity(box_after),
               static_cast<double>(least.solution.rank), least.solution.dependent ? 1.0 : 0.0,
               least.solution.Fdt(0), least.solution.Fdt(1), basic.solution.Fdt(0),
               basic.solution.Fdt(1), vy(least), vy(basic)});
    }
  }

  // 2. The bead in a shallow V: the supports' normals lean in, by angles beta1 (left support,
  //    normal leaning right) and beta2 (right support, leaning left), beta1 + beta2 = tilt (not
  //    the paper's a_1, a_2). Any tilt makes the two normals independent and the answer unique; it
  //    is recorded as the share of the impulse carried by the left support, against beta1 / tilt.
  {
    lab::Csv csv(out / "tilt.csv", {"left_fraction", "share_tilt_2", "share_tilt_30", "rank_tilt_2",
                                    "rank_tilt_30", "vy_after_tilt_2", "vy_after_tilt_30"});
    for (int i = 0; i <= 20; ++i) {
      const double fraction = 0.05 * i;
      double share[2] = {0.0, 0.0};
      double rank[2] = {0.0, 0.0};
      double vy[2] = {0.0, 0.0};
      const double tilts[2] = {2.0, 30.0};
      for (int k = 0; k < 2; ++k) {
        const double beta1 = fraction * tilts[k] * std::numbers::pi / 180;
        const double beta2 = (1 - fraction) * tilts[k] * std::numbers::pi / 180;
        const auto contacts =
            two_contacts({std::sin(beta1), std::cos(beta1)}, {-std::sin(beta2), std::cos(beta2)});
        const mp::Resolution r = land(bead(), contacts, impulse::DependentPolicy::minimum_norm);
        share[k] = r.solution.Fdt(0) / (r.solution.Fdt(0) + r.solution.Fdt(1));
        rank[k] = static_cast<double>(r.solution.rank);
        vy[k] =
            impulse::material_2d::velocity(std::get<impulse::material_2d::PointMass>(r.after[1]))
                .y();
      }
      csv.row({fraction, share[0], share[1], rank[0], rank[1], vy[0], vy[1]});
    }
  }

  std::printf("Lab 4: a box and a bead (mass %g) land at %g on two contacts, elasticity %g\n", mass,
              speed, elasticity.value());
  std::printf("wrote lever.csv and tilt.csv in %s\n", out.c_str());
  return 0;
}
