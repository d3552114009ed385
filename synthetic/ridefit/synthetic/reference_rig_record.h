#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/model/strut_test.h"

namespace ridefit::synthetic {

// `samples` instants k / rate_Hz, k = 0, 1, ...: the grid of a rig record.
std::vector<double> sample_times(std::size_t samples, double rate_Hz);

// A noise-free rig record of `strut` under a displacement (and a controlled damper's command, in
// A) known at every instant: both sampled at `time_s`, the force by CVODE at rtol 1e-10
// (simulate::reference_strut_test_force). Another integrator than the ESDIRK that `fit` and
// `diagnose` run, and no sampled input, so a fit to it measures the model, not its own
// discretisation. RunError when CVODE fails.
fitting::HysteresisRecord reference_rig_record(std::vector<double> time_s,
                                               const std::function<double(double)>& displacement_m,
                                               const model::StrutTestParameters<double>& strut,
                                               const std::function<double(double)>& command = {},
                                               const std::string& source = "synthetic");

}  // namespace ridefit::synthetic
