#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "ridefit/model/half_car.h"
#include "ridefit/road/road_input.h"
#include "ridefit/simulate/integrator.h"
#include "ridefit/simulate/simulation_options.h"

namespace ridefit::simulate {

// A half-car run sampled at a fixed rate: every output of the model at each output time.
struct HalfCarResponse {
  std::vector<double> time_s;
  std::vector<model::HalfCarOutputs> samples;
  double rear_delay_s = 0.0;
  SolverStatistics statistics;

  // One channel over time, e.g. channel(&model::HalfCarOutputs::seat_acc_m_per_s2).
  std::vector<double> channel(double model::HalfCarOutputs::*member) const;
};

struct HalfCarSimulationOptions : SimulationOptions {
  // For roads given over time; roads driven at a speed delay the rear by wheelbase/speed.
  std::optional<double> rear_delay_s;
  // How a message asking for the delay names it (the CLI gives its flag); a string that
  // outlives the options, such as a literal.
  std::string_view rear_delay_name = "rear_delay_s";
};

// Runs the car from static equilibrium at rest over the road (front wheel) and its delayed
// copy (rear wheel). RunError on solver failure, InputError for options that cannot work.
HalfCarResponse simulate(const model::HalfCar& car, const road::RoadInput& road,
                         const HalfCarSimulationOptions& options);

}  // namespace ridefit::simulate
