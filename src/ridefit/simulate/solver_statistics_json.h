#pragma once

#include <nlohmann/json.hpp>

#include "ridefit/simulate/integrator.h"

namespace ridefit::simulate {

// What the integrator did, for the JSON summaries of the commands that simulate.
nlohmann::json to_json(const SolverStatistics& statistics);

}  // namespace ridefit::simulate
