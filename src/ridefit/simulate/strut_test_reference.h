#pragma once

#include <functional>
#include <span>
#include <vector>

#include "ridefit/model/strut_test.h"

namespace ridefit::simulate {

// Reference rig forces: the strut-test model (StrutTestSystem) under a displacement known at
// every instant, integrated by CVODE at rtol 1e-10 (a tenth of a nanometre on z_c, nanonewtons
// on F_f), started at rest (z_c = x(t₀), F_f = 0). The data the generators write and the tests
// fit are made this way: by another integrator than the adaptive ESDIRK that `fit` and
// `diagnose` run, and without sampling the displacement, so a fit measures the model and not its
// own discretisation. A controlled damper reads `command` (empty: a command of 0), also known at
// every instant. The inertia of the mass the load cell carries is m times a central second
// difference of the exact displacement. The load cell's chain (gain, delay, low-pass) is applied
// by its own closed forms here, not by apply_force_sensor: the delay by evaluating the force at
// t − δ from a dense solution, the low-pass by integrating the filter's states alongside the
// strut's. RunError when CVODE fails.
std::vector<double> reference_strut_test_force(std::span<const double> time_s,
                                               const std::function<double(double)>& displacement_m,
                                               const model::StrutTestParameters<double>& parameters,
                                               const std::function<double(double)>& command = {});

}  // namespace ridefit::simulate
