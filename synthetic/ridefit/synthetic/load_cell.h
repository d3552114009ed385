#pragma once

#include <random>
#include <span>
#include <vector>

namespace ridefit::synthetic {

// What a rig's load cell adds to the true force: Gaussian noise, then (if quantum_N > 0) rounding
// to its resolution, e.g. a 16-bit converter over ±5 kN. Its zero error is the strut test's
// force_offset_N, part of the truth, not of this reading.
struct LoadCell {
  double noise_N = 0.0;    // standard deviation
  double quantum_N = 0.0;  // 0: not quantised
};

// The cell's reading of `force_N`: the noise drawn in sample order from `rng` (gaussian_noise.h),
// none drawn when noise_N is 0.
std::vector<double> read_load_cell(std::span<const double> force_N, const LoadCell& cell,
                                   std::mt19937_64& rng);

}  // namespace ridefit::synthetic
