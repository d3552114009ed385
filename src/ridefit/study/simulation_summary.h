#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

#include "ridefit/model/quarter_car.h"
#include "ridefit/simulate/half_car_simulation.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "ridefit/study/half_car_metrics.h"

namespace ridefit::study {

// What a simulation was given and what it took, for its summary.
struct SimulationRun {
  std::string model_file;
  std::string excitation_file;
  std::string output_file;  // "" when no CSV was written
  double output_rate_Hz = 0.0;
  double wall_time_s = 0.0;
};

// A quarter-car run in a line (damper state, samples, solver steps, body and wheel RMS, the
// share of time stuck) and as JSON (also the travel peak and the RMS of travel, tyre and
// friction force).
std::string summary_text(const SimulationRun& run, const model::QuarterCar& car,
                         const simulate::QuarterCarResponse& response);
nlohmann::json summary_json(const SimulationRun& run, const model::QuarterCar& car,
                            const simulate::QuarterCarResponse& response);

// A half-car run: samples, solver steps and rear delay, and seed 001's ride figures where
// `metrics` were computed (the output rate must carry the ISO 2631-1 weightings).
std::string summary_text(const SimulationRun& run, const simulate::HalfCarResponse& response,
                         const std::optional<HalfCarMetrics>& metrics);
nlohmann::json summary_json(const SimulationRun& run, const simulate::HalfCarResponse& response,
                            const std::optional<HalfCarMetrics>& metrics);

}  // namespace ridefit::study
