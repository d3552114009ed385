#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/model/strut_test.h"
#include "ridefit/simulate/strut_test_reference.h"

namespace ridefit::testing {

// The rig force of a strut under an analytic displacement x(t), integrated by CVODE at rtol
// 1e-10 (simulate::reference_strut_test_force): data made by another integrator than the one the
// fits and the strut solver use (ridefit's ESDIRK), and without sampling the displacement, so a
// test that fits or compares against it measures the scheme under test.
template <typename Displacement>
std::vector<double> cvode_rig_force(const std::vector<double>& time_s, Displacement x,
                                    const model::StrutTestParameters<double>& p) {
  return simulate::reference_strut_test_force(
      time_s, [&x](double t) { return static_cast<double>(x(t)); }, p);
}

// The rig tests' multisine: 3, 1.5 and 0.8 mm at 0.7, 2.3 and 6.1 Hz, with optional phases.
struct ThreeSines {
  double phase_rad[3] = {0.0, 0.0, 0.0};
  double operator()(double t) const {
    const double w = 2.0 * 3.14159265358979323846;
    return 0.003 * std::sin(w * 0.7 * t + phase_rad[0]) +
           0.0015 * std::sin(w * 2.3 * t + phase_rad[1]) +
           0.0008 * std::sin(w * 6.1 * t + phase_rad[2]);
  }
};

// A rig record of `p` under x(t) sampled at `rate_Hz` over [0, duration_s], its force by
// cvode_rig_force (noise-free).
template <typename Displacement>
fitting::HysteresisRecord cvode_rig_record(const model::StrutTestParameters<double>& p,
                                           const Displacement& x, double duration_s, double rate_Hz,
                                           const std::string& source) {
  fitting::HysteresisRecord r;
  r.source = source;
  const auto samples = static_cast<int>(std::lround(duration_s * rate_Hz));
  for (int k = 0; k <= samples; ++k) {
    r.time_s.push_back(k / rate_Hz);
    r.displacement_m.push_back(x(r.time_s.back()));
  }
  r.force_N = cvode_rig_force(r.time_s, x, p);
  return r;
}

}  // namespace ridefit::testing
