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

namespace {

// Plausibility limits: far beyond any road vehicle, close enough to catch a unit slip
// (N/mm typed as N/m is 1e3 off; 1e300 is a typo) before it becomes a NaN in the solver.
constexpr double kMaxMass_kg = 1e5;
constexpr double kMaxStiffness_N_per_m = 1e10;
constexpr double kMaxDamping_Ns_per_m = 1e7;
constexpr double kMaxCoulombForce_N = 1e5;
// A damper's compression coefficient over its rebound coefficient: > 0 (the damper rate divides
// by it), at most 10 (beyond any real valving; catches a typed percentage).
constexpr double kMaxCompressionToReboundRatio = 10.0;

QuarterCarFile read_quarter_car(const YamlMap& file, const std::string& damper_state) {
  file.choice("model", {"quarter_car"});
  QuarterCarFile result{};
  // The file's own damper_state is checked even when the caller replaces it.
  const auto file_state =
      parse_damper_state(file.text("damper_state"), file.locate("damper_state"));
  result.damper_state =
      damper_state.empty() ? file_state : parse_damper_state(damper_state, "damper state");
  auto& p = result.parameters;
  p.sprung_mass_kg = file.positive_up_to("sprung_mass_kg", kMaxMass_kg);
  p.unsprung_mass_kg = file.positive_up_to("unsprung_mass_kg", kMaxMass_kg);
  p.tyre_stiffness_N_per_m = file.positive_up_to("tyre_stiffness_N_per_m", kMaxStiffness_N_per_m);
  p.tyre_damping_Ns_per_m = file.non_negative_up_to("tyre_damping_Ns_per_m", kMaxDamping_Ns_per_m);
  p.spring_stiffness_N_per_m =
      file.positive_up_to("spring_stiffness_N_per_m", kMaxStiffness_N_per_m);
  p.top_mount_spring_path_stiffness_N_per_m =
      file.positive_up_to("top_mount_spring_path_stiffness_N_per_m", kMaxStiffness_N_per_m);
  p.top_mount_stiffness_N_per_m =
      file.positive_up_to("top_mount_stiffness_N_per_m", kMaxStiffness_N_per_m);
  // The Maxwell element's damper rate is (k_tm·(z − z_c) − F)/c: c must be > 0.
  p.damping_Ns_per_m = file.positive_up_to("damping_Ns_per_m", kMaxDamping_Ns_per_m);
  // damping_Ns_per_m is the rebound coefficient; compression gets this ratio times it (and by
  // default the same: the symmetric damper).
  p.compression_to_rebound_ratio = 1.0;
  if (file.has("compression_to_rebound_ratio")) {
    p.compression_to_rebound_ratio =
        file.positive_up_to("compression_to_rebound_ratio", kMaxCompressionToReboundRatio);
  }
  const bool friction_required = result.damper_state == model::DamperState::kStickSlip;
  if (friction_required || file.has("dahl_sigma0_N_per_m") || file.has("coulomb_force_N") ||
      file.has("dahl_exponent")) {
    p.dahl_sigma0_N_per_m = file.positive_up_to("dahl_sigma0_N_per_m", 1e3 * kMaxStiffness_N_per_m);
    p.coulomb_force_N = file.non_negative_up_to("coulomb_force_N", kMaxCoulombForce_N);
    p.dahl_exponent = file.number_in("dahl_exponent", 0.1, 10.0);
  } else {
    p.dahl_sigma0_N_per_m = 1.0;
    p.coulomb_force_N = 0.0;
    p.dahl_exponent = 1.0;
  }
  file.finish();
  return result;
}

}  // namespace

QuarterCarFile load_quarter_car(const std::filesystem::path& path,
                                const std::map<std::string, double>& overrides,
                                const std::string& damper_state) {
  YamlMap file = YamlMap::load(path);
  if (overrides.empty()) return read_quarter_car(file, damper_state);
  for (const auto& [key, value] : overrides) {
    if (key == "damper_state" || key == "model") {
      throw InputError(
          fmt::format("--set {}: not a number key; use --damper-state for the "
                      "topology",
                      key));
    }
  }
  YAML::Node root = YAML::LoadFile(path.string());
  for (const auto& [key, value] : overrides) root[key] = value;
  try {
    return read_quarter_car(YamlMap(root, path, ""), damper_state);
  } catch (const InputError& e) {
    // Say so when the offending key came from the command line rather than the file.
    const std::string message = e.what();
    for (const auto& [key, value] : overrides) {
      if (message.find("'" + key + "'") != std::string::npos) {
        throw InputError(
            fmt::format("{} (given on the command line as --set {}={})", message, key, value));
      }
    }
    throw;
  }
}

}  // namespace ridefit::io
