#include "ridefit/model/quarter_car_parameter_table.h"

#include <fmt/core.h>

namespace ridefit::model {
namespace {

namespace rows = quarter_car_rows;

// `a` and `b` switch one effect on together (> 0) or leave it off (0).
std::optional<ParameterError> together(const ParameterInfo& a, double va, const ParameterInfo& b,
                                       double vb, std::string_view prefix) {
  if ((va > 0.0) == (vb > 0.0)) return std::nullopt;
  const ParameterInfo& set = va > 0.0 ? a : b;
  const ParameterInfo& missing = va > 0.0 ? b : a;
  return ParameterError{fmt::format("{}{}", prefix, set.key),
                        fmt::format("needs '{}{}' > 0 as well ({}); both or neither", prefix,
                                    missing.key, missing.meaning)};
}

}  // namespace

std::optional<ParameterError> validate_strut(const StrutParameters<double>& p,
                                             std::string_view prefix, bool passive_damper) {
  auto key = [&](const ParameterInfo& row) { return fmt::format("{}{}", prefix, row.key); };
  for (std::size_t i = 0; i < kStrutRows.size(); ++i) {
    const ParameterInfo& row = kQuarterCarParameters[kStrutRows[i]];
    const double v = strut_field(const_cast<StrutParameters<double>&>(p), i);
    if (passive_damper && &row == &rows::damping_Ns_per_m && v == 0.0) continue;
    if (auto error = check_range(row, v, key(row))) return error;
  }
  constexpr auto& k_s = rows::top_mount_small_amplitude_stiffness_N_per_m;
  constexpr auto& delta0 = rows::top_mount_transition_deflection_m;
  constexpr auto& k_l = rows::top_mount_stiffness_N_per_m;
  if (auto error = together(k_s, p.top_mount_small_amplitude_stiffness_N_per_m, delta0,
                            p.top_mount_transition_deflection_m, prefix)) {
    return error;
  }
  if (p.top_mount_transition_deflection_m > 0.0 &&
      p.top_mount_small_amplitude_stiffness_N_per_m < p.top_mount_stiffness_N_per_m) {
    return ParameterError{key(k_s), fmt::format("is {}, expected at least '{}' {} (the "
                                                "large-amplitude stiffness)",
                                                p.top_mount_small_amplitude_stiffness_N_per_m,
                                                key(k_l), p.top_mount_stiffness_N_per_m)};
  }
  constexpr auto& c_h = rows::damping_above_knee_Ns_per_m;
  if (auto error = together(rows::damper_knee_velocity_m_per_s, p.damper_knee_velocity_m_per_s, c_h,
                            p.damping_above_knee_Ns_per_m, prefix)) {
    return error;
  }
  if (p.damping_above_knee_Ns_per_m > p.damping_Ns_per_m) {
    return ParameterError{
        key(c_h),
        fmt::format("is {}, expected a value <= {} (at most '{}': the knee is digressive)",
                    p.damping_above_knee_Ns_per_m, p.damping_Ns_per_m,
                    key(rows::damping_Ns_per_m))};
  }
  if (p.damping_above_knee_exponent != 1.0 && !(p.damper_knee_velocity_m_per_s > 0.0)) {
    return ParameterError{
        key(rows::damping_above_knee_exponent),
        fmt::format("is {} but the damper has no knee: '{}' > 0 as well (the "
                    "power acts above the knee), or 1",
                    p.damping_above_knee_exponent, key(rows::damper_knee_velocity_m_per_s))};
  }
  if (p.free_play_damping_Ns_per_m > 0.0 && !(p.free_play_m > 0.0)) {
    return ParameterError{key(rows::free_play_damping_Ns_per_m),
                          fmt::format("needs free play: '{}' > 0 (it is {}); the damping acts "
                                      "while the play's slack is crossed",
                                      key(rows::free_play_m), p.free_play_m)};
  }
  if (p.stribeck_velocity_m_per_s > 0.0) {
    if (!(p.coulomb_force_N > 0.0)) {
      return ParameterError{key(rows::stribeck_velocity_m_per_s),
                            fmt::format("needs Dahl friction: '{}' > 0 (it is {})",
                                        key(rows::coulomb_force_N), p.coulomb_force_N)};
    }
    if (p.static_friction_force_N < p.coulomb_force_N) {
      return ParameterError{
          key(rows::static_friction_force_N),
          fmt::format("is {}, expected at least '{}' {}: friction breaks away at or above its "
                      "sliding level",
                      p.static_friction_force_N, key(rows::coulomb_force_N), p.coulomb_force_N)};
    }
  }
  return std::nullopt;
}

std::optional<ParameterError> validate(const QuarterCarParameters<double>& p) {
  for (std::size_t i = 0; i < kQuarterCarParameters.size(); ++i) {
    if (auto error = check_range(kQuarterCarParameters[i], quarter_car_parameter(p, i))) {
      return error;
    }
  }
  if (auto error = validate_strut(p)) return error;
  if (auto error = together(rows::bump_stop_stiffness_N_per_m, p.bump_stop_stiffness_N_per_m,
                            rows::bump_stop_clearance_m, p.bump_stop_clearance_m, "")) {
    return error;
  }
  if (p.sensors.acc_sensor_order != 1 && p.sensors.acc_sensor_order != 2) {
    return ParameterError{"acc_sensor_order",
                          fmt::format("is {}, expected 1 or 2", p.sensors.acc_sensor_order)};
  }
  return std::nullopt;
}

void set_quarter_car_parameter(QuarterCarParameters<double>& p, std::size_t index, double value) {
  if (index == quarter_car_row_index(rows::coulomb_force_N) &&
      p.static_friction_force_N == p.coulomb_force_N) {
    p.static_friction_force_N = value;
  }
  quarter_car_parameter(p, index) = value;
}

}  // namespace ridefit::model
