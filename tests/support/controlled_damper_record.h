#pragma once

#include <functional>
#include <random>
#include <string>

#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/model/strut_test.h"
#include "ridefit/synthetic/lab_truth.h"
#include "ridefit/synthetic/multisine.h"
#include "ridefit/synthetic/switching_command.h"
#include "support/cvode_rig_record.h"

namespace ridefit::testing {

// The library's random rig motion (40 sines over 0.5–20 Hz, about 4 mm RMS; synthetic/
// multisine.h), its phases from a generator of its own seeded with `seed`.
inline synthetic::Multisine random_rig_motion(unsigned seed, double scale = 1.0) {
  std::mt19937_64 rng(seed);
  return synthetic::random_rig_motion(rng, scale);
}

// The library's switching command (random levels in [0, top] held 0.15–0.5 s, smooth edges;
// synthetic/switching_command.h) from a generator of its own seeded with `seed`.
inline synthetic::SwitchingCommand switching_command(unsigned seed, double duration_s, double top) {
  std::mt19937_64 rng(seed);
  return synthetic::SwitchingCommand(duration_s, top, rng);
}

// A rig record of a controlled strut `p` under x(t) and command u(t), sampled at `rate_Hz` over
// [0, duration_s], the force by CVODE at rtol 1e-10 (cvode_rig_record).
inline fitting::HysteresisRecord cvode_controlled_record(
    const model::StrutTestParameters<double>& p, const std::function<double(double)>& x,
    const std::function<double(double)>& u, double duration_s, double rate_Hz,
    const std::string& source = "controlled") {
  return cvode_rig_record(p, x, duration_s, rate_Hz, source, u);
}

// The lab's MR-like strut (synthetic/lab_truth.h: passive c = 800 N·s/m, Fc = 40 N, rising with
// the current by 1500 N·s/m and 180 N per A, the fluid following the coil with τ = 12 ms) without
// the load cell's zero error.
inline model::StrutTestParameters<double> mr_strut() {
  model::StrutTestParameters<double> p = synthetic::lab_mr_strut();
  p.force_offset_N = 0.0;
  p.static_friction_force_N = 40.0;
  return p;
}

}  // namespace ridefit::testing
