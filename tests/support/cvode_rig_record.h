#pragma once

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/model/strut_test.h"
#include "ridefit/simulate/strut_test_reference.h"
#include "ridefit/synthetic/reference_rig_record.h"

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

// A rig record of `p` under x(t) (and a controlled damper's command u(t), in A) sampled at
// `rate_Hz` over [0, duration_s], its force by CVODE (synthetic/reference_rig_record.h),
// noise-free.
inline fitting::HysteresisRecord cvode_rig_record(const model::StrutTestParameters<double>& p,
                                                  const std::function<double(double)>& x,
                                                  double duration_s, double rate_Hz,
                                                  const std::string& source,
                                                  const std::function<double(double)>& u = {}) {
  const auto samples = static_cast<std::size_t>(std::lround(duration_s * rate_Hz)) + 1;
  return synthetic::reference_rig_record(synthetic::sample_times(samples, rate_Hz), x, p, u,
                                         source);
}

}  // namespace ridefit::testing
