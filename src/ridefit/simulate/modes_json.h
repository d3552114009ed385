#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ridefit/simulate/half_car_modes.h"

namespace ridefit::simulate {

// The modes of a model in each state, as `ridefit modes --json` prints them and Python's modes()
// returns them: {"model", "states": {STATE: {"modes": [...], "first_order": [...]}}}.
nlohmann::json modes_json(const std::string& model_name, const std::vector<StateModes>& states);

}  // namespace ridefit::simulate
