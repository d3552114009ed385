#pragma once

#include <vector>

#include "ridefit/model/quarter_car.h"
#include "ridefit/road/road_input.h"
#include "ridefit/simulate/integrator.h"
#include "ridefit/simulate/simulation_options.h"

namespace ridefit::simulate {

// Every output channel of a quarter-car run, sampled at a fixed rate (SI units).
struct QuarterCarResponse {
  std::vector<double> time_s;
  std::vector<double> road_m;
  std::vector<double> body_acc_m_per_s2;
  std::vector<double> wheel_acc_m_per_s2;
  std::vector<double> travel_m;
  std::vector<double> tyre_force_N;
  std::vector<double> damper_force_N;
  std::vector<double> friction_force_N;
  std::vector<double> top_mount_deflection_m;
  std::vector<double> stuck;
  // The filtered command ū the damper followed (the road's unit); empty unless the car follows a
  // command (QuarterCar::follows_command).
  std::vector<double> damper_command;
  SolverStatistics statistics;
};

// Runs the car from static equilibrium at rest over the road and samples every channel at
// output_rate_Hz (the integrator's dense output gives the states there; accelerations
// come from the model at those states). Throws RunError on solver failure and InputError
// for a rate or duration that cannot work (non-finite, longer than the road, or more than
// kMaxOutputSamples samples).
QuarterCarResponse simulate(const model::QuarterCar& car, const road::RoadInput& road,
                            const SimulationOptions& options);

}  // namespace ridefit::simulate
