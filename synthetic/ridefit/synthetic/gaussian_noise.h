#pragma once

#include <cstddef>
#include <random>
#include <vector>

namespace ridefit::synthetic {

// n samples of zero-mean Gaussian white noise of standard deviation `sigma`, drawn in order from
// `rng` through one distribution (so a seed gives the same samples, and interleaved channels can
// share one draw of 2n). Its one-sided density at sample rate fs is 2σ²/fs. sigma = 0 gives zeros
// without touching `rng`; InputError for a negative or non-finite sigma.
std::vector<double> gaussian_noise(std::size_t n, double sigma, std::mt19937_64& rng);

}  // namespace ridefit::synthetic
