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

/// |a - b| / max(|a|, |b|, scale): the relative disagreement of two values whose terms are of
/// size `scale` (pass the sum of the magnitudes that cancel). Comparing with an exact zero needs
/// a scale: without one, any non-zero value would be "100% off" (std::invalid_argument).
double relative_error(double a, double b, double scale = 0.0);

/// The worst relative error over a run of samples.
struct Errors {
  double worst = 0.0;
  std::size_t samples = 0;
  /// A value that is already a relative error.
  void add_relative(double error) {
    worst = std::max(worst, std::isnan(error) ? std::numeric_limits<double>::infinity() : error);
    ++samples;
  }
  /// Two values that should agree, compared relative to their size or `scale`.
  void add(double a, double b, double scale = 0.0) { add_relative(relative_error(a, b, scale)); }
};

/// How far "holds" and "fails" are apart for a numeric method.
inline constexpr double holds_below = 1e-9;  ///< worst relative error of a statement that holds
inline constexpr double fails_above = 1e-6;  ///< smallest worst error of one that does not

/// ∫_a^b f with GSL's adaptive Gauss–Kronrod (qag, 61 points), to a relative tolerance of 1e-12
/// or an absolute one of 1e-13 times `scale` (the size of the terms the integral is compared
/// with: a small result of large cancelling contributions is judged against those). Throws
/// std::runtime_error with GSL's message if it does not converge.
double integrate(const std::function<double(double)>& f, double a, double b, double scale = 0.0);

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

/// The minimiser of f in [lower, upper] by GSL's Brent method, started at `guess` (which must
/// lie below both ends), to a relative interval of 1e-10.
double minimise(const std::function<double(double)>& f, double lower, double upper, double guess);

/// Shortest text that reads back as the same double.
std::string number(double value);
/// A few significant digits, for notes ("1.2e-08").
std::string brief(double value, int digits = 3);

}  // namespace impulse::derivations::num
