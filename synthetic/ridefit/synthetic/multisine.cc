#include "ridefit/synthetic/multisine.h"

#include <cmath>
#include <numbers>

namespace ridefit::synthetic {

double Multisine::operator()(double time_s) const {
  double x = 0.0;
  for (std::size_t i = 0; i < amplitude_m.size(); ++i) {
    x +=
        amplitude_m[i] * std::sin(2.0 * std::numbers::pi * frequency_Hz[i] * time_s + phase_rad[i]);
  }
  return x;
}

Multisine lab_three_sines() { return {{0.003, 0.0015, 0.0008}, {0.7, 2.3, 6.1}, {0.0, 0.0, 0.0}}; }

Multisine random_rig_motion(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
  Multisine m;
  for (int i = 0; i < 40; ++i) {
    const double f = 0.5 * std::pow(40.0, i / 39.0);
    m.frequency_Hz.push_back(f);
    m.amplitude_m.push_back(scale * 0.0012 / f);
    m.phase_rad.push_back(angle(rng));
  }
  return m;
}

}  // namespace ridefit::synthetic
