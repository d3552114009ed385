#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

#include "ridefit/model/parameter_info.h"
#include "ridefit/model/quarter_car.h"

namespace ridefit::model {

// The continuous quarter-car parameters, one row each (parameter_info.h): the quarter-car file
// reader, --set, the fits, the diagnosis and the optimiser address a parameter through this
// table and reach the same field for doubles and for Jets. The half car's axles use the rows of
// the keys they share. tyre_lift_off and acc_sensor_order are switches, not parameters, and are
// not listed; neither is the damper state (the topology). The last three rows are the
// accelerometers' measuring chain (acceleration_sensors.h), not physics.
inline constexpr std::array<ParameterInfo, 32> kQuarterCarParameters{{
    {"sprung_mass_kg", "kg", 0.0, 1e5, true, false, "body mass carried by the corner"},
    {"unsprung_mass_kg", "kg", 0.0, 1e5, true, false, "wheel, hub, brake and strut body"},
    {"tyre_stiffness_N_per_m", "N/m", 0.0, 1e10, true, false, "tyre vertical stiffness"},
    {"tyre_damping_Ns_per_m", "N*s/m", 0.0, 1e7, false, false, "tyre vertical damping"},
    {"spring_stiffness_N_per_m", "N/m", 0.0, 1e10, true, false, "coil spring"},
    {"top_mount_spring_path_stiffness_N_per_m", "N/m", 0.0, 1e10, true, false,
     "top mount in series with the coil spring"},
    {"top_mount_stiffness_N_per_m", "N/m", 0.0, 1e10, true, false,
     "top mount in series with the damper (k_tm; the large-amplitude stiffness k_l)"},
    // The Maxwell element's damper rate is (k_tm·(z − z_c) − F)/c: c must be > 0.
    {"damping_Ns_per_m", "N*s/m", 0.0, 1e7, true, false, "damper rebound coefficient c_r"},
    {"dahl_sigma0_N_per_m", "N/m", 0.0, 1e13, true, false, "Dahl rest stiffness sigma0"},
    {"coulomb_force_N", "N", 0.0, 1e5, false, false, "Dahl sliding (Coulomb) force Fc"},
    {"dahl_exponent", "1", 0.1, 10.0, false, false, "Dahl shape exponent d"},
    // > 0 (the damper rate divides by it), at most 10 (beyond any valving; a typed percentage).
    {"compression_to_rebound_ratio", "1", 0.0, 10.0, true, false,
     "compression coefficient over rebound coefficient (default 1, symmetric)"},
    {"top_mount_small_amplitude_stiffness_N_per_m", "N/m", 0.0, 1e10, true, true,
     "top mount stiffness at zero deflection k_s (>= k_l)"},
    {"top_mount_transition_deflection_m", "m", 0.0, 1.0, true, true,
     "deflection over which the small-amplitude stiffening fades, delta0"},
    {"bump_stop_stiffness_N_per_m", "N/m", 0.0, 1e10, true, true, "bump stop secant stiffness"},
    {"bump_stop_clearance_m", "m", 0.0, 1.0, true, true, "compression at first bump-stop contact"},
    {"bump_stop_exponent", "1", 1.0, 10.0, false, false, "bump stop law exponent (default 2)"},
    {"damper_knee_velocity_m_per_s", "m/s", 0.0, 10.0, true, true, "damper blow-off knee v_k"},
    {"damping_above_knee_Ns_per_m", "N*s/m", 0.0, 1e7, true, true,
     "damper slope above the knee c_h (<= damping_Ns_per_m: digressive)"},
    {"static_friction_force_N", "N", 0.0, 1e5, false, false,
     "Stribeck breakaway force Fs (>= Fc; default Fc)"},
    {"stribeck_velocity_m_per_s", "m/s", 0.0, 10.0, true, true,
     "sliding velocity over which Fs falls to Fc"},
    {"damping_per_command_Ns_per_m", "N*s/m", -1e5, 1e6, false, false,
     "controlled damper: damping slope per A or V"},
    {"coulomb_force_per_command_N", "N", -1e4, 1e4, false, false,
     "controlled damper: friction slope per A or V"},
    {"command_lag_s", "s", 0.0, 1.0, false, false, "controlled damper: command lag tau"},
    // Gains > 0 and at most 10 (a typed percentage or g for m/s² is caught).
    {"body_acc_gain", "1", 0.0, 10.0, true, false, "measured over true body acceleration"},
    {"wheel_acc_gain", "1", 0.0, 10.0, true, false, "measured over true wheel acceleration"},
    {"acc_sensor_cutoff_Hz", "Hz", 0.0, 1e5, false, false,
     "accelerometer low-pass corner; 0 = none"},
    // Dry-friction devices (the real friction damper's records): levels that differ with the
    // direction, and slack in series with the damper path.
    {"friction_compression_to_rebound_ratio", "1", 0.0, 10.0, true, false,
     "Dahl sliding level in compression over that in rebound (default 1)"},
    {"free_play_m", "m", 0.0, 1.0, false, false,
     "free play (backlash) in series with the damper path, total width; 0 = none"},
    {"command_exponent", "1", 0.0, 10.0, true, false,
     "controlled damper: levels affine in the command to this power (default 1)"},
    {"free_play_damping_Ns_per_m", "N*s/m", 0.0, 1e7, false, false,
     "free play's damping while its slack is crossed (needs free_play_m); 0 = a dry play"},
    {"damping_above_knee_exponent", "1", 0.0, 5.0, true, false,
     "damper force above the knee grows as |v|^n (default 1; < 1 flattens; needs the knee)"},
}};

// Each row by name, for code that means one parameter: quarter_car_rows::coulomb_force_N is the
// row of coulomb_force_N and .key its key, which only the table above spells (a misspelt name
// does not compile; tests/model/parameter_table_test.cc checks each name's row).
namespace quarter_car_rows {
inline constexpr const ParameterInfo& sprung_mass_kg = kQuarterCarParameters[0];
inline constexpr const ParameterInfo& unsprung_mass_kg = kQuarterCarParameters[1];
inline constexpr const ParameterInfo& tyre_stiffness_N_per_m = kQuarterCarParameters[2];
inline constexpr const ParameterInfo& tyre_damping_Ns_per_m = kQuarterCarParameters[3];
inline constexpr const ParameterInfo& spring_stiffness_N_per_m = kQuarterCarParameters[4];
inline constexpr const ParameterInfo& top_mount_spring_path_stiffness_N_per_m =
    kQuarterCarParameters[5];
inline constexpr const ParameterInfo& top_mount_stiffness_N_per_m = kQuarterCarParameters[6];
inline constexpr const ParameterInfo& damping_Ns_per_m = kQuarterCarParameters[7];
inline constexpr const ParameterInfo& dahl_sigma0_N_per_m = kQuarterCarParameters[8];
inline constexpr const ParameterInfo& coulomb_force_N = kQuarterCarParameters[9];
inline constexpr const ParameterInfo& dahl_exponent = kQuarterCarParameters[10];
inline constexpr const ParameterInfo& compression_to_rebound_ratio = kQuarterCarParameters[11];
inline constexpr const ParameterInfo& top_mount_small_amplitude_stiffness_N_per_m =
    kQuarterCarParameters[12];
inline constexpr const ParameterInfo& top_mount_transition_deflection_m = kQuarterCarParameters[13];
inline constexpr const ParameterInfo& bump_stop_stiffness_N_per_m = kQuarterCarParameters[14];
inline constexpr const ParameterInfo& bump_stop_clearance_m = kQuarterCarParameters[15];
inline constexpr const ParameterInfo& bump_stop_exponent = kQuarterCarParameters[16];
inline constexpr const ParameterInfo& damper_knee_velocity_m_per_s = kQuarterCarParameters[17];
inline constexpr const ParameterInfo& damping_above_knee_Ns_per_m = kQuarterCarParameters[18];
inline constexpr const ParameterInfo& static_friction_force_N = kQuarterCarParameters[19];
inline constexpr const ParameterInfo& stribeck_velocity_m_per_s = kQuarterCarParameters[20];
inline constexpr const ParameterInfo& damping_per_command_Ns_per_m = kQuarterCarParameters[21];
inline constexpr const ParameterInfo& coulomb_force_per_command_N = kQuarterCarParameters[22];
inline constexpr const ParameterInfo& command_lag_s = kQuarterCarParameters[23];
inline constexpr const ParameterInfo& body_acc_gain = kQuarterCarParameters[24];
inline constexpr const ParameterInfo& wheel_acc_gain = kQuarterCarParameters[25];
inline constexpr const ParameterInfo& acc_sensor_cutoff_Hz = kQuarterCarParameters[26];
inline constexpr const ParameterInfo& friction_compression_to_rebound_ratio =
    kQuarterCarParameters[27];
inline constexpr const ParameterInfo& free_play_m = kQuarterCarParameters[28];
inline constexpr const ParameterInfo& command_exponent = kQuarterCarParameters[29];
inline constexpr const ParameterInfo& free_play_damping_Ns_per_m = kQuarterCarParameters[30];
inline constexpr const ParameterInfo& damping_above_knee_exponent = kQuarterCarParameters[31];
}  // namespace quarter_car_rows

// Index of `key` in kQuarterCarParameters, or none.
constexpr std::optional<std::size_t> quarter_car_parameter_index(std::string_view key) {
  for (std::size_t i = 0; i < kQuarterCarParameters.size(); ++i) {
    if (kQuarterCarParameters[i].key == key) return i;
  }
  return std::nullopt;
}

// The index of a row of kQuarterCarParameters (a quarter_car_rows name).
constexpr std::size_t quarter_car_row_index(const ParameterInfo& row) {
  return static_cast<std::size_t>(&row - kQuarterCarParameters.data());
}

// The field of `p` of row `index`.
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
                       &p.sensors.acc_sensor_cutoff_Hz,
                       &p.friction_compression_to_rebound_ratio,
                       &p.free_play_m,
                       &p.command_exponent,
                       &p.free_play_damping_Ns_per_m,
                       &p.damping_above_knee_exponent};
  static_assert(sizeof(fields) / sizeof(fields[0]) == kQuarterCarParameters.size());
  return *fields[index];
}

