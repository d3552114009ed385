// The parameter tables (model/*_parameter_table.h): well formed, the file readers' limits, and
// validate() for models edited in memory.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <initializer_list>
#include <map>
#include <set>
#include <string>

#include "ridefit/io/half_car_file.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/model/half_car_parameter_table.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/model/strut_test_parameter_table.h"
#include "support/input_error_message.h"
#include "support/passat.h"

namespace ridefit::model {
namespace {

using testing::dataset;

// design.md's unit suffixes: the unit column must say what the key's name says.
std::string unit_of_name(std::string_view key) {
  const std::pair<std::string_view, std::string_view> suffixes[] = {
      {"_N_per_m", "N/m"}, {"_Ns_per_m", "N*s/m"}, {"_kg_m2", "kg*m^2"}, {"_m_per_s", "m/s"},
      {"_kg", "kg"},       {"_Hz", "Hz"},          {"_N", "N"},          {"_s", "s"},
      {"_m", "m"}};
  for (const auto& [suffix, unit] : suffixes) {
    if (key.ends_with(suffix)) return std::string(unit);
  }
  return "1";
}

template <std::size_t N>
void expect_well_formed(const std::array<ParameterInfo, N>& rows) {
  std::set<std::string_view> keys;
  for (const auto& row : rows) {
    SCOPED_TRACE(std::string(row.key));
    EXPECT_TRUE(keys.insert(row.key).second) << "key listed twice";
    EXPECT_EQ(unit_of_name(row.key), row.unit);
    EXPECT_LT(row.lower, row.upper);
    EXPECT_FALSE(row.meaning.empty());
    EXPECT_TRUE(row.contains(row.upper));
    EXPECT_FALSE(row.contains(row.upper * 1.001 + 1e-9));
    EXPECT_EQ(row.contains(row.lower), !row.lower_open || (row.zero_is_off && row.lower == 0.0));
  }
}

TEST(ParameterTable, EveryRowHasAUniqueKeyItsUnitARangeAndAMeaning) {
  expect_well_formed(kQuarterCarParameters);
  expect_well_formed(kHalfCarBodyParameters);
  expect_well_formed(kSuspendedMassParameters);
  expect_well_formed(kControlParameters);
}

// Each named row (quarter_car_rows::coulomb_force_N, ...) is a row of its table whose key is its
// name, and every row has a name: a name bound to the wrong index would read another row.
template <std::size_t N>
void expect_named(const std::array<ParameterInfo, N>& table,
                  std::initializer_list<std::pair<const ParameterInfo*, std::string_view>> named) {
  EXPECT_EQ(named.size(), N) << "a row without a name";
  std::set<const ParameterInfo*> seen;
  for (const auto& entry : named) {  // (Clang 14 cannot capture a structured binding)
    const ParameterInfo* row = entry.first;
    const std::string_view key = entry.second;
    SCOPED_TRACE(std::string(key));
    EXPECT_TRUE(seen.insert(row).second) << "two names for one row";
    EXPECT_TRUE(std::any_of(table.begin(), table.end(), [&](const auto& r) { return &r == row; }))
        << "not a row of its table";
    EXPECT_EQ(row->key, key);
  }
}

TEST(ParameterTable, EachNamedRowIsTheRowOfItsKey) {
  expect_named(
      kQuarterCarParameters,
      {{&quarter_car_rows::sprung_mass_kg, "sprung_mass_kg"},
       {&quarter_car_rows::unsprung_mass_kg, "unsprung_mass_kg"},
       {&quarter_car_rows::tyre_stiffness_N_per_m, "tyre_stiffness_N_per_m"},
       {&quarter_car_rows::tyre_damping_Ns_per_m, "tyre_damping_Ns_per_m"},
       {&quarter_car_rows::spring_stiffness_N_per_m, "spring_stiffness_N_per_m"},
       {&quarter_car_rows::top_mount_spring_path_stiffness_N_per_m,
        "top_mount_spring_path_stiffness_N_per_m"},
       {&quarter_car_rows::top_mount_stiffness_N_per_m, "top_mount_stiffness_N_per_m"},
       {&quarter_car_rows::damping_Ns_per_m, "damping_Ns_per_m"},
       {&quarter_car_rows::dahl_sigma0_N_per_m, "dahl_sigma0_N_per_m"},
       {&quarter_car_rows::coulomb_force_N, "coulomb_force_N"},
       {&quarter_car_rows::dahl_exponent, "dahl_exponent"},
       {&quarter_car_rows::compression_to_rebound_ratio, "compression_to_rebound_ratio"},
       {&quarter_car_rows::top_mount_small_amplitude_stiffness_N_per_m,
        "top_mount_small_amplitude_stiffness_N_per_m"},
       {&quarter_car_rows::top_mount_transition_deflection_m, "top_mount_transition_deflection_m"},
       {&quarter_car_rows::bump_stop_stiffness_N_per_m, "bump_stop_stiffness_N_per_m"},
       {&quarter_car_rows::bump_stop_clearance_m, "bump_stop_clearance_m"},
       {&quarter_car_rows::bump_stop_exponent, "bump_stop_exponent"},
       {&quarter_car_rows::damper_knee_velocity_m_per_s, "damper_knee_velocity_m_per_s"},
       {&quarter_car_rows::damping_above_knee_Ns_per_m, "damping_above_knee_Ns_per_m"},
       {&quarter_car_rows::static_friction_force_N, "static_friction_force_N"},
       {&quarter_car_rows::stribeck_velocity_m_per_s, "stribeck_velocity_m_per_s"},
       {&quarter_car_rows::damping_per_command_Ns_per_m, "damping_per_command_Ns_per_m"},
       {&quarter_car_rows::coulomb_force_per_command_N, "coulomb_force_per_command_N"},
       {&quarter_car_rows::command_lag_s, "command_lag_s"},
       {&quarter_car_rows::body_acc_gain, "body_acc_gain"},
       {&quarter_car_rows::wheel_acc_gain, "wheel_acc_gain"},
       {&quarter_car_rows::acc_sensor_cutoff_Hz, "acc_sensor_cutoff_Hz"},
       {&quarter_car_rows::friction_compression_to_rebound_ratio,
        "friction_compression_to_rebound_ratio"},
       {&quarter_car_rows::free_play_m, "free_play_m"},
       {&quarter_car_rows::command_exponent, "command_exponent"},
       {&quarter_car_rows::free_play_damping_Ns_per_m, "free_play_damping_Ns_per_m"},
       {&quarter_car_rows::damping_above_knee_exponent, "damping_above_knee_exponent"}});
  expect_named(kHalfCarBodyParameters,
               {{&half_car_body_rows::body_mass_kg, "body_mass_kg"},
                {&half_car_body_rows::pitch_inertia_kg_m2, "pitch_inertia_kg_m2"},
                {&half_car_body_rows::front_axle_distance_m, "front_axle_distance_m"},
                {&half_car_body_rows::rear_axle_distance_m, "rear_axle_distance_m"},
                {&half_car_body_rows::seat_distance_m, "seat_distance_m"}});
  expect_named(kSuspendedMassParameters,
               {{&suspended_mass_rows::mass_kg, "mass_kg"},
                {&suspended_mass_rows::stiffness_N_per_m, "stiffness_N_per_m"},
                {&suspended_mass_rows::damping_Ns_per_m, "damping_Ns_per_m"}});
  expect_named(kControlParameters,
               {{&control_rows::min_damping_Ns_per_m, "min_damping_Ns_per_m"},
                {&control_rows::max_damping_Ns_per_m, "max_damping_Ns_per_m"},
                {&control_rows::skyhook_damping_Ns_per_m, "skyhook_damping_Ns_per_m"},
                {&control_rows::groundhook_damping_Ns_per_m, "groundhook_damping_Ns_per_m"},
                {&control_rows::skyhook_share, "skyhook_share"}});
  expect_named(kStrutRigParameters,
               {{&strut_rig_rows::gas_force_N, "gas_force_N"},
                {&strut_rig_rows::gas_stiffness_N_per_m, "gas_stiffness_N_per_m"},
                {&strut_rig_rows::force_offset_N, "force_offset_N"},
                {&strut_rig_rows::force_gain, "force_gain"},
                {&strut_rig_rows::force_delay_s, "force_delay_s"},
                {&strut_rig_rows::force_sensor_cutoff_Hz, "force_sensor_cutoff_Hz"},
                {&strut_rig_rows::moving_mass_kg, "moving_mass_kg"}});
  EXPECT_EQ(quarter_car_row_index(quarter_car_rows::coulomb_force_N),
            quarter_car_parameter_index("coulomb_force_N").value_or(kQuarterCarParameters.size()));
}

// A lone key of an optional effect needs its partner in a file; these make each row readable.
std::map<std::string, double> partners(std::string_view key) {
  if (key == "top_mount_small_amplitude_stiffness_N_per_m")
    return {{"top_mount_transition_deflection_m", 2e-4}};
  if (key == "top_mount_transition_deflection_m")
    return {{"top_mount_small_amplitude_stiffness_N_per_m", 707000}};
  if (key == "bump_stop_stiffness_N_per_m") return {{"bump_stop_clearance_m", 0.03}};
  if (key == "bump_stop_clearance_m" || key == "bump_stop_exponent")
    return {{"bump_stop_stiffness_N_per_m", 2e5}, {"bump_stop_clearance_m", 0.03}};
  if (key == "damper_knee_velocity_m_per_s") return {{"damping_above_knee_Ns_per_m", 300}};
  if (key == "damping_above_knee_Ns_per_m") return {{"damper_knee_velocity_m_per_s", 0.1}};
  if (key == "static_friction_force_N") return {{"stribeck_velocity_m_per_s", 0.01}};
  return {};
}

// Just above each row's upper limit: the file reader and validate() both refuse it and name the
// key; so the reader's limits are the table's.
TEST(ParameterTable, TheQuarterCarReaderAndValidateRefuseWhatTheTableRefuses) {
  const std::string file = dataset("vehicles/passat_b8_front.yaml");
  const auto base = io::load_quarter_car(file).parameters;
  ASSERT_FALSE(validate(base).has_value());
  for (std::size_t i = 0; i < kQuarterCarParameters.size(); ++i) {
    const ParameterInfo& row = kQuarterCarParameters[i];
    SCOPED_TRACE(std::string(row.key));
    const double above = row.upper * 1.5;
    auto overrides = partners(row.key);
    overrides[std::string(row.key)] = above;
    io::ModelOverrides given;
    for (const auto& [key, value] : overrides) given.set(key, value);
    const std::string message =
        testing::input_error_message([&] { io::load_quarter_car(file, given); });
    EXPECT_NE(message.find(std::string(row.key)), std::string::npos) << message;
    // The limit in the reader's wording ({:g} or {}); c_h's rule, <= c_r, is tighter than its row.
    if (row.key != "damping_above_knee_Ns_per_m") {
      EXPECT_TRUE(message.find(fmt::format("{:g}", row.upper)) != std::string::npos ||
                  message.find(fmt::format("{}", row.upper)) != std::string::npos)
          << message;
    }
    auto p = base;
    for (const auto& [key, value] : partners(row.key)) {
      set_quarter_car_parameter(p, *quarter_car_parameter_index(key), value);
    }
    set_quarter_car_parameter(p, i, above);  // ranges are checked before the pairs' rules
    const auto error = validate(p);
    ASSERT_TRUE(error.has_value());
    EXPECT_EQ(error->key, row.key);
  }
}

TEST(ParameterTable, ValidateKeepsTheRulesBetweenParameters) {
  auto p = io::load_quarter_car(dataset("vehicles/passat_b8_front.yaml")).parameters;
  auto with = [&](std::string_view key, double value) {
    auto q = p;
    set_quarter_car_parameter(q, *quarter_car_parameter_index(key), value);
    return q;
  };
  // One key of a pair alone.
  auto error = validate(with("bump_stop_stiffness_N_per_m", 2e5));
  ASSERT_TRUE(error);
  EXPECT_NE(error->message.find("bump_stop_clearance_m"), std::string::npos) << error->text();
  // k_s below k_l.
  auto q = with("top_mount_transition_deflection_m", 2e-4);
  set_quarter_car_parameter(
      q, *quarter_car_parameter_index("top_mount_small_amplitude_stiffness_N_per_m"),
      0.5 * q.top_mount_stiffness_N_per_m);
  error = validate(q);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->key, "top_mount_small_amplitude_stiffness_N_per_m");
  // A progressive knee.
  q = with("damper_knee_velocity_m_per_s", 0.1);
  set_quarter_car_parameter(q, *quarter_car_parameter_index("damping_above_knee_Ns_per_m"),
                            2.0 * q.damping_Ns_per_m);
  error = validate(q);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->key, "damping_above_knee_Ns_per_m");
  // Stribeck without Dahl friction.
  q = with("coulomb_force_N", 0.0);
  set_quarter_car_parameter(q, *quarter_car_parameter_index("stribeck_velocity_m_per_s"), 0.01);
  error = validate(q);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->key, "stribeck_velocity_m_per_s");
}

