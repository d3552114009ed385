#pragma once

#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>
#include <vector>

namespace ridefit::bench {

// A body- or seat-acceleration-like record for benchmarks: a 1.2 Hz sine on seeded white
// noise (σ = 0.5), duration_s at sample_rate_Hz.
inline std::vector<double> sine_on_noise(double duration_s, double sample_rate_Hz) {
  const auto n = static_cast<std::size_t>(duration_s * sample_rate_Hz);
  std::mt19937_64 rng(42);
  std::normal_distribution<double> noise(0.0, 0.5);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / sample_rate_Hz;
    x[i] = std::sin(2.0 * std::numbers::pi * 1.2 * t) + noise(rng);
  }
  return x;
}

}  // namespace ridefit::bench
