#pragma once

#include <vector>

#include "ridefit/model/strut_test.h"
#include "ridefit/road/rig_test.h"
#include "ridefit/simulate/strut_test_response.h"

namespace ridefit::simulate {

// A rig test run on a strut model: what the rig would record (the load cell's reading of the
// strut's force, its chain and offset included) at the test's samples.
struct RigTestRecord {
  std::vector<double> time_s;
  std::vector<double> displacement_m;
  std::vector<double> velocity_m_per_s;  // the actuator's, exact (a rig's LVDT rate channel)
  std::vector<double> force_N;
  // The motion's peaks and fastest frequency (road::RigMotion), and the force's.
  double peak_displacement_m = 0.0;
  double peak_velocity_m_per_s = 0.0;
  double highest_frequency_Hz = 0.0;
  double peak_force_N = 0.0;  // the largest |force|
  double peak_time_s = 0.0;   // where it is
};

// Runs `test` (validated against `limits`) on `strut` with ridefit's own strut solver, driven by
// the exact displacement and velocity at the samples (straight lines between samples for a
// triangle, whose corners a spline would round). InputError when the test breaks a limit, when
// the force it needs exceeds the rig's (limits.force_N, with the peak and its time), or when the
// model cannot be solved on it.
RigTestRecord simulate_rig_test(const model::StrutTestParameters<double>& strut,
                                const road::RigTest& test, const road::RigLimits& limits = {},
                                const StrutTestSolverOptions& solver = {});

}  // namespace ridefit::simulate