// Fs = Fc is the reader's default: a flat Stribeck curve stays flat when Fc changes, as a file
// that gives only coulomb_force_N would read.
TEST(ParameterTable, TheBreakawayForceFollowsTheCoulombForceWhileTheyAreEqual) {
  const std::string file = dataset("vehicles/passat_b8_front.yaml");
  auto p = io::load_quarter_car(file, {{"stribeck_velocity_m_per_s", 0.01}}).parameters;
  set_quarter_car_parameter(p, *quarter_car_parameter_index("coulomb_force_N"), 90.0);
  const auto read =
      io::load_quarter_car(file, {{"stribeck_velocity_m_per_s", 0.01}, {"coulomb_force_N", 90.0}})
          .parameters;
  EXPECT_EQ(p.static_friction_force_N, read.static_friction_force_N);
  EXPECT_EQ(p.static_friction_force_N, 90.0);
  EXPECT_FALSE(validate(p).has_value());
}

TEST(ParameterTable, HalfCarDottedKeysReachTheirFieldsAndValidateNamesThem) {
  const auto file = io::load_half_car(dataset("vehicles/ajayi_half_car.yaml"));
  auto p = file.parameters;
  auto topology = file.topology;
  ASSERT_FALSE(validate(p, topology).has_value()) << validate(p, topology)->text();
  const auto field = half_car_field(p, topology.control, "rear.damping_Ns_per_m");
  ASSERT_TRUE(field.has_value());
  EXPECT_EQ(field->value, &p.rear.damping_Ns_per_m);
  EXPECT_EQ(half_car_field(p, topology.control, "seat.mass_kg")->value, &p.seat.mass_kg);
  EXPECT_EQ(half_car_field(p, topology.control, "pitch_inertia_kg_m2")->value,
            &p.pitch_inertia_kg_m2);
  EXPECT_EQ(half_car_field(p, topology.control, "control.skyhook_share")->value,
            &topology.control.skyhook_share);
  EXPECT_FALSE(half_car_field(p, topology.control, "front.sprung_mass_kg"));  // quarter car only
  EXPECT_FALSE(half_car_field(p, topology.control, "middle.damping_Ns_per_m"));
  *half_car_field(p, topology.control, "lower_body.stiffness_N_per_m")->value = -1.0;
  const auto error = validate(p, topology);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->key, "lower_body.stiffness_N_per_m");
  // Every dotted key the reader refuses above the row's limit.
  const std::string message = testing::input_error_message([&] {
    io::load_half_car(dataset("vehicles/ajayi_half_car.yaml"), {{"front.coulomb_force_N", "2e5"}});
  });
  EXPECT_NE(message.find("100000"), std::string::npos) << message;
}

}  // namespace
}  // namespace ridefit::model
