#include "ridefit/fitting/diagnose/model_changes.h"

#include <fmt/core.h>

#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::fitting::diagnose {
namespace {

std::string value_text(double v) { return fmt::format("{:.6g}", v); }

}  // namespace

std::vector<std::pair<std::string, std::string>> changed_model_values(
    const model::QuarterCar& before, const model::QuarterCar& after) {
  std::vector<std::pair<std::string, std::string>> values;
  if (before.damper_state() != after.damper_state()) {
    values.emplace_back("damper_state", model::to_string(after.damper_state()));
  }
  for (std::size_t i = 0; i < model::kQuarterCarParameters.size(); ++i) {
    const double a = model::quarter_car_parameter(before.parameters(), i);
    const double b = model::quarter_car_parameter(after.parameters(), i);
    if (a != b) {
      values.emplace_back(std::string(model::kQuarterCarParameters[i].key), value_text(b));
    }
  }
  if (before.parameters().tyre_lift_off != after.parameters().tyre_lift_off) {
    values.emplace_back("tyre_lift_off", after.parameters().tyre_lift_off ? "true" : "false");
  }
  if (before.parameters().sensors.acc_sensor_order != after.parameters().sensors.acc_sensor_order) {
    values.emplace_back("acc_sensor_order",
                        std::to_string(after.parameters().sensors.acc_sensor_order));
  }
  return values;
}

StrutChanges changed_strut_values(const model::StrutTestParameters<double>& before,
                                  const model::StrutTestParameters<double>& after) {
  StrutChanges changes;
  for (std::size_t i = 0; i < kStrutParameters.size(); ++i) {
    const double old_value = strut_parameter(before, i);
    const double new_value = strut_parameter(after, i);
    if (old_value == new_value) continue;
    const std::string name(kStrutParameters[i].name());
    if (kStrutParameters[i].in_model_file) {
      changes.model_values.emplace_back(name, value_text(new_value));
    } else {
      changes.rig_only += fmt::format("{}{}: {}", changes.rig_only.empty() ? "" : ", ", name,
                                      value_text(new_value));
    }
  }
  return changes;
}

}  // namespace ridefit::fitting::diagnose
