#pragma once

#include <cstddef>
#include <random>
#include <vector>

namespace ridefit::testing {

// n samples of zero-mean Gaussian white noise with standard deviation sigma, from `rng` (seed
// it in the test): its one-sided density at sample rate fs is 2σ²/fs.
inline std::vector<double> white_noise(std::size_t n, double sigma, std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, sigma);
  std::vector<double> x(n);
  for (double& v : x) v = normal(rng);
  return x;
}

}  // namespace ridefit::testing
