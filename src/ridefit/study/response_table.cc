#include "ridefit/study/response_table.h"

#include <tuple>
#include <vector>

namespace ridefit::study {

io::CsvTable response_table(const simulate::QuarterCarResponse& r,
                            const std::string& command_unit) {
  io::CsvTable table;
  table.add("time", "s", r.time_s);
  table.add("road", "m", r.road_m);
  table.add("body_acc", "m/s^2", r.body_acc_m_per_s2);
  table.add("wheel_acc", "m/s^2", r.wheel_acc_m_per_s2);
  table.add("travel", "m", r.travel_m);
  table.add("tyre_force", "N", r.tyre_force_N);
  table.add("damper_force", "N", r.damper_force_N);
  table.add("friction_force", "N", r.friction_force_N);
  table.add("top_mount_deflection", "m", r.top_mount_deflection_m);
  table.add("stuck", "1", r.stuck);
  if (!r.damper_command.empty()) table.add("damper_command", command_unit, r.damper_command);
  return table;
}

io::CsvTable response_table(const simulate::HalfCarResponse& r) {
  using O = model::HalfCarOutputs;
  io::CsvTable table;
  table.add("time", "s", r.time_s);
  const std::vector<std::tuple<const char*, const char*, double O::*>> channels = {
      {"road_front", "m", &O::front_road_m},
      {"road_rear", "m", &O::rear_road_m},
      {"body_acc", "m/s^2", &O::body_acc_m_per_s2},
      {"pitch_acc", "rad/s^2", &O::pitch_acc_rad_per_s2},
      {"seat_acc", "m/s^2", &O::seat_acc_m_per_s2},
      {"lower_body_acc", "m/s^2", &O::lower_body_acc_m_per_s2},
      {"upper_body_acc", "m/s^2", &O::upper_body_acc_m_per_s2},
      {"front_wheel_acc", "m/s^2", &O::front_wheel_acc_m_per_s2},
      {"rear_wheel_acc", "m/s^2", &O::rear_wheel_acc_m_per_s2},
      {"front_travel", "m", &O::front_travel_m},
      {"rear_travel", "m", &O::rear_travel_m},
      {"front_tyre_force", "N", &O::front_tyre_force_N},
      {"rear_tyre_force", "N", &O::rear_tyre_force_N},
      {"front_damper_force", "N", &O::front_damper_force_N},
      {"rear_damper_force", "N", &O::rear_damper_force_N},
      {"front_friction_force", "N", &O::front_friction_force_N},
      {"rear_friction_force", "N", &O::rear_friction_force_N},
      {"front_damping", "Ns/m", &O::front_damping_Ns_per_m},
      {"rear_damping", "Ns/m", &O::rear_damping_Ns_per_m},
      {"front_stuck", "1", &O::front_stuck},
      {"rear_stuck", "1", &O::rear_stuck}};
  for (const auto& [name, unit, member] : channels) table.add(name, unit, r.channel(member));
  return table;
}

}  // namespace ridefit::study
