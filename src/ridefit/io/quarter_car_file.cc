#include "ridefit/io/quarter_car_file.h"

#include <fmt/core.h>

#include <string_view>

#include "ridefit/common/errors.h"
#include "ridefit/io/yaml_map.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::io {

model::DamperState parse_damper_state(const std::string& text, const std::string& where) {
  if (text == "slip") return model::DamperState::kSlip;
  if (text == "stick") return model::DamperState::kStick;
  if (text == "stick_slip") return model::DamperState::kStickSlip;
  throw InputError(
      fmt::format("{} is '{}', expected one of: slip, stick, stick_slip", where, text));
}

namespace {

namespace rows = model::quarter_car_rows;

// `key` is only meaningful together with `needed`: name both when `needed` is missing.
void require_with(const YamlMap& file, std::string_view key, std::string_view needed,
                  const std::string& why) {
  if (!file.has(std::string(needed))) {
    throw InputError(fmt::format("{} needs the key '{}' as well ({})",
                                 file.locate(std::string(key)), needed, why));
  }
}

// A number in [lo, row's upper limit] where lo is another key's value: the message says which
// and why.
double number_from(const YamlMap& file, const model::ParameterInfo& row, double lo,
                   const std::string& rule) {
  const double v = file.number(row);
  if (v < lo || v > row.upper) {
    throw InputError(fmt::format("{} is {}, expected a value in [{}, {:g}] ({})", file.locate(row),
                                 v, lo, row.upper, rule));
  }
  return v;
}

// The quarter car's own optional effects, each off when its keys are absent
// (quarter_car_file.h).
void read_optional_effects(const YamlMap& file, model::QuarterCarParameters<double>& p) {
  // 2. Bump stop: stiffness and clearance together, the exponent optional (default 2).
  if (file.has(rows::bump_stop_stiffness_N_per_m) || file.has(rows::bump_stop_clearance_m) ||
      file.has(rows::bump_stop_exponent)) {
    const std::string_view given =
        file.has(rows::bump_stop_stiffness_N_per_m) ? rows::bump_stop_stiffness_N_per_m.key
        : file.has(rows::bump_stop_clearance_m)     ? rows::bump_stop_clearance_m.key
                                                    : rows::bump_stop_exponent.key;
    require_with(file, given, rows::bump_stop_stiffness_N_per_m.key, "the stop's secant stiffness");
    require_with(file, given, rows::bump_stop_clearance_m.key, "the compression at first contact");
    p.bump_stop_stiffness_N_per_m = file.parameter(rows::bump_stop_stiffness_N_per_m);
    p.bump_stop_clearance_m = file.parameter(rows::bump_stop_clearance_m);
    p.bump_stop_exponent = 2.0;
    if (file.has(rows::bump_stop_exponent)) {
      p.bump_stop_exponent = file.parameter(rows::bump_stop_exponent);
    }
  }
  // 3. Tyre lift-off: true | false, or 1 | 0 (what --set tyre_lift_off=1 writes).
  if (file.has("tyre_lift_off")) {
    const std::string text = file.choice("tyre_lift_off", {"true", "false", "1", "0"});
    p.tyre_lift_off = text == "true" || text == "1";
  }
}

}  // namespace

