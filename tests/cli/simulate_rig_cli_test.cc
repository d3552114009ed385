// `ridefit simulate-rig`: a rig test run on a model's strut, written as a record the fits read;
// bad input is exit 2 with nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "ridefit/fitting/hysteresis_record.h"
#include "support/cli_runner.h"
#include "support/passat.h"
#include "support/temp_dir.h"

namespace ridefit {
namespace {

namespace fs = std::filesystem;
using testing::CliRun;
using testing::run_cli;

const char* const kSine =
    "waveform: sine\namplitude_m: 0.01\nfrequency_Hz: 2\nduration_s: 3\nsample_rate_Hz: 500\n";

TEST(SimulateRigCli, WritesARecordTheFitsRead) {
  testing::TempDir dir("simulate_rig_cli");
  const std::string test = dir.write("sine.yaml", kSine);
  const fs::path record = dir.path() / "record.csv";
  const std::string model = testing::dataset("vehicles/passat_b8_front.yaml");
  const CliRun run = run_cli("simulate-rig " + model + " " + test + " -o " + record.string() +
                             " --set force_offset_N=2.5 --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto summary = nlohmann::json::parse(run.output);
  EXPECT_EQ(summary.at("samples").get<int>(), 1500);
  EXPECT_NEAR(summary.at("peak_velocity_m_per_s").get<double>(), 0.04 * 3.14159265358979, 1e-9);
  const fitting::HysteresisRecord r = fitting::load_hysteresis_record(record);
  ASSERT_EQ(r.time_s.size(), 1500u);
  EXPECT_EQ(r.velocity_m_per_s.size(), 1500u);  // the actuator's rate, for the fits
  EXPECT_NEAR(r.displacement_m[100], 0.01 * std::sin(0.8 * std::numbers::pi), 1e-12);  // 0.2 s
  EXPECT_NEAR(r.force_N.front(), 2.5, 1e-9);  // at rest: the load cell's offset
  EXPECT_NEAR(summary.at("peak_force_N").get<double>(), 171.0, 30.0);  // c·v_max + Fc + k·x
}

TEST(SimulateRigCli, ShippedTestsRunOnThePassatStrut) {
  testing::TempDir dir("simulate_rig_cli_shipped");
  const std::string model = testing::dataset("vehicles/passat_b8_front.yaml");
  for (const char* name :
       {"sine_10mm_2hz.yaml", "triangle_3mm_1mmps.yaml", "random_2mm_0p5_20hz.yaml"}) {
    const fs::path record = dir.path() / (std::string(name) + ".csv");
    const CliRun run =
        run_cli("simulate-rig " + model + " " + testing::dataset(std::string("rig_tests/") + name) +
                " -o " + record.string());
    ASSERT_EQ(run.exit_code, 0) << name << "\n" << run.output;
    EXPECT_GT(fitting::load_hysteresis_record(record).time_s.size(), 4000u) << name;
  }
}

TEST(SimulateRigCli, BadInputIsExitTwoWithNothingWritten) {
  testing::TempDir dir("simulate_rig_cli_bad");
  const std::string model = testing::dataset("vehicles/passat_b8_front.yaml");
  const std::string good = dir.write("sine.yaml", kSine);
  const std::string far =
      dir.write("far.yaml", "waveform: sine\namplitude_m: 0.08\nfrequency_Hz: 1\nduration_s: 2\n");
  const std::string strong = dir.write(
      "strong.yaml",
      "waveform: sine\namplitude_m: 0.02\nfrequency_Hz: 10\nduration_s: 1\nrig: {force_N: 400}\n");
  const std::string rig = dir.write("rig.yaml", "stroke_m: 0.005\n");
  const fs::path out = dir.path() / "out.csv";
  const struct {
    std::string arguments;
    std::string words;
  } cases[] = {
      {model + " " + far, "far.yaml: amplitude_m: the test reaches ±80 mm, beyond the rig's"},
      {model + " " + strong, "strong.yaml: the sine test needs"},
      {model + " " + good + " --rig " + rig, "sine.yaml: amplitude_m: the test reaches ±10 mm"},
      {model + " " + good + " --set free_play_m=-1", "--set free_play_m=-1: give 0 (off)"},
      {model + " " + good + " --set force_offset=1", "'force_offset' is not a strut-test"},
      {model + " " + good + " --set damping_Ns_per_m=x", "'x' is not a finite number"},
      {testing::dataset("vehicles/ajayi_half_car.yaml") + " " + good, "give a quarter-car model"},
  };
  for (const auto& c : cases) {
    const CliRun run = run_cli("simulate-rig " + c.arguments + " -o " + out.string());
    EXPECT_EQ(run.exit_code, 2) << c.arguments << "\n" << run.output;
    EXPECT_NE(run.output.find(c.words), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(out)) << c.arguments;
  }
  const CliRun self = run_cli("simulate-rig " + model + " " + good + " -o " + good);
  EXPECT_EQ(self.exit_code, 2) << self.output;
  EXPECT_NE(self.output.find("is also an input of this run"), std::string::npos) << self.output;
}

}  // namespace
}  // namespace ridefit