template <typename T>
const T& quarter_car_parameter(const QuarterCarParameters<T>& p, std::size_t index) {
  return quarter_car_parameter(const_cast<QuarterCarParameters<T>&>(p), index);
}

// The strut's rows (StrutParameters), in its fields' order: the damper path's parameters that
// the quarter car, each half-car axle and the rig share.
inline constexpr std::array<std::size_t, 20> kStrutRows{
    quarter_car_row_index(quarter_car_rows::top_mount_stiffness_N_per_m),
    quarter_car_row_index(quarter_car_rows::damping_Ns_per_m),
    quarter_car_row_index(quarter_car_rows::dahl_sigma0_N_per_m),
    quarter_car_row_index(quarter_car_rows::coulomb_force_N),
    quarter_car_row_index(quarter_car_rows::dahl_exponent),
    quarter_car_row_index(quarter_car_rows::compression_to_rebound_ratio),
    quarter_car_row_index(quarter_car_rows::damper_knee_velocity_m_per_s),
    quarter_car_row_index(quarter_car_rows::damping_above_knee_Ns_per_m),
    quarter_car_row_index(quarter_car_rows::damping_above_knee_exponent),
    quarter_car_row_index(quarter_car_rows::top_mount_small_amplitude_stiffness_N_per_m),
    quarter_car_row_index(quarter_car_rows::top_mount_transition_deflection_m),
    quarter_car_row_index(quarter_car_rows::static_friction_force_N),
    quarter_car_row_index(quarter_car_rows::stribeck_velocity_m_per_s),
    quarter_car_row_index(quarter_car_rows::friction_compression_to_rebound_ratio),
    quarter_car_row_index(quarter_car_rows::free_play_m),
    quarter_car_row_index(quarter_car_rows::free_play_damping_Ns_per_m),
    quarter_car_row_index(quarter_car_rows::damping_per_command_Ns_per_m),
    quarter_car_row_index(quarter_car_rows::coulomb_force_per_command_N),
    quarter_car_row_index(quarter_car_rows::command_lag_s),
    quarter_car_row_index(quarter_car_rows::command_exponent),
};

