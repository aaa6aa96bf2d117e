// SPDX-License-Identifier: GPL-3.0-or-later
// Reproducible random configurations for the property tests.
//
// Every generator is seeded from Catch2's --rng-seed and a per-test salt, so a failure replays
// with the seed Catch prints; each test CAPTUREs its inputs.
#pragma once

#include <Eigen/Core>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>
#include <string_view>

namespace impulse::test {

/// How many random configurations each property is checked on.
/// 1,000 in optimised builds (the figure); 100 in a Debug build (the asan preset),
/// where unoptimised Eigen is about a hundred times slower and the sanitizers, not the count of
/// samples, are the point of the run.
#ifdef NDEBUG
inline constexpr int configurations = 1000;
#else
inline constexpr int configurations = 100;
#endif

class Sampler {
 public:
  explicit Sampler(std::string_view salt)
      : engine_(static_cast<std::uint64_t>(Catch::rngSeed()) * 0x9E3779B97F4A7C15ULL ^
                std::hash<std::string_view>{}(salt)) {}

  double uniform(double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(engine_);
  }
  /// Spread evenly over the orders of magnitude between low and high (both > 0).
  double log_uniform(double low, double high) {
    return std::exp(uniform(std::log(low), std::log(high)));
  }
  /// A mass or moment of inertia spanning 1e-3 .. 1e3.
  double mass() { return log_uniform(1e-3, 1e3); }
  int integer(int low, int high) { return std::uniform_int_distribution<int>(low, high)(engine_); }
  bool coin() { return integer(0, 1) == 1; }
  Eigen::Vector2d unit_vector() {
    const double angle = uniform(0.0, 2.0 * std::numbers::pi);
    return {std::cos(angle), std::sin(angle)};
  }
  Eigen::Vector2d vector(double scale) { return {uniform(-scale, scale), uniform(-scale, scale)}; }

 private:
  std::mt19937_64 engine_;
};

/// |a - b| / scale, the error measure of the property tests.
inline double relative_error(double a, double b, double scale) {
  return std::abs(a - b) / scale;
}

/// Keeps the worst error a property test saw; prints it at the end of the test when the
/// environment variable IMPULSELAB_REPORT_WORST is set (the figures of the issue notes).
class Worst {
 public:
  explicit Worst(std::string name) : name_(std::move(name)) {}
  Worst(const Worst&) = delete;
  Worst& operator=(const Worst&) = delete;
  ~Worst() {
    if (std::getenv("IMPULSELAB_REPORT_WORST") != nullptr) {
      std::fprintf(stderr, "worst %-48s %.3e\n", name_.c_str(), value_);
    }
  }
  void see(double error) { value_ = std::max(value_, error); }

 private:
  std::string name_;
  double value_ = 0.0;
};

}  // namespace impulse::test
