#pragma once

#include <string>
#include <vector>

#include "command_options.h"

namespace ridefit::cli {

// The flags of `ridefit simulate`, shared by the quarter-car and the half-car run.
struct SimulateFlags {
  std::string model_file;
  std::string excitation_file;
  std::string output_file;
  std::string damper_state;
  std::vector<std::string> overrides;
  double output_rate_Hz = 1000.0;
  double duration_s = 0.0;
  bool json = false;
  double rear_delay_s = -1.0;  // half car on a road given over time; < 0 = not given
  SolverFlags solver;
};

// `ridefit simulate` for a half-car model file (model: half_car).
void simulate_half_car(const SimulateFlags& flags);

}  // namespace ridefit::cli
