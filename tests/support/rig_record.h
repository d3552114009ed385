#pragma once

#include <numbers>
#include <random>

#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/model/strut_test.h"
#include "ridefit/synthetic/load_cell.h"
#include "ridefit/synthetic/multisine.h"
#include "support/cvode_rig_record.h"

namespace ridefit::testing {

// A strut rig test with the hidden rig datasets' multisine (synthetic::lab_three_sines: 3, 1.5,
// 0.8 mm at 0.7, 2.3, 6.1 Hz): the force of `strut` itself plus seeded Gaussian noise of
// `noise_N`; `random_phases` draws the three phases from the same seed (another test of the same
// strut), else they are 0.
inline fitting::HysteresisRecord multisine_rig_record(
    const model::StrutTestParameters<double>& strut, double duration_s, double rate_Hz,
    double noise_N = 0.0, unsigned seed = 1, bool random_phases = false) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
  synthetic::Multisine x = synthetic::lab_three_sines();
  if (random_phases) {
    for (double& p : x.phase_rad) p = angle(rng);
  }
  // CVODE at rtol 1e-10 on the analytic multisine: not the solver the fits use.
  fitting::HysteresisRecord r =
      cvode_rig_record(strut, x, duration_s, rate_Hz, random_phases ? "judged" : "fitted");
  r.force_N = synthetic::read_load_cell(r.force_N, {noise_N, 0.0}, rng);
  return r;
}

}  // namespace ridefit::testing
