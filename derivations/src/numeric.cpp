// SPDX-License-Identifier: GPL-3.0-or-later
#include "numeric.hpp"

#include <gsl/gsl_errno.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

namespace impulse::derivations::num {

void quiet_gsl() {
  static const bool once = [] {
    gsl_set_error_handler_off();
    return true;
  }();
  (void)once;
}

Random::Random(std::uint64_t seed) : rng_(gsl_rng_alloc(gsl_rng_mt19937), gsl_rng_free) {
  if (!rng_) {
    throw std::runtime_error("gsl_rng_alloc failed");
  }
  // gsl_rng_set takes an unsigned long; fold the 64 bits so every bit of the seed counts.
  gsl_rng_set(rng_.get(), static_cast<unsigned long>(seed ^ (seed >> 32)));
}

double Random::uniform(double low, double high) {
  return low + (high - low) * gsl_rng_uniform(rng_.get());
}

double Random::log_uniform(double low, double high) {
  return std::exp(uniform(std::log(low), std::log(high)));
}

int Random::integer(int low, int high) {
  const auto span = static_cast<unsigned long>(high - low + 1);
  return low + static_cast<int>(gsl_rng_uniform_int(rng_.get(), span));
}

Eigen::Vector2d Random::unit_vector() {
  const double angle = uniform(0.0, 2.0 * std::numbers::pi);
  return {std::cos(angle), std::sin(angle)};
}

Eigen::Vector2d Random::vector(double scale) {
  return {uniform(-scale, scale), uniform(-scale, scale)};
}

namespace {

// GSL's rk8pd driver of y' = rhs(t, y), relative and absolute tolerance 1e-13. The system it
// points at lives with it: the driver keeps a pointer to it.
class OdeDriver {
 public:
  OdeDriver(const OdeRhs& rhs, std::size_t dimension, double initial_step)
      : system_{[](double t, const double y[], double dydt[], void* params) -> int {
                  (*static_cast<const OdeRhs*>(params))(t, y, dydt);
                  return GSL_SUCCESS;
                },
                nullptr, dimension, const_cast<OdeRhs*>(&rhs)},
        driver_(nullptr, gsl_odeiv2_driver_free) {
    quiet_gsl();
    driver_.reset(
        gsl_odeiv2_driver_alloc_y_new(&system_, gsl_odeiv2_step_rk8pd, initial_step, 1e-13, 1e-13));
    if (!driver_) {
      throw std::runtime_error("gsl_odeiv2_driver_alloc_y_new failed");
    }
  }
  OdeDriver(const OdeDriver&) = delete;
  OdeDriver& operator=(const OdeDriver&) = delete;

  // From t to @p to, y in place; throws when GSL fails.
  void apply(double& t, double to, std::vector<double>& y) {
    const int status = gsl_odeiv2_driver_apply(driver_.get(), &t, to, y.data());
    if (status != GSL_SUCCESS) {
      throw std::runtime_error(std::string("ODE integration failed: ") + gsl_strerror(status));
    }
  }

  void reset() { gsl_odeiv2_driver_reset(driver_.get()); }

 private:
  gsl_odeiv2_system system_;
  std::unique_ptr<gsl_odeiv2_driver, void (*)(gsl_odeiv2_driver*)> driver_;
};

}  // namespace

std::vector<std::vector<double>> integrate_to(const OdeRhs& rhs, std::vector<double> y0,
                                              const std::vector<double>& times,
                                              double initial_step) {
  OdeDriver driver(rhs, y0.size(), initial_step);
  std::vector<std::vector<double>> states;
  double t = 0.0;
  for (const double next : times) {
    if (next > t) {
      driver.apply(t, next, y0);
    }
    states.push_back(y0);
  }
  return states;
}

double gauss_legendre(const std::function<std::vector<double>(const std::vector<double>&)>& values,
                      double a, double b, int pieces) {
  static const std::unique_ptr<gsl_integration_glfixed_table,
                               void (*)(gsl_integration_glfixed_table*)>
      table(gsl_integration_glfixed_table_alloc(24), gsl_integration_glfixed_table_free);
  std::vector<double> points;
  std::vector<double> weights;
  for (int piece = 0; piece < pieces; ++piece) {
    const double lo = a + (b - a) * piece / pieces;
    const double hi = a + (b - a) * (piece + 1) / pieces;
    for (std::size_t k = 0; k < table->n; ++k) {
      double x = 0.0;
      double w = 0.0;
      gsl_integration_glfixed_point(lo, hi, k, &x, &w, table.get());
      points.push_back(x);
      weights.push_back(w);
    }
  }
  // The points of a piece are not in increasing order: sort them, keeping their weights.
  std::vector<std::size_t> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    order[i] = i;
  }
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return points[i] < points[j]; });
  std::vector<double> sorted;
  for (const std::size_t i : order) {
    sorted.push_back(points[i]);
  }
  const std::vector<double> f = values(sorted);
  double sum = 0.0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    sum += weights[order[k]] * f[k];
  }
  return sum;
}

OdeResult integrate_until(const OdeRhs& rhs, std::vector<double> y0, const OdeEvent& event,
                          double initial_step, double t_max, double event_tolerance) {
  OdeDriver driver(rhs, y0.size(), initial_step);
  OdeResult result;
  double t = 0.0;
  std::vector<double> y = std::move(y0);
  // March in output intervals of the initial step; when the event turns non-positive, bisect
  // the last interval by re-integrating from its start.
  const double interval = initial_step;
  while (t < t_max) {
    const std::vector<double> saved = y;
    const double t_saved = t;
    driver.apply(t, t + interval, y);
    ++result.steps;
    if (event(t, y.data()) <= 0.0) {
      double low = t_saved;
      double high = t;
      std::vector<double> y_low = saved;
      while (high - low > event_tolerance) {
        const double mid = 0.5 * (low + high);
        std::vector<double> y_mid = y_low;
        double t_mid = low;
        driver.reset();
        driver.apply(t_mid, mid, y_mid);
        if (event(mid, y_mid.data()) > 0.0) {
          low = mid;
          y_low = y_mid;
        } else {
          high = mid;
        }
      }
      result.t = low;
      result.y = y_low;
      return result;
    }
  }
  throw std::runtime_error("ODE integration: the event did not occur before t = " + brief(t_max));
}

std::string brief(double value, int digits) {
  std::array<char, 32> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.*g", digits, value);
  return buffer.data();
}

std::string residual_text(double worst) {
  return worst < rounding_level ? "below " + brief(rounding_level, 2) : brief(worst, 2);
}

}  // namespace impulse::derivations::num
