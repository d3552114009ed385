// The optional-effect keys of a quarter-car file: read when present, off when absent, and every
// bad value an InputError naming the key (and the range or the partner key it needs).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "ridefit/io/quarter_car_file.h"
#include "support/passat.h"
#include "support/throws_input_error.h"

namespace ridefit::io {
namespace {

namespace fs = std::filesystem;

class OptionalEffectsFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ridefit_effects_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // The Passat corner with `extra` lines appended.
  fs::path passat_with(const std::string& extra) const {
    std::ifstream in(testing::dataset("vehicles/passat_b8_front.yaml"));
    const fs::path path = dir_ / "passat.yaml";
    std::ofstream out(path);
    out << in.rdbuf() << "\n" << extra << "\n";
    return path;
  }
  model::QuarterCarParameters<double> load(const std::string& extra) const {
    return load_quarter_car(passat_with(extra)).parameters;
  }
  ::testing::AssertionResult rejects(const std::string& extra, const std::string& words) const {
    return testing::throws_input_error([&] { load_quarter_car(passat_with(extra)); }, words);
  }
  fs::path dir_;
};

TEST_F(OptionalEffectsFile, ReadsEveryKey) {
  const auto p = load(
      "top_mount_small_amplitude_stiffness_N_per_m: 707000\n"
      "top_mount_transition_deflection_m: 0.0002\n"
      "bump_stop_stiffness_N_per_m: 200000\n"
      "bump_stop_clearance_m: 0.03\n"
      "bump_stop_exponent: 3\n"
      "tyre_lift_off: true\n"
      "damper_knee_velocity_m_per_s: 0.1\n"
      "damping_above_knee_Ns_per_m: 300\n"
      "stribeck_velocity_m_per_s: 0.01\n"
      "static_friction_force_N: 90");
  EXPECT_EQ(p.top_mount_small_amplitude_stiffness_N_per_m, 707000.0);
  EXPECT_EQ(p.top_mount_transition_deflection_m, 0.0002);
  EXPECT_EQ(p.bump_stop_stiffness_N_per_m, 200000.0);
  EXPECT_EQ(p.bump_stop_clearance_m, 0.03);
  EXPECT_EQ(p.bump_stop_exponent, 3.0);
  EXPECT_TRUE(p.tyre_lift_off);
  EXPECT_EQ(p.damper_knee_velocity_m_per_s, 0.1);
  EXPECT_EQ(p.damping_above_knee_Ns_per_m, 300.0);
  EXPECT_EQ(p.stribeck_velocity_m_per_s, 0.01);
  EXPECT_EQ(p.static_friction_force_N, 90.0);
  // The rest of the file is unchanged.
  EXPECT_EQ(p.top_mount_stiffness_N_per_m, 488000.0);
  EXPECT_EQ(p.coulomb_force_N, 60.0);
}

TEST_F(OptionalEffectsFile, DefaultsWhenAbsentOrPartlyGiven) {
  const auto off = testing::passat_corner().parameters;
  EXPECT_EQ(off.top_mount_transition_deflection_m, 0.0);
  EXPECT_EQ(off.bump_stop_stiffness_N_per_m, 0.0);
  EXPECT_FALSE(off.tyre_lift_off);
  EXPECT_EQ(off.damper_knee_velocity_m_per_s, 0.0);
  EXPECT_EQ(off.stribeck_velocity_m_per_s, 0.0);
  // The bump stop's exponent defaults to 2; the static friction to coulomb_force_N.
  EXPECT_EQ(
      load("bump_stop_stiffness_N_per_m: 1e5\nbump_stop_clearance_m: 0.02").bump_stop_exponent,
      2.0);
  EXPECT_EQ(load("stribeck_velocity_m_per_s: 0.01").static_friction_force_N, 60.0);
  EXPECT_FALSE(load("tyre_lift_off: false").tyre_lift_off);
  EXPECT_TRUE(load("tyre_lift_off: 1").tyre_lift_off);
  EXPECT_FALSE(load("tyre_lift_off: 0").tyre_lift_off);
  // Equal small- and large-amplitude stiffness is allowed (a linear mount).
  EXPECT_EQ(load("top_mount_small_amplitude_stiffness_N_per_m: 488000\n"
                 "top_mount_transition_deflection_m: 0.001")
                .top_mount_small_amplitude_stiffness_N_per_m,
            488000.0);
}

TEST_F(OptionalEffectsFile, RejectsBadTopMountStiffening) {
  const std::string deflection = "top_mount_transition_deflection_m: 0.0002\n";
  const std::string stiffness = "top_mount_small_amplitude_stiffness_N_per_m: 707000\n";
  EXPECT_TRUE(rejects(deflection + "top_mount_small_amplitude_stiffness_N_per_m: 400000",
                      "key 'top_mount_small_amplitude_stiffness_N_per_m' is 400000, expected a "
                      "value in [488000, 1e+10] (at least top_mount_stiffness_N_per_m"));
  EXPECT_TRUE(rejects(deflection + "top_mount_small_amplitude_stiffness_N_per_m: stiff",
                      "key 'top_mount_small_amplitude_stiffness_N_per_m' is 'stiff', expected a "
                      "number"));
  EXPECT_TRUE(
      rejects(stiffness + "top_mount_transition_deflection_m: 0",
              "key 'top_mount_transition_deflection_m' is 0, expected a value > 0 and <= 1"));
  EXPECT_TRUE(rejects(stiffness + "top_mount_transition_deflection_m: -0.001",
                      "key 'top_mount_transition_deflection_m' is -0.001"));
  EXPECT_TRUE(rejects(stiffness,
                      "key 'top_mount_small_amplitude_stiffness_N_per_m' needs the key "
                      "'top_mount_transition_deflection_m' as well"));
  EXPECT_TRUE(rejects(deflection,
                      "key 'top_mount_transition_deflection_m' needs the key "
                      "'top_mount_small_amplitude_stiffness_N_per_m' as well"));
}

TEST_F(OptionalEffectsFile, RejectsBadBumpStop) {
  const std::string both = "bump_stop_stiffness_N_per_m: 1e5\nbump_stop_clearance_m: 0.02\n";
  EXPECT_TRUE(rejects("bump_stop_stiffness_N_per_m: -1e5\nbump_stop_clearance_m: 0.02",
                      "key 'bump_stop_stiffness_N_per_m' is -100000, expected a value > 0"));
  EXPECT_TRUE(rejects("bump_stop_stiffness_N_per_m: 1e5\nbump_stop_clearance_m: 0",
                      "key 'bump_stop_clearance_m' is 0, expected a value > 0 and <= 1"));
  EXPECT_TRUE(rejects("bump_stop_stiffness_N_per_m: 1e5\nbump_stop_clearance_m: 30",
                      "key 'bump_stop_clearance_m' is 30"));  // millimetres typed as metres
  EXPECT_TRUE(rejects(both + "bump_stop_exponent: 0.5",
                      "key 'bump_stop_exponent' is 0.5, expected a value in [1, 10]"));
  EXPECT_TRUE(rejects(both + "bump_stop_exponent: two",
                      "key 'bump_stop_exponent' is 'two', expected a number"));
  EXPECT_TRUE(rejects("bump_stop_exponent: 2",
                      "key 'bump_stop_exponent' needs the key 'bump_stop_stiffness_N_per_m'"));
  EXPECT_TRUE(rejects("bump_stop_stiffness_N_per_m: 1e5",
                      "key 'bump_stop_stiffness_N_per_m' needs the key 'bump_stop_clearance_m'"));
}

TEST_F(OptionalEffectsFile, RejectsBadTyreLiftOff) {
  EXPECT_TRUE(rejects("tyre_lift_off: maybe",
                      "key 'tyre_lift_off' is 'maybe', expected one of: 0, 1, false, true"));
  EXPECT_TRUE(rejects("tyre_lift_off: 2", "key 'tyre_lift_off' is '2'"));
}

TEST_F(OptionalEffectsFile, RejectsBadDamperKnee) {
  const std::string slope = "damping_above_knee_Ns_per_m: 300\n";
  const std::string knee = "damper_knee_velocity_m_per_s: 0.1\n";
  EXPECT_TRUE(rejects(slope + "damper_knee_velocity_m_per_s: 0",
                      "key 'damper_knee_velocity_m_per_s' is 0, expected a value > 0 and <= 10"));
  EXPECT_TRUE(rejects(slope + "damper_knee_velocity_m_per_s: -0.1",
                      "key 'damper_knee_velocity_m_per_s' is -0.1"));
  EXPECT_TRUE(rejects(knee + "damping_above_knee_Ns_per_m: 0",
                      "key 'damping_above_knee_Ns_per_m' is 0, expected a value > 0 and <= 886.9"));
  EXPECT_TRUE(rejects(knee + "damping_above_knee_Ns_per_m: 1000",
                      "key 'damping_above_knee_Ns_per_m' is 1000, expected a value > 0 and <= "
                      "886.9 (at most damping_Ns_per_m"));
  EXPECT_TRUE(rejects(knee + "damping_above_knee_Ns_per_m: soft",
                      "key 'damping_above_knee_Ns_per_m' is 'soft', expected a number"));
  EXPECT_TRUE(rejects(knee,
                      "key 'damper_knee_velocity_m_per_s' needs the key "
                      "'damping_above_knee_Ns_per_m' as well"));
}

TEST_F(OptionalEffectsFile, RejectsBadStribeckLevel) {
  EXPECT_TRUE(rejects("stribeck_velocity_m_per_s: 0",
                      "key 'stribeck_velocity_m_per_s' is 0, expected a value > 0 and <= 10"));
  EXPECT_TRUE(
      rejects("stribeck_velocity_m_per_s: -0.01", "key 'stribeck_velocity_m_per_s' is -0.01"));
  EXPECT_TRUE(rejects("stribeck_velocity_m_per_s: fast",
                      "key 'stribeck_velocity_m_per_s' is 'fast', expected a number"));
  EXPECT_TRUE(rejects("stribeck_velocity_m_per_s: 0.01\nstatic_friction_force_N: 50",
                      "key 'static_friction_force_N' is 50, expected a value in [60, 100000] (at "
                      "least coulomb_force_N"));
  EXPECT_TRUE(rejects("static_friction_force_N: 90",
                      "key 'static_friction_force_N' needs the key 'stribeck_velocity_m_per_s'"));
  // Without Dahl friction there is no level to shape.
  std::ifstream in(testing::dataset("vehicles/passat_b8_front.yaml"));
  const fs::path path = dir_ / "frictionless.yaml";
  std::ofstream out(path);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("damper_state", 0) == 0) line = "damper_state: slip";
    if (line.rfind("coulomb_force_N", 0) == 0) line = "coulomb_force_N: 0";
    out << line << "\n";
  }
  out << "stribeck_velocity_m_per_s: 0.01\n";
  out.close();
  EXPECT_TRUE(testing::throws_input_error(
      [&] { load_quarter_car(path); },
      "key 'stribeck_velocity_m_per_s' needs Dahl friction: coulomb_force_N > 0"));
}