void read_strut_effects(const YamlMap& file, model::StrutParameters<double>& p) {
  // 1. Top mount stiffer at small amplitude: k_s ≥ k_l and δ0 > 0, both or neither.
  const bool stiffening = file.has(rows::top_mount_small_amplitude_stiffness_N_per_m) ||
                          file.has(rows::top_mount_transition_deflection_m);
  if (stiffening) {
    require_with(file, rows::top_mount_small_amplitude_stiffness_N_per_m.key,
                 rows::top_mount_transition_deflection_m.key,
                 "the deflection where the stiffening fades");
    require_with(file, rows::top_mount_transition_deflection_m.key,
                 rows::top_mount_small_amplitude_stiffness_N_per_m.key,
                 "the stiffness at zero deflection");
    p.top_mount_small_amplitude_stiffness_N_per_m = number_from(
        file, rows::top_mount_small_amplitude_stiffness_N_per_m, p.top_mount_stiffness_N_per_m,
        "at least top_mount_stiffness_N_per_m, the large-amplitude stiffness");
    p.top_mount_transition_deflection_m = file.parameter(rows::top_mount_transition_deflection_m);
  }
  // 4. Damper blow-off knee: v_k > 0 and 0 < c_h ≤ c_r, both or neither.
  if (file.has(rows::damper_knee_velocity_m_per_s) || file.has(rows::damping_above_knee_Ns_per_m)) {
    require_with(file, rows::damper_knee_velocity_m_per_s.key,
                 rows::damping_above_knee_Ns_per_m.key, "the slope above the knee");
    require_with(file, rows::damping_above_knee_Ns_per_m.key,
                 rows::damper_knee_velocity_m_per_s.key, "where the slope changes");
    p.damper_knee_velocity_m_per_s = file.parameter(rows::damper_knee_velocity_m_per_s);
    // Digressive only: a slope above the knee greater than c_r would be a progressive damper.
    p.damping_above_knee_Ns_per_m = file.number(rows::damping_above_knee_Ns_per_m);
    if (!(p.damping_above_knee_Ns_per_m > 0.0) ||
        p.damping_above_knee_Ns_per_m > p.damping_Ns_per_m) {
      throw InputError(fmt::format(
          "{} is {}, expected a value > 0 and <= {} (at most damping_Ns_per_m: the knee is "
          "digressive)",
          file.locate(rows::damping_above_knee_Ns_per_m), p.damping_above_knee_Ns_per_m,
          p.damping_Ns_per_m));
    }
  }
  // 5. Stribeck level of the Dahl element: v_s > 0 switches it on, Fs ≥ Fc (default Fc). Fs = Fc
  // also while it is off, so a fit that frees only v_s starts from a flat curve, not from Fs = 0.
  p.static_friction_force_N = p.coulomb_force_N;
  if (file.has(rows::stribeck_velocity_m_per_s) || file.has(rows::static_friction_force_N)) {
    require_with(file, rows::static_friction_force_N.key, rows::stribeck_velocity_m_per_s.key,
                 "the sliding velocity over which Fs falls to coulomb_force_N");
    p.stribeck_velocity_m_per_s = file.parameter(rows::stribeck_velocity_m_per_s);
    if (!(p.coulomb_force_N > 0.0)) {
      throw InputError(fmt::format("{} needs Dahl friction: coulomb_force_N > 0 (it is {})",
                                   file.locate(rows::stribeck_velocity_m_per_s),
                                   p.coulomb_force_N));
    }
    if (file.has(rows::static_friction_force_N)) {
      p.static_friction_force_N = number_from(
          file, rows::static_friction_force_N, p.coulomb_force_N,
          "at least coulomb_force_N: friction breaks away at or above its sliding level");
    }
  }
  // 6b. Dry-friction devices: the friction's direction ratio (default 1) and free play (default 0).
  if (file.has(rows::friction_compression_to_rebound_ratio)) {
    p.friction_compression_to_rebound_ratio =
        file.parameter(rows::friction_compression_to_rebound_ratio);
  }
  if (file.has(rows::free_play_m)) p.free_play_m = file.parameter(rows::free_play_m);
  // The knee's power (default 1, a straight slope) acts only above the knee.
  if (file.has(rows::damping_above_knee_exponent)) {
    p.damping_above_knee_exponent = file.parameter(rows::damping_above_knee_exponent);
    if (p.damping_above_knee_exponent != 1.0 && !(p.damper_knee_velocity_m_per_s > 0.0)) {
      throw InputError(fmt::format(
          "{} is {} but the damper has no knee: give damper_knee_velocity_m_per_s and "
          "damping_above_knee_Ns_per_m as well (the power acts above the knee), or leave it out",
          file.locate(rows::damping_above_knee_exponent), p.damping_above_knee_exponent));
    }
  }
  // The play's damping (default 0, a dry play) acts only while its slack is crossed.
  if (file.has(rows::free_play_damping_Ns_per_m)) {
    p.free_play_damping_Ns_per_m = file.parameter(rows::free_play_damping_Ns_per_m);
    if (p.free_play_damping_Ns_per_m > 0.0 && !(p.free_play_m > 0.0)) {
      throw InputError(fmt::format(
          "{} is {} N*s/m but the model has no free play: give free_play_m > 0 as well (the "
          "damping acts while the play's slack is crossed), or leave the damping out",
          file.locate(rows::free_play_damping_Ns_per_m), p.free_play_damping_Ns_per_m));
    }
  }
  // 6. Controlled damper: each key optional (0 = off).
  if (file.has(rows::damping_per_command_Ns_per_m)) {
    p.damping_per_command_Ns_per_m = file.parameter(rows::damping_per_command_Ns_per_m);
  }
  if (file.has(rows::coulomb_force_per_command_N)) {
    p.coulomb_force_per_command_N = file.parameter(rows::coulomb_force_per_command_N);
  }
  if (file.has(rows::command_lag_s)) p.command_lag_s = file.parameter(rows::command_lag_s);
  if (file.has(rows::command_exponent)) p.command_exponent = file.parameter(rows::command_exponent);
}