// The field of the strut row kStrutRows[i].
template <typename T>
T& strut_field(StrutParameters<T>& s, std::size_t i) {
  T* const fields[] = {&s.top_mount_stiffness_N_per_m,
                       &s.damping_Ns_per_m,
                       &s.dahl_sigma0_N_per_m,
                       &s.coulomb_force_N,
                       &s.dahl_exponent,
                       &s.compression_to_rebound_ratio,
                       &s.damper_knee_velocity_m_per_s,
                       &s.damping_above_knee_Ns_per_m,
                       &s.damping_above_knee_exponent,
                       &s.top_mount_small_amplitude_stiffness_N_per_m,
                       &s.top_mount_transition_deflection_m,
                       &s.static_friction_force_N,
                       &s.stribeck_velocity_m_per_s,
                       &s.friction_compression_to_rebound_ratio,
                       &s.free_play_m,
                       &s.free_play_damping_Ns_per_m,
                       &s.damping_per_command_Ns_per_m,
                       &s.coulomb_force_per_command_N,
                       &s.command_lag_s,
                       &s.command_exponent};
  static_assert(sizeof(fields) / sizeof(fields[0]) == kStrutRows.size());
  return *fields[i];
}

// The index i of `row` in kStrutRows, or none (a row the strut does not have).
constexpr std::optional<std::size_t> strut_row(const ParameterInfo& row) {
  for (std::size_t i = 0; i < kStrutRows.size(); ++i) {
    if (&kQuarterCarParameters[kStrutRows[i]] == &row) return i;
  }
  return std::nullopt;
}

// The strut's ranges and rules (the effects' keys together or not at all, k_s >= k_l,
// c_h <= c_r, Fs >= Fc, Stribeck only with Dahl friction, a free play's damping only with free
// play, a knee's exponent only with the knee); each key named with `prefix` ("front."
// for a half-car axle). `passive_damper` allows damping_Ns_per_m = 0 (a passive half-car axle's
// damper; a strut's rate divides by it).
std::optional<ParameterError> validate_strut(const StrutParameters<double>& p,
                                             std::string_view prefix = "",
                                             bool passive_damper = false);

// Every row's range and the rules between parameters that the file reader enforces (an effect's
// keys together or not at all, k_s >= k_l, c_h <= c_r, Fs >= Fc, Stribeck only with Dahl
// friction, a sensor order of 1 or 2): the first violation, or none. For a model edited in
// memory (the optimiser's design values, a fit's result) rather than read from a file.
std::optional<ParameterError> validate(const QuarterCarParameters<double>& p);

// Sets row `index` of `p` to `value` as a file that gives the key would: the breakaway force
// follows a change of the Coulomb force while the two are equal (the file reader's default,
// Fs = Fc, a flat Stribeck curve). Call validate() after the last change.
void set_quarter_car_parameter(QuarterCarParameters<double>& p, std::size_t index, double value);

}  // namespace ridefit::model
