#include "ridefit/io/quarter_car_file.h"

#include <fmt/core.h>

#include "ridefit/io/input_error.h"
#include "ridefit/io/yaml_map.h"

namespace ridefit::io {

model::DamperState parse_damper_state(const std::string& text, const std::string& where) {
  if (text == "slip") return model::DamperState::kSlip;
  if (text == "stick") return model::DamperState::kStick;
  if (text == "stick_slip") return model::DamperState::kStickSlip;
  throw InputError(
      fmt::format("{} is '{}', expected one of: slip, stick, stick_slip", where, text));
}

QuarterCarFile load_quarter_car(const std::filesystem::path& path,
                                const std::map<std::string, double>& overrides,
                                const std::string& damper_state) {
  YamlMap file = YamlMap::load(path);
  if (!overrides.empty() || !damper_state.empty()) {
    YAML::Node root = YAML::LoadFile(path.string());
    for (const auto& [key, value] : overrides) root[key] = value;
    if (!damper_state.empty()) root["damper_state"] = damper_state;
    file = YamlMap(root, path, "");
  }
  file.choice("model", {"quarter_car"});
  QuarterCarFile result{};
  result.damper_state = parse_damper_state(file.text("damper_state"), file.locate("damper_state"));
  auto& p = result.parameters;
  p.sprung_mass_kg = file.positive("sprung_mass_kg");
  p.unsprung_mass_kg = file.positive("unsprung_mass_kg");
  p.tyre_stiffness_N_per_m = file.positive("tyre_stiffness_N_per_m");
  p.tyre_damping_Ns_per_m = file.non_negative("tyre_damping_Ns_per_m");
  p.spring_stiffness_N_per_m = file.positive("spring_stiffness_N_per_m");
  p.top_mount_spring_path_stiffness_N_per_m =
      file.positive("top_mount_spring_path_stiffness_N_per_m");
  p.top_mount_stiffness_N_per_m = file.positive("top_mount_stiffness_N_per_m");
  // The Maxwell element's damper rate is (k_tm·(z − z_c) − F)/c: c must be > 0.
  p.damping_Ns_per_m = file.positive("damping_Ns_per_m");
  const bool friction_required = result.damper_state == model::DamperState::kStickSlip;
  if (friction_required || file.has("dahl_sigma0_N_per_m") || file.has("coulomb_force_N") ||
      file.has("dahl_exponent")) {
    p.dahl_sigma0_N_per_m = file.positive("dahl_sigma0_N_per_m");
    p.coulomb_force_N = file.non_negative("coulomb_force_N");
    p.dahl_exponent = file.number_in("dahl_exponent", 0.1, 10.0);
  } else {
    p.dahl_sigma0_N_per_m = 1.0;
    p.coulomb_force_N = 0.0;
    p.dahl_exponent = 1.0;
  }
  file.finish();
  return result;
}

}  // namespace ridefit::io
