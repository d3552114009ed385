#include "ridefit/io/half_car_file.h"

#include <fmt/core.h>

#include <sstream>
#include <string_view>

#include "ridefit/common/errors.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/io/yaml_map.h"
#include "ridefit/model/half_car_parameter_table.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::io {
namespace {

namespace axle_rows = model::quarter_car_rows;

constexpr double kSymmetricDamper = 1.0;

// Keys each axle may leave out, because alone they have a default (a file without them means
// what it meant before they existed). A dotted override may add these to the file; every other
// key must be in the file, so a typo never adds a key that nothing reads. The Dahl keys and the
// control section are optional too, but only as a group (a lone coulomb_force_N has no
// sensible partners), so they are not here.
constexpr const char* kAxles[] = {"front", "rear"};
constexpr std::string_view kOptionalAxleKeys[] = {
    axle_rows::compression_to_rebound_ratio.key,
    axle_rows::damper_knee_velocity_m_per_s.key,
    axle_rows::damping_above_knee_Ns_per_m.key,
    axle_rows::damping_above_knee_exponent.key,
    axle_rows::top_mount_small_amplitude_stiffness_N_per_m.key,
    axle_rows::top_mount_transition_deflection_m.key,
    axle_rows::static_friction_force_N.key,
    axle_rows::stribeck_velocity_m_per_s.key,
    axle_rows::damping_per_command_Ns_per_m.key,
    axle_rows::coulomb_force_per_command_N.key,
    axle_rows::command_lag_s.key,
    axle_rows::command_exponent.key,
    axle_rows::friction_compression_to_rebound_ratio.key,
    axle_rows::free_play_m.key,
    axle_rows::free_play_damping_Ns_per_m.key};

std::pair<model::AxleTopology, model::HalfCarAxle<double>> read_axle(const YamlMap& axle) {
  model::AxleTopology topology;
  model::HalfCarAxle<double> p{};
  topology.suspension = axle.choice("suspension", {"passive", "strut"}) == "strut"
                            ? model::AxleSuspension::kStrut
                            : model::AxleSuspension::kPassive;
  const bool strut = topology.suspension == model::AxleSuspension::kStrut;
  if (strut || axle.has("damper_state")) {
    topology.damper_state =
        parse_damper_state(axle.text("damper_state"), axle.locate("damper_state"));
  }
  p.unsprung_mass_kg = axle.parameter(axle_rows::unsprung_mass_kg);
  p.tyre_stiffness_N_per_m = axle.parameter(axle_rows::tyre_stiffness_N_per_m);
  p.tyre_damping_Ns_per_m = axle.parameter(axle_rows::tyre_damping_Ns_per_m);
  p.spring_stiffness_N_per_m = axle.parameter(axle_rows::spring_stiffness_N_per_m);
  // A strut's damper rate is (k_tm·(z − z_c) − F)/c: c must be > 0 there.
  p.damping_Ns_per_m = strut ? axle.parameter(axle_rows::damping_Ns_per_m)
                             : axle.non_negative_up_to(axle_rows::damping_Ns_per_m.key_string(),
                                                       axle_rows::damping_Ns_per_m.upper);
  // damping_Ns_per_m is the rebound coefficient; compression gets this ratio times it.
  p.compression_to_rebound_ratio = kSymmetricDamper;
  if (axle.has(axle_rows::compression_to_rebound_ratio)) {
    p.compression_to_rebound_ratio = axle.parameter(axle_rows::compression_to_rebound_ratio);
  }
  p.top_mount_stiffness_N_per_m = 1.0;
  if (strut || axle.has(axle_rows::top_mount_stiffness_N_per_m)) {
    p.top_mount_stiffness_N_per_m = axle.parameter(axle_rows::top_mount_stiffness_N_per_m);
  }
  const bool friction = strut && topology.damper_state == model::DamperState::kStickSlip;
  p.dahl_sigma0_N_per_m = 1.0;
  p.coulomb_force_N = 0.0;
  p.dahl_exponent = 1.0;
  if (friction || axle.has(axle_rows::dahl_sigma0_N_per_m) ||
      axle.has(axle_rows::coulomb_force_N) || axle.has(axle_rows::dahl_exponent)) {
    p.dahl_sigma0_N_per_m = axle.parameter(axle_rows::dahl_sigma0_N_per_m);
    p.coulomb_force_N = axle.parameter(axle_rows::coulomb_force_N);
    p.dahl_exponent = axle.parameter(axle_rows::dahl_exponent);
  }
  // The strut's optional effects and a controlled damper: the quarter car's keys and rules.
  read_strut_effects(axle, p);
  axle.finish();
  return {topology, p};
}

model::SuspendedMass<double> read_mass(const YamlMap& m) {
  namespace rows = model::suspended_mass_rows;
  return {m.parameter(rows::mass_kg), m.parameter(rows::stiffness_N_per_m),
          m.parameter(rows::damping_Ns_per_m)};
}

// The limits and gains are required where the law uses them and checked wherever given, so a
// file can keep them while its law is passive (and a study can switch the law).
model::SemiActiveControl read_control(const YamlMap& c) {
  model::SemiActiveControl control;
  const std::string law = c.choice("law", {"passive", "skyhook", "groundhook", "hybrid"});
  control.law = law == "passive"      ? model::ControlLaw::kPassive
                : law == "skyhook"    ? model::ControlLaw::kSkyhook
                : law == "groundhook" ? model::ControlLaw::kGroundhook
                                      : model::ControlLaw::kHybrid;
  const bool active = control.law != model::ControlLaw::kPassive;
  namespace rows = model::control_rows;
  auto read_if = [&](const model::ParameterInfo& row, bool required, double& value) {
    if (required || c.has(row)) value = c.parameter(row);
  };
  read_if(rows::min_damping_Ns_per_m, active, control.min_damping_Ns_per_m);
  read_if(rows::max_damping_Ns_per_m, active, control.max_damping_Ns_per_m);
  if (control.min_damping_Ns_per_m > control.max_damping_Ns_per_m) {
    throw InputError(
        fmt::format("{} is {} Ns/m, above {} {} Ns/m; a damper's limits need c_min <= c_max",
                    c.locate(rows::min_damping_Ns_per_m), control.min_damping_Ns_per_m,
                    rows::max_damping_Ns_per_m.key, control.max_damping_Ns_per_m));
  }
  if (active && !(control.max_damping_Ns_per_m > 0.0)) {
    throw InputError(
        fmt::format("{} must be > 0 for a {} damper", c.locate(rows::max_damping_Ns_per_m), law));
  }
  read_if(rows::skyhook_damping_Ns_per_m,
          control.law == model::ControlLaw::kSkyhook || control.law == model::ControlLaw::kHybrid,
          control.skyhook_damping_Ns_per_m);
  read_if(
      rows::groundhook_damping_Ns_per_m,
      control.law == model::ControlLaw::kGroundhook || control.law == model::ControlLaw::kHybrid,
      control.groundhook_damping_Ns_per_m);
  read_if(rows::skyhook_share, control.law == model::ControlLaw::kHybrid, control.skyhook_share);
  c.finish();
  return control;
}

HalfCarFile read_half_car(const YamlMap& file) {
  file.choice("model", {"half_car"});
  HalfCarFile result{};
  auto& p = result.parameters;
  namespace body = model::half_car_body_rows;
  p.body_mass_kg = file.parameter(body::body_mass_kg);
  p.pitch_inertia_kg_m2 = file.parameter(body::pitch_inertia_kg_m2);
  p.front_axle_distance_m = file.parameter(body::front_axle_distance_m);
  p.rear_axle_distance_m = file.parameter(body::rear_axle_distance_m);
  p.seat_distance_m = file.parameter(body::seat_distance_m);
  std::tie(result.topology.front, p.front) = read_axle(file.map("front"));
  std::tie(result.topology.rear, p.rear) = read_axle(file.map("rear"));
  const YamlMap seat = file.map("seat");
  p.seat = read_mass(seat);
  seat.finish();
  const YamlMap lower = file.map("lower_body");
  p.lower_body = read_mass(lower);
  lower.finish();
  const YamlMap upper = file.map("upper_body");
  p.upper_body = read_mass(upper);
  result.topology.upper_body_support =
      upper.choice("supported_by", {"seat", "lower_body"}) == "seat"
          ? model::UpperBodySupport::kSeat
          : model::UpperBodySupport::kLowerBody;
  upper.finish();
  if (file.has("control")) result.topology.control = read_control(file.map("control"));
  // A semi-active law reaches its coefficient through a controlled damper's command,
  // u = (c_law − c)/c_b: that needs a damping slope.
  if (result.topology.control.law != model::ControlLaw::kPassive) {
    for (const auto& [name, axle] : {std::pair{"front", &p.front}, {"rear", &p.rear}}) {
      if (axle->commanded() && axle->damping_per_command_Ns_per_m == 0.0) {
        const YamlMap section = file.map(name);
        throw InputError(fmt::format(
            "{}: {}.{} without {}.{}: the control law sets the damping through the command, u = "
            "(c_law - c)/c_b, so give the damper's damping slope c_b (N*s/m per A or V, not 0)",
            section.locate(axle_rows::coulomb_force_per_command_N), name,
            axle_rows::coulomb_force_per_command_N.key, name,
            axle_rows::damping_per_command_Ns_per_m.key));
      }
    }
  }
  file.finish();
  return result;
}

std::vector<std::string> split_dotted(const std::string& key) {
  std::vector<std::string> parts;
  std::stringstream in(key);
  std::string part;
  while (std::getline(in, part, '.')) parts.push_back(part);
  return parts;
}

// The scalar node at a dotted path, or an undefined node. Recursion rather than `node =
// node[part]`: assigning to a yaml-cpp node overwrites what it refers to.
YAML::Node find_scalar(const YAML::Node& node, const std::vector<std::string>& parts,
                       std::size_t i = 0) {
  if (i == parts.size()) return node.IsScalar() ? node : YAML::Node(YAML::NodeType::Undefined);
  if (!node.IsMap() || parts[i].empty() || !node[parts[i]]) {
    return YAML::Node(YAML::NodeType::Undefined);
  }
  return find_scalar(node[parts[i]], parts, i + 1);
}

// True for a key of kOptionalAxleKeys under front or rear.
bool optional_key(const std::vector<std::string>& parts) {
  if (parts.size() != 2) return false;
  bool axle = false, key = false;
  for (const char* a : kAxles) axle = axle || parts[0] == a;
  for (const std::string_view k : kOptionalAxleKeys) key = key || parts[1] == k;
  return axle && key;
}

}  // namespace