// `--set` turns each effect on from the command line, tyre_lift_off as 1 or 0.
TEST_F(OptionalEffectsFile, OverridesSwitchEffectsOn) {
  const auto path = testing::dataset("vehicles/passat_b8_front.yaml");
  const auto p = load_quarter_car(path, {{"tyre_lift_off", 1.0},
                                         {"bump_stop_stiffness_N_per_m", 1e5},
                                         {"bump_stop_clearance_m", 0.02},
                                         {"damper_knee_velocity_m_per_s", 0.1},
                                         {"damping_above_knee_Ns_per_m", 300.0}})
                     .parameters;
  EXPECT_TRUE(p.tyre_lift_off);
  EXPECT_EQ(p.bump_stop_stiffness_N_per_m, 1e5);
  EXPECT_EQ(p.damping_above_knee_Ns_per_m, 300.0);
  EXPECT_FALSE(load_quarter_car(path, {{"tyre_lift_off", 0.0}}).parameters.tyre_lift_off);
  EXPECT_TRUE(testing::throws_input_error(
      [&] {
        load_quarter_car(path, {{"tyre_lift_off", 0.5}});
      },
      "key 'tyre_lift_off' is '0.5', expected one of: 0, 1, false, true (given as an override "
      "tyre_lift_off=0.5)"));
  EXPECT_TRUE(testing::throws_input_error(
      [&] {
        load_quarter_car(path, {{"stribeck_velocity_m_per_s", -1.0}});
      },
      "key 'stribeck_velocity_m_per_s' is -1"));
}

}  // namespace
}  // namespace ridefit::io
