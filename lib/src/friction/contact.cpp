// SPDX-License-Identifier: GPL-3.0-or-later
// Routh's method for one contact with Coulomb friction (Stronge, Impact Mechanics, ch. 5).
//
// The relative velocity u = (separation, slip) follows u(P) = u0 + W P. In a phase the ratio
// dP_t / dP_n is constant (slip: -s mu; stick: -W_tn / W_tt), so u is linear in the normal
// impulse, and each end of a phase (slip stops, compression ends, restitution ends) is the root
// of a linear (or, for the energetic law, quadratic) equation. A phase is walked along the
// direction (dP_n, dP_t) scaled so that neither component exceeds 1 in magnitude: a huge mu or
// stick ratio then makes a short step in P_n, not an overflow.
#include "impulse/friction/contact.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "impulse/core/error.hpp"

namespace impulse::friction {

namespace {

// How far W may be from symmetric, and |W_nt| above sqrt(W_nn W_tt), relative to W's size.
constexpr double matrix_tolerance = 1e-12;
constexpr double infinity = std::numeric_limits<double>::infinity();

// numerator / denominator for numerator >= 0 and denominator >= 0: 0 for a zero numerator (the
// end is where the phase starts), +infinity where the quotient would overflow or the denominator
// is 0 (the division is then not done: no exception is raised).
double ratio(double numerator, double denominator) {
  if (numerator == 0.0) {
    return 0.0;
  }
  if (!(denominator > 0.0)) {
    return infinity;
  }
  if (denominator < 1.0 && numerator > denominator * std::numeric_limits<double>::max()) {
    return infinity;
  }
  return numerator / denominator;
}

double sign(double x) {
  return x > 0.0 ? 1.0 : -1.0;
}

// A phase's direction in the impulse plane: (dP_n, dP_t), dP_n > 0, both at most 1.
struct Direction {
  double normal = 1.0;
  double tangential = 0.0;
};

// Slip along s: dP_t = -s mu dP_n (Coulomb's law against the slip).
Direction slip_direction(double mu, double s) {
  if (mu <= 1.0) {
    return {1.0, -s * mu};
  }
  return {1.0 / mu, -s};
}

// Stick: du_t = W_tn dP_n + W_tt dP_t = 0, so dP_t = -W_tn / W_tt dP_n (nothing when W_tt = 0,
// where W_tn = 0 too: a tangential impulse would then change nothing).
Direction stick_direction(const Eigen::Matrix2d& W) {
  const double W_tt = W(1, 1);
  const double W_tn = W(1, 0);
  if (!(W_tt > 0.0)) {
    return {1.0, 0.0};
  }
  const double scale = std::max(W_tt, std::abs(W_tn));
  return {W_tt / scale, -W_tn / scale};
}

// Whether the contact can stick: the stick ratio |W_tn| / W_tt is within mu.
bool can_stick(const Eigen::Matrix2d& W, double mu) {
  if (!(W(1, 1) > 0.0)) {
    return W(1, 0) == 0.0;
  }
  return ratio(std::abs(W(1, 0)), W(1, 1)) <= mu;
}

// How far along a restitution phase the normal impulse does the work `left`: the work after
// x is d_n (u_n x + v_n x^2 / 2), with u_n >= 0 the separation where the phase starts, v_n its
// growth along the phase and d_n the phase's dP_n per step. The root is taken in the form that
// does not cancel, x = 2 l / (u_n + sqrt(u_n^2 + 2 v_n l)) with l = left / d_n, and the square
// root as sqrt(u_n^2 + q^2) with q = sqrt(2 v_n) sqrt(l) (or sqrt(u_n - q) sqrt(u_n + q) if
// v_n < 0), so that nothing overflows; infinity when the phase never does that work.
double to_work(double left, double d_n, double u_n, double v_n) {
  const double l = ratio(left, d_n);
  if (l == 0.0) {
    return 0.0;
  }
  if (!std::isfinite(l)) {
    return infinity;
  }
  const double q = std::sqrt(2.0 * std::abs(v_n)) * std::sqrt(l);
  double root = 0.0;
  if (v_n >= 0.0) {
    root = std::hypot(u_n, q);
  } else if (q <= u_n) {
    root = std::sqrt(u_n - q) * std::sqrt(u_n + q);
  } else {
    return infinity;  // the separation falls before the work is done (not for a W from bodies)
  }
  return ratio(l, (u_n + root) / 2.0);
}

[[noreturn]] void refuse(const std::string& message) {
  throw InvalidInput(message);
}

// W made exactly symmetric, its coupling within the semi-definite bound (validate() allowed a
// rounding's worth beyond either): the stick phase then never speeds up the approach.
Eigen::Matrix2d symmetrised(Eigen::Matrix2d W) {
  const double bound = std::sqrt(W(0, 0)) * std::sqrt(W(1, 1));
  const double coupling = std::clamp((W(0, 1) + W(1, 0)) / 2.0, -bound, bound);
  W(0, 1) = coupling;
  W(1, 0) = coupling;
  return W;
}

// du along a phase's direction d. At stick the slip stays 0 (W_tn W_tt - W_tt W_tn, zero but
// for rounding), and the separation grows by (W_nn W_tt - W_nt^2) / scale with the determinant
// computed without cancellation when it is known.
Eigen::Vector2d rate(const Eigen::Matrix2d& W, std::optional<double> determinant, Slip regime,
                     const Direction& d) {
  Eigen::Vector2d v = W * Eigen::Vector2d(d.normal, d.tangential);
  if (regime == Slip::stick) {
    v.y() = 0.0;
    if (determinant && W(1, 1) > 0.0) {
      v.x() = *determinant * (d.normal / W(1, 1));
    }
  }
  return v;
}

// The first regime and its slip direction s: slip along the slip there is; from rest, stick if
// the ratio allows (s = 0), else slip the way W_tn drives the contact.
std::pair<Slip, double> first_regime(const Eigen::Matrix2d& W, double mu, double slip) {
  if (slip != 0.0) {
    return {Slip::slip, sign(slip)};
  }
  return can_stick(W, mu) ? std::pair{Slip::stick, 0.0} : std::pair{Slip::slip, sign(W(1, 0))};
}

}  // namespace

std::string_view to_string(Slip regime) {
  switch (regime) {
    case Slip::slip:
      return "slip";
    case Slip::stick:
      return "stick";
    case Slip::reversed:
      return "reversed";
  }
  return "?";
}

std::string_view to_string(ContactStatus status) {
  switch (status) {
    case ContactStatus::resolved:
      return "resolved";
    case ContactStatus::not_approaching:
      return "not-approaching";
    case ContactStatus::cannot_stop:
      return "cannot-stop";
    case ContactStatus::non_finite:
      return "non-finite";
  }
  return "?";
}

void validate(const ContactLaw& law) {
  if (!(std::isfinite(law.friction) && law.friction >= 0.0)) {
    refuse("friction must be finite and at least 0, got " + format_number(law.friction));
  }
  const double e = law.elasticity.value();
  if (e < 1.0) {
    refuse(
        "elasticity must be at least 1 with friction (the impulse is followed through "
        "compression, which it cannot stop before), got " +
        format_number(e));
  }
  if (law.restitution == RestitutionLaw::energetic && e > 2.0) {
    refuse(
        "elasticity must be at most 2 for the energetic law (restitution gives back at most "
        "the work of compression), got " +
        format_number(e));
  }
}

void validate(const ContactDynamics& contact) {
  const Eigen::Matrix2d& W = contact.W;
  const auto entries = [&W] {
    return "[[" + format_number(W(0, 0)) + ", " + format_number(W(0, 1)) + "], [" +
           format_number(W(1, 0)) + ", " + format_number(W(1, 1)) + "]]";
  };
  if (!all_finite_in(W)) {
    refuse("W must be finite, got " + entries());
  }
  if (!all_finite_in(contact.u0)) {
    refuse("u0 must be finite, got [" + format_number(contact.u0.x()) + ", " +
           format_number(contact.u0.y()) + "]");
  }
  if (W(0, 0) < 0.0 || W(1, 1) < 0.0) {
    refuse("W must be positive semi-definite (its diagonal at least 0), got " + entries());
  }
  const double size = W.cwiseAbs().maxCoeff();
  if (std::abs(W(0, 1) - W(1, 0)) > matrix_tolerance * size) {
    refuse("W must be symmetric, got " + entries());
  }
  // |W_nt| <= sqrt(W_nn) sqrt(W_tt): the determinant is not negative (without the product
  // W_nn W_tt, which could overflow).
  const double bound = std::sqrt(W(0, 0)) * std::sqrt(W(1, 1));
  const double off = std::abs(W(0, 1) + W(1, 0)) / 2.0;
  if (off > bound * (1.0 + matrix_tolerance)) {
    refuse("W must be positive semi-definite (|W_nt| at most sqrt(W_nn W_tt) = " +
           format_number(bound) + "), got " + entries());
  }
  if (contact.determinant) {
    const double det = *contact.determinant;
    if (!(std::isfinite(det) && det >= 0.0)) {
      refuse("the determinant of W must be finite and at least 0, got " + format_number(det));
    }
    // Compared on W / size, so that no product overflows.
    const Eigen::Matrix2d scaled = size > 0.0 ? Eigen::Matrix2d(W / size) : W;
    const double products = scaled(0, 0) * scaled(1, 1) + std::abs(scaled(0, 1) * scaled(1, 0));
    const double difference = scaled(0, 0) * scaled(1, 1) - scaled(0, 1) * scaled(1, 0);
    const double given = size > 0.0 ? det / size / size : det;
    if (std::abs(given - difference) > matrix_tolerance * products) {
      refuse("the determinant of W must be W_nn W_tt - W_nt W_tn = " +
             format_number(difference * size * size) + " (within " +
             format_number(matrix_tolerance) + " of the products), got " + format_number(det) +
             " for W = " + entries());
    }
  }
}

ContactImpulse resolve_contact(const ContactDynamics& contact, const ContactLaw& law) {
  validate(contact);
  validate(law);
  const double mu = law.friction;
  const double e = law.elasticity.value();

  const Eigen::Matrix2d W = symmetrised(contact.W);
  ContactImpulse r;
  r.u_before = contact.u0;
  r.u_after = contact.u0;
  Eigen::Vector2d u = contact.u0;
  if (!(u.x() < 0.0)) {
    r.status = ContactStatus::not_approaching;
    r.outcome = u.y() != 0.0 ? Slip::slip : Slip::stick;
    return r;
  }

  auto [regime, s] = first_regime(W, mu, u.y());
  // Only a slip that has a speed to lose can stop: a slip from rest or a reversed slip is
  // driven by W_tn beyond what friction holds, and goes on to the end.
  bool slip_can_stop = regime == Slip::slip && u.y() != 0.0;

  bool compressing = true;
  double P = 0.0;   // normal impulse so far
  double Pt = 0.0;  // tangential impulse so far
  // Newton: the separation speed to reach, (e - 1) times the approach before.
  const double newton_target = (e - 1.0) * -contact.u0.x();
  double work_target = 0.0;  // energetic: (e - 1)^2 |work of compression|, once it is known
  bool finished = false;

  for (int event = 0; !finished; ++event) {
    // Each pass ends at least one of: the slip stops (once), compression ends, the law is met.
    assert(event < 3);
    const Direction d = regime == Slip::stick ? stick_direction(W) : slip_direction(mu, s);
    const Eigen::Vector2d v = rate(W, contact.determinant, regime, d);

    // How far along the direction each end lies (infinity: not in this phase).
    double to_slip_stop = infinity;
    if (slip_can_stop && s * v.y() < 0.0) {
      to_slip_stop = ratio(std::abs(u.y()), std::abs(v.y()));
    }
    double to_compression = infinity;
    double to_end = infinity;
    if (compressing) {
      // u_n reaches 0 (only if it grows; at once if rounding at a slip's stop just overshot 0)
      to_compression = ratio(std::max(-u.x(), 0.0), v.x());
    } else {
      switch (law.restitution) {
        case RestitutionLaw::newton:  // the separation speed reaches its target
          to_end = ratio(std::max(newton_target - u.x(), 0.0), v.x());
          break;
        case RestitutionLaw::poisson:  // the normal impulse reaches e times compression's
          to_end = ratio(std::max(e * r.compression - P, 0.0), d.normal);
          break;
        case RestitutionLaw::energetic:  // restitution's work reaches its target
          to_end = to_work(std::max(work_target - r.work_restitution, 0.0), d.normal, u.x(), v.x());
          break;
      }
    }
    const double step = std::min({to_slip_stop, to_compression, to_end});
    if (!std::isfinite(step)) {
      r.status = ContactStatus::cannot_stop;
      break;
    }

    // Along the phase: u, the impulses and the works (exact: u is linear in the step).
    Eigen::Vector2d u_next = u + v * step;
    if (step == to_slip_stop) {
      u_next.y() = 0.0;
    }
    if (step == to_compression) {
      u_next.x() = 0.0;
    }
    if (step == to_end && law.restitution == RestitutionLaw::newton) {
      u_next.x() = newton_target;
    }
    const double work_normal = d.normal * step * (u.x() + u_next.x()) / 2.0;
    r.work_tangential += d.tangential * step * (u.y() + u_next.y()) / 2.0;
    (compressing ? r.work_compression : r.work_restitution) += work_normal;
    P += d.normal * step;
    Pt += d.tangential * step;
    u = u_next;

    if (step == to_slip_stop) {
      r.phase_list[r.phase_count++] = {regime, s, P, Pt, u};
      slip_can_stop = false;
      if (can_stick(W, mu)) {
        regime = Slip::stick;
        s = 0.0;
      } else {
        regime = Slip::reversed;
        s = -s;
      }
    }
    if (step == to_compression) {
      compressing = false;
      r.compression = P;
      work_target = (e - 1.0) * (e - 1.0) * -r.work_compression;
    }
    if (step == to_end) {
      if (law.restitution == RestitutionLaw::poisson) {
        P = e * r.compression;
      } else if (law.restitution == RestitutionLaw::energetic) {
        r.work_restitution = work_target;
      }
      r.phase_list[r.phase_count++] = {regime, s, P, Pt, u};
      finished = true;
    }
  }

  r.normal = P;
  r.tangential = Pt;
  r.u_after = u;
  r.outcome = regime;
  if (!all_finite(P, Pt, u.x(), u.y(), r.work_compression, r.work_restitution, r.work_tangential) &&
      r.status == ContactStatus::resolved) {
    r.status = ContactStatus::non_finite;
  }
  return r;
}

}  // namespace impulse::friction
