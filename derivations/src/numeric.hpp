// SPDX-License-Identifier: GPL-3.0-or-later
// Numeric tools of the checks: GSL random numbers, error bookkeeping, quadrature and an ODE
// driver with event location. Every GSL call's status is checked (the error handler is off).
#pragma once

#include <gsl/gsl_integration.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_rng.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace impulse::derivations::num {

/// Turns GSL's abort-on-error handler off (once; checks read the statuses).
void quiet_gsl();

/// A seeded Mersenne twister (gsl_rng_mt19937).
class Random {
 public:
  explicit Random(std::uint64_t seed);
  double uniform(double low, double high);
  /// Spread evenly over the orders of magnitude between low and high (both > 0).
  double log_uniform(double low, double high);
  /// A mass or a moment of inertia, 1e-3 .. 1e3.
  double mass() { return log_uniform(1e-3, 1e3); }
  int integer(int low, int high);
  bool coin() { return integer(0, 1) == 1; }
  Eigen::Vector2d unit_vector();
  Eigen::Vector2d vector(double scale);

 private:
  std::unique_ptr<gsl_rng, void (*)(gsl_rng*)> rng_;
};

/// An ODE y' = f(t, y) integrated with GSL's rk8pd until an event function g(t, y) crosses
/// from positive to zero (located by bisection to `event_tolerance` in t).
struct OdeResult {
  double t = 0.0;
  std::vector<double> y;
  std::size_t steps = 0;
};
using OdeRhs = std::function<void(double t, const double* y, double* dydt)>;
using OdeEvent = std::function<double(double t, const double* y)>;
OdeResult integrate_until(const OdeRhs& rhs, std::vector<double> y0, const OdeEvent& event,
                          double initial_step, double t_max, double event_tolerance);

/// The states of an ODE y' = f(t, y), from y0 at t = 0, at each of the increasing @p times
/// (GSL's rk8pd, relative and absolute tolerance 1e-13).
std::vector<std::vector<double>> integrate_to(const OdeRhs& rhs, std::vector<double> y0,
                                              const std::vector<double>& times,
                                              double initial_step);

/// ∫_a^b of a function known at chosen points (an ODE's solution, sampled in one pass): the
/// 24-point Gauss–Legendre rule on each of @p pieces equal pieces. @p values returns the
/// function at the given increasing points.
double gauss_legendre(const std::function<std::vector<double>(const std::vector<double>&)>& values,
                      double a, double b, int pieces);

/// A few significant digits, for notes ("1.2e-08").
std::string brief(double value, int digits = 3);

/// Below this a relative residual is rounding: its digits follow the order in which a sum's
/// terms were added, which GiNaC takes from hashes that follow the program's layout in memory,
/// so they change from build to build (and from run to run with address-space randomisation).
inline constexpr double rounding_level = 1e-15;

/// A worst relative residual as a JSON report writes it: above 0 and below the rounding level,
/// the level itself (an upper bound), since the digits there change from run to run.
inline double reported_residual(double worst) {
  return worst > 0 && worst < rounding_level ? rounding_level : worst;
}

/// A worst relative residual as notes print it: two significant digits, or "below 1e-15" at
/// the level of rounding.
std::string residual_text(double worst);

}  // namespace impulse::derivations::num