bool half_car_has_key(const std::filesystem::path& path, const std::string& dotted_key) {
  YamlMap::load(path);  // the file's own errors first
  const YAML::Node root = YAML::LoadFile(path.string());
  const std::vector<std::string> parts = split_dotted(dotted_key);
  return find_scalar(root, parts).IsDefined() || optional_key(parts);
}

HalfCarFile load_half_car(const std::filesystem::path& path, const ModelOverrides& overrides) {
  const YamlMap file = YamlMap::load(path);
  if (!overrides.damper_state.empty()) {
    throw InputError(fmt::format(
        "{}: a half car has a damper state per axle; set front.damper_state or rear.damper_state "
        "({} damper_state={})",
        path.string(), overrides.origin, overrides.damper_state));
  }
  if (overrides.keys.empty()) return read_half_car(file);
  YAML::Node root = YAML::Clone(YAML::LoadFile(path.string()));
  for (const auto& [key, value] : overrides.keys) {
    if (key == "model") {
      throw InputError(fmt::format("'model': the model type cannot be replaced ({} model={})",
                                   overrides.origin, value));
    }
    const std::vector<std::string> parts = split_dotted(key);
    YAML::Node target = find_scalar(root, parts);
    if (target.IsDefined()) {
      target = value;
    } else if (optional_key(parts) && root[parts[0]].IsMap()) {
      YAML::Node axle = root[parts[0]];
      axle[parts[1]] = value;  // an optional key the file leaves at its default
    } else {
      throw InputError(
          fmt::format("'{}' is not a key of {}: use a dotted path to a key the file has, e.g. "
                      "front.{}, or an optional one such as front.{} ({} {}={})",
                      key, path.string(), axle_rows::damping_Ns_per_m.key,
                      axle_rows::compression_to_rebound_ratio.key, overrides.origin, key, value));
    }
  }
  try {
    return read_half_car(YamlMap(root, path, ""));
  } catch (const InputError& e) {
    throw InputError(with_override_named(e.what(), overrides));
  }
}

}  // namespace ridefit::io
