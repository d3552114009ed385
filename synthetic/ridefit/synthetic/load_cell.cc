#include "ridefit/synthetic/load_cell.h"

#include <cmath>

#include "ridefit/synthetic/gaussian_noise.h"

namespace ridefit::synthetic {

std::vector<double> read_load_cell(std::span<const double> force_N, const LoadCell& cell,
                                   std::mt19937_64& rng) {
  std::vector<double> reading = gaussian_noise(force_N.size(), cell.noise_N, rng);
  for (std::size_t k = 0; k < reading.size(); ++k) {
    reading[k] += force_N[k];
    if (cell.quantum_N > 0.0) reading[k] = std::round(reading[k] / cell.quantum_N) * cell.quantum_N;
  }
  return reading;
}

}  // namespace ridefit::synthetic
