#pragma once

#include <vector>

#include "ridefit/simulate/integrator.h"

namespace ridefit::simulate {

struct SimulationOptions {
  double output_rate_Hz = 1000.0;
  double duration_s = 0.0;  // 0 = the road's duration
  IntegratorOptions integrator;
};

// Ten to twenty channels of 8 bytes each: 2e7 samples keep a run within a few GB.
constexpr double kMaxOutputSamples = 2e7;

// The output times 0, 1/rate, … up to the duration (the road's own when options.duration_s is
// 0). InputError for a rate or duration that cannot work: non-finite, not positive, longer
// than the road (`road_duration_s`), or more than kMaxOutputSamples samples.
std::vector<double> output_times(const SimulationOptions& options, double road_duration_s);

// Output samples faster than this resolve nothing the solvers compute for a vehicle.
inline constexpr double kMaxOutputRate_Hz = 1e5;

// An output rate against what a run of `duration_s` can give: at most kMaxOutputRate_Hz, and at
// least two samples. InputError whose message begins with the rate ("200000 Hz: ..."), so a
// caller can name where it came from. (rk4 with a step longer than the output interval is
// refused by the integrator itself.)
void check_output_rate(double rate_Hz, double duration_s);

}  // namespace ridefit::simulate
