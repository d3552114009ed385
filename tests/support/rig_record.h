#pragma once

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/model/strut_test.h"
#include "support/cvode_rig_record.h"

namespace ridefit::testing {

// A strut rig test with the hidden rig datasets' multisine (3, 1.5, 0.8 mm at 0.7, 2.3, 6.1 Hz):
// the force of `strut` itself plus seeded Gaussian noise of `noise_N`; `random_phases` draws
// the three phases from the same seed (another test of the same strut), else they are 0.
inline fitting::HysteresisRecord multisine_rig_record(
    const model::StrutTestParameters<double>& strut, double duration_s, double rate_Hz,
    double noise_N = 0.0, unsigned seed = 1, bool random_phases = false) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
  std::normal_distribution<double> noise(0.0, noise_N > 0.0 ? noise_N : 1.0);
  double phase[3] = {0.0, 0.0, 0.0};
  if (random_phases) {
    for (double& p : phase) p = angle(rng);
  }
  fitting::HysteresisRecord r;
  r.source = random_phases ? "judged" : "fitted";
  const auto samples = static_cast<int>(std::lround(duration_s * rate_Hz));
  for (int k = 0; k <= samples; ++k) {
    const double t = k / rate_Hz, w = 2.0 * std::numbers::pi;
    r.time_s.push_back(t);
    r.displacement_m.push_back(0.003 * std::sin(w * 0.7 * t + phase[0]) +
                               0.0015 * std::sin(w * 2.3 * t + phase[1]) +
                               0.0008 * std::sin(w * 6.1 * t + phase[2]));
  }
  // CVODE at rtol 1e-10 on the analytic multisine: not the solver the fits use.
  r.force_N = cvode_rig_force(
      r.time_s,
      [&phase](double t) {
        const double w = 2.0 * std::numbers::pi;
        return 0.003 * std::sin(w * 0.7 * t + phase[0]) +
               0.0015 * std::sin(w * 2.3 * t + phase[1]) +
               0.0008 * std::sin(w * 6.1 * t + phase[2]);
      },
      strut);
  if (noise_N > 0.0) {
    for (double& f : r.force_N) f += noise(rng);
  }
  return r;
}

}  // namespace ridefit::testing
