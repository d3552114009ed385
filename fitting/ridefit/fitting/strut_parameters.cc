#include "ridefit/fitting/strut_parameters.h"

#include <fmt/core.h>

#include "ridefit/common/errors.h"

namespace ridefit::fitting {

std::size_t strut_parameter_index(std::string_view name) {
  std::string names;
  for (std::size_t i = 0; i < kStrutParameters.size(); ++i) {
    if (kStrutParameters[i].name() == name) return i;
    names += (names.empty() ? "" : ", ") + std::string(kStrutParameters[i].name());
  }
  throw InputError(
      fmt::format("'{}' is not a strut-test parameter; the parameters are: {}", name, names));
}

model::StrutTestParameters<double> with_strut_values(model::StrutTestParameters<double> p,
                                                     const std::map<std::string, double>& values) {
  for (const auto& [name, value] : values) {
    try {
      strut_parameter(p, strut_parameter_index(name)) = value;
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", name, e.what()));
    }
  }
  return p;
}

std::vector<std::pair<std::string, double>> model_file_values(
    const model::StrutTestParameters<double>& p, const std::vector<std::string>& names) {
  std::vector<std::pair<std::string, double>> values;
  for (const auto& name : names) {
    const std::size_t index = strut_parameter_index(name);
    if (kStrutParameters[index].in_model_file) values.emplace_back(name, strut_parameter(p, index));
  }
  return values;
}

model::StrutTestParameters<double> strut_on_rig(const model::QuarterCarParameters<double>& q) {
  model::StrutTestParameters<double> strut{q.dahl_sigma0_N_per_m,
                                           q.coulomb_force_N,
                                           q.dahl_exponent,
                                           q.top_mount_stiffness_N_per_m,
                                           q.damping_Ns_per_m,
                                           0.0,
                                           0.0,
                                           0.0,
                                           q.static_friction_force_N,
                                           q.stribeck_velocity_m_per_s,
                                           q.damping_per_command_Ns_per_m,
                                           q.coulomb_force_per_command_N,
                                           q.command_lag_s};
  strut.friction_compression_to_rebound_ratio = q.friction_compression_to_rebound_ratio;
  strut.free_play_m = q.free_play_m;
  strut.compression_to_rebound_ratio = q.compression_to_rebound_ratio;
  strut.damper_knee_velocity_m_per_s = q.damper_knee_velocity_m_per_s;
  strut.damping_above_knee_Ns_per_m = q.damping_above_knee_Ns_per_m;
  strut.top_mount_small_amplitude_stiffness_N_per_m = q.top_mount_small_amplitude_stiffness_N_per_m;
  strut.top_mount_transition_deflection_m = q.top_mount_transition_deflection_m;
  strut.command_exponent = q.command_exponent;
  return strut;
}

model::StrutTestParameters<double> strut_on_rig(const model::QuarterCar& car) {
  model::StrutTestParameters<double> strut = strut_on_rig(car.parameters());
  if (car.damper_state() == model::DamperState::kSlip) strut.coulomb_force_N = 0.0;
  return strut;
}

}  // namespace ridefit::fitting
