#pragma once

#include <random>
#include <vector>

namespace ridefit::synthetic {

// A sum of sines x(t) = Σ aᵢ·sin(2π·fᵢ·t + φᵢ), known at every instant: a rig displacement history
// that the reference integrator follows exactly (no sampled input to interpolate).
struct Multisine {
  std::vector<double> amplitude_m;
  std::vector<double> frequency_Hz;
  std::vector<double> phase_rad;  // one per sine

  double operator()(double time_s) const;
};

// The lab's dynamic history: 3, 1.5 and 0.8 mm at 0.7, 2.3 and 6.1 Hz, in sine phase (damper
// speeds up to about 60 mm/s).
Multisine lab_three_sines();

// A random rig motion: 40 sines log-spaced over 0.5–20 Hz, amplitudes falling as 1/f (about
// 4 mm RMS at `scale` 1), phases uniform in [0, 2π) drawn from `rng`, one per sine in order.
Multisine random_rig_motion(std::mt19937_64& rng, double scale = 1.0);

}  // namespace ridefit::synthetic
