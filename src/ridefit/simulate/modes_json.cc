#include "ridefit/simulate/modes_json.h"

namespace ridefit::simulate {

nlohmann::json modes_json(const std::string& model_name, const std::vector<StateModes>& states) {
  nlohmann::json summary = {{"model", model_name}, {"states", nlohmann::json::object()}};
  for (const auto& [state, modes] : states) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& mode : modes.oscillatory) {
      list.push_back({{"mode", mode.dominant_dof},
                      {"natural_frequency_Hz", mode.natural_frequency_Hz},
                      {"damped_frequency_Hz", mode.damped_frequency_Hz},
                      {"damping_ratio", mode.damping_ratio},
                      {"energy_share", mode.energy_share}});
    }
    nlohmann::json first_order = nlohmann::json::array();
    for (const auto& mode : modes.real) {
      first_order.push_back(
          {{"eigenvalue_per_s", mode.eigenvalue_per_s}, {"time_constant_s", mode.time_constant_s}});
    }
    summary["states"][state] = {{"modes", list}, {"first_order", first_order}};
  }
  return summary;
}

}  // namespace ridefit::simulate