namespace {

// 7. The accelerometers' measuring chain (acceleration_sensors.h), each key optional: gains
// (default 1), a low-pass cutoff (default 0 = none) and its order (1 or 2, only with a cutoff).
void read_acceleration_sensors(const YamlMap& file, model::AccelerationSensors<double>& s) {
  if (file.has(rows::body_acc_gain)) {
    s.body_acc_gain = file.parameter(rows::body_acc_gain);
  }
  if (file.has(rows::wheel_acc_gain)) {
    s.wheel_acc_gain = file.parameter(rows::wheel_acc_gain);
  }
  if (file.has(rows::acc_sensor_cutoff_Hz)) {
    s.acc_sensor_cutoff_Hz = file.parameter(rows::acc_sensor_cutoff_Hz);
  }
  if (file.has("acc_sensor_order")) {
    require_with(file, "acc_sensor_order", rows::acc_sensor_cutoff_Hz.key,
                 "the low-pass' corner frequency, 0 = none");
    const double order = file.number("acc_sensor_order");
    if (order != 1.0 && order != 2.0) {
      throw InputError(fmt::format(
          "{} is {}, expected 1 (first-order low-pass) or 2 (two first-order stages in series)",
          file.locate("acc_sensor_order"), order));
    }
    s.acc_sensor_order = static_cast<int>(order);
  }
}

QuarterCarFile read_quarter_car(const YamlMap& file, const std::string& damper_state) {
  file.choice("model", {"quarter_car"});
  QuarterCarFile result{};
  // The file's own damper_state is checked even when the caller replaces it.
  const auto file_state =
      parse_damper_state(file.text("damper_state"), file.locate("damper_state"));
  result.damper_state =
      damper_state.empty() ? file_state : parse_damper_state(damper_state, "damper state");
  auto& p = result.parameters;
  p.sprung_mass_kg = file.parameter(rows::sprung_mass_kg);
  p.unsprung_mass_kg = file.parameter(rows::unsprung_mass_kg);
  p.tyre_stiffness_N_per_m = file.parameter(rows::tyre_stiffness_N_per_m);
  p.tyre_damping_Ns_per_m = file.parameter(rows::tyre_damping_Ns_per_m);
  p.spring_stiffness_N_per_m = file.parameter(rows::spring_stiffness_N_per_m);
  p.top_mount_spring_path_stiffness_N_per_m =
      file.parameter(rows::top_mount_spring_path_stiffness_N_per_m);
  p.top_mount_stiffness_N_per_m = file.parameter(rows::top_mount_stiffness_N_per_m);
  // The Maxwell element's damper rate is (k_tm·(z − z_c) − F)/c: c must be > 0.
  p.damping_Ns_per_m = file.parameter(rows::damping_Ns_per_m);
  // damping_Ns_per_m is the rebound coefficient; compression gets this ratio times it (and by
  // default the same: the symmetric damper).
  p.compression_to_rebound_ratio = 1.0;
  if (file.has(rows::compression_to_rebound_ratio)) {
    p.compression_to_rebound_ratio = file.parameter(rows::compression_to_rebound_ratio);
  }
  const bool friction_required = result.damper_state == model::DamperState::kStickSlip;
  if (friction_required || file.has(rows::dahl_sigma0_N_per_m) || file.has(rows::coulomb_force_N) ||
      file.has(rows::dahl_exponent)) {
    p.dahl_sigma0_N_per_m = file.parameter(rows::dahl_sigma0_N_per_m);
    p.coulomb_force_N = file.parameter(rows::coulomb_force_N);
    p.dahl_exponent = file.parameter(rows::dahl_exponent);
  } else {
    p.dahl_sigma0_N_per_m = 1.0;
    p.coulomb_force_N = 0.0;
    p.dahl_exponent = 1.0;
  }
  read_optional_effects(file, p);
  read_strut_effects(file, p);
  read_acceleration_sensors(file, p.sensors);
  file.finish();
  return result;
}

}  // namespace

QuarterCarFile load_quarter_car(const std::filesystem::path& path,
                                const ModelOverrides& overrides) {
  YamlMap file = YamlMap::load(path);
  if (overrides.keys.empty()) return read_quarter_car(file, overrides.damper_state);
  for (const auto& [key, value] : overrides.keys) {
    if (key == "damper_state" || key == "model") {
      throw InputError(fmt::format(
          "{}: '{}' is not a number key; the damper's topology is chosen as its damper state "
          "({} {}={})",
          path.string(), key, overrides.origin, key, value));
    }
  }
  YAML::Node root = YAML::LoadFile(path.string());
  for (const auto& [key, value] : overrides.keys) root[key] = value;
  try {
    return read_quarter_car(YamlMap(root, path, ""), overrides.damper_state);
  } catch (const InputError& e) {
    throw InputError(with_override_named(e.what(), overrides));
  }
}

}  // namespace ridefit::io
