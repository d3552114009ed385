#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

#include "ridefit/model/quarter_car.h"

namespace ridefit::model {

// The continuous quarter-car parameters by their YAML key (design.md's names), in one table, so
// the fits and the diagnosis address a parameter by name and reach the same field for doubles
// and for Jets. tyre_lift_off and acc_sensor_order are switches, not parameters, and are not
// listed. The last three are the accelerometers' measuring chain (acceleration_sensors.h), not
// physics.
inline constexpr std::array<std::string_view, 27> kQuarterCarParameterNames{
    "sprung_mass_kg",
    "unsprung_mass_kg",
    "tyre_stiffness_N_per_m",
    "tyre_damping_Ns_per_m",
    "spring_stiffness_N_per_m",
    "top_mount_spring_path_stiffness_N_per_m",
    "top_mount_stiffness_N_per_m",
    "damping_Ns_per_m",
    "dahl_sigma0_N_per_m",
    "coulomb_force_N",
    "dahl_exponent",
    "compression_to_rebound_ratio",
    "top_mount_small_amplitude_stiffness_N_per_m",
    "top_mount_transition_deflection_m",
    "bump_stop_stiffness_N_per_m",
    "bump_stop_clearance_m",
    "bump_stop_exponent",
    "damper_knee_velocity_m_per_s",
    "damping_above_knee_Ns_per_m",
    "static_friction_force_N",
    "stribeck_velocity_m_per_s",
    "damping_per_command_Ns_per_m",
    "coulomb_force_per_command_N",
    "command_lag_s",
    "body_acc_gain",
    "wheel_acc_gain",
    "acc_sensor_cutoff_Hz"};

// Index of `name` in kQuarterCarParameterNames, or none.
inline std::optional<std::size_t> quarter_car_parameter_index(std::string_view name) {
  for (std::size_t i = 0; i < kQuarterCarParameterNames.size(); ++i) {
    if (kQuarterCarParameterNames[i] == name) return i;
  }
  return std::nullopt;
}

// The field of `p` named kQuarterCarParameterNames[index].
template <typename T>
T& quarter_car_parameter(QuarterCarParameters<T>& p, std::size_t index) {
  T* const fields[] = {&p.sprung_mass_kg,
                       &p.unsprung_mass_kg,
                       &p.tyre_stiffness_N_per_m,
                       &p.tyre_damping_Ns_per_m,
                       &p.spring_stiffness_N_per_m,
                       &p.top_mount_spring_path_stiffness_N_per_m,
                       &p.top_mount_stiffness_N_per_m,
                       &p.damping_Ns_per_m,
                       &p.dahl_sigma0_N_per_m,
                       &p.coulomb_force_N,
                       &p.dahl_exponent,
                       &p.compression_to_rebound_ratio,
                       &p.top_mount_small_amplitude_stiffness_N_per_m,
                       &p.top_mount_transition_deflection_m,
                       &p.bump_stop_stiffness_N_per_m,
                       &p.bump_stop_clearance_m,
                       &p.bump_stop_exponent,
                       &p.damper_knee_velocity_m_per_s,
                       &p.damping_above_knee_Ns_per_m,
                       &p.static_friction_force_N,
                       &p.stribeck_velocity_m_per_s,
                       &p.damping_per_command_Ns_per_m,
                       &p.coulomb_force_per_command_N,
                       &p.command_lag_s,
                       &p.sensors.body_acc_gain,
                       &p.sensors.wheel_acc_gain,
                       &p.sensors.acc_sensor_cutoff_Hz};
  static_assert(sizeof(fields) / sizeof(fields[0]) == kQuarterCarParameterNames.size());
  return *fields[index];
}

template <typename T>
const T& quarter_car_parameter(const QuarterCarParameters<T>& p, std::size_t index) {
  return quarter_car_parameter(const_cast<QuarterCarParameters<T>&>(p), index);
}

}  // namespace ridefit::model
