#include "ridefit/synthetic/gaussian_noise.h"

#include <fmt/core.h>

#include <cmath>

#include "ridefit/common/errors.h"

namespace ridefit::synthetic {

std::vector<double> gaussian_noise(std::size_t n, double sigma, std::mt19937_64& rng) {
  if (!(sigma >= 0.0) || !std::isfinite(sigma)) {
    throw InputError(fmt::format("noise standard deviation {:g}: give a finite value >= 0", sigma));
  }
  std::vector<double> x(n, 0.0);
  if (sigma == 0.0) return x;  // std::normal_distribution needs σ > 0
  std::normal_distribution<double> normal(0.0, sigma);
  for (double& v : x) v = normal(rng);
  return x;
}

}  // namespace ridefit::synthetic
