// Smoke tests of every subcommand and the bad-input contract: a clear message, exit code 2
// and no output file.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_runner.h"
#include "support/passat.h"

namespace ridefit {
namespace {

namespace fs = std::filesystem;

using testing::CliRun;
using testing::run_cli;

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ridefit_cli_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) const {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path.string();
  }
  std::string model() const { return testing::dataset("vehicles/passat_b8_front.yaml"); }
  std::string short_sweep() const {
    return write("sweep.yaml", "type: log_sweep\ninitial_amplitude_m: 0.002\nduration_s: 2\n");
  }
  // A copy of the Passat file with one line replaced (or removed when `line` is empty).
  std::string model_with(const std::string& key, const std::string& line) const {
    std::ifstream in(model());
    std::string text, l;
    while (std::getline(in, l)) {
      if (l.rfind(key + ":", 0) == 0) {
        if (!line.empty()) text += line + "\n";
      } else {
        text += l + "\n";
      }
    }
    return write("model.yaml", text);
  }
  void expect_bad_input(const std::string& arguments, const std::string& must_mention) {
    const fs::path out = dir_ / "out.csv";
    const CliRun run = run_cli(arguments + " -o " + out.string());
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find(must_mention), std::string::npos)
        << "message should mention '" << must_mention << "':\n"
        << run.output;
    EXPECT_FALSE(fs::exists(out)) << "no output file on bad input";
  }

  fs::path dir_;
};

TEST_F(Cli, HelpOnEveryLevel) {
  for (const std::string level : {"", "modes ", "simulate ", "friction-study "}) {
    const CliRun run = run_cli(level + "--help");
    EXPECT_EQ(run.exit_code, 0) << level;
    EXPECT_NE(run.output.find("Usage"), std::string::npos) << level;
  }
}

TEST_F(Cli, ModesPrintsTheFourSeedFrequencies) {
  const CliRun run = run_cli("modes " + model() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("\"slip\""), std::string::npos);
  EXPECT_NE(run.output.find("\"stick\""), std::string::npos);
  EXPECT_NE(run.output.find("natural_frequency_Hz"), std::string::npos);
  const CliRun text = run_cli("modes " + model() + " --state stick");
  ASSERT_EQ(text.exit_code, 0);
  EXPECT_NE(text.output.find("3.4"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("21.4"), std::string::npos) << text.output;
}

// The half car's modes: one linear model for passive axles, slip and stick for a strut axle; a
// --state for a car without struts is refused before anything is printed.
TEST_F(Cli, ModesOfTheHalfCar) {
  const std::string half_car = testing::dataset("vehicles/ajayi_half_car.yaml");
  const CliRun run = run_cli("modes " + half_car + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto j = nlohmann::json::parse(run.output);
  ASSERT_TRUE(j["states"].contains("passive")) << run.output;
  EXPECT_EQ(j["states"]["passive"]["modes"].size(), 7u);
  EXPECT_NE(run.output.find("\"front_wheel\""), std::string::npos);
  // The file's front axle as seed 000's strut (its stick/slip state set to slip, then stick).
  const CliRun struts = run_cli("modes " + half_car + " --set front.suspension=strut");
  ASSERT_EQ(struts.exit_code, 0) << struts.output;
  EXPECT_NE(struts.output.find("slip "), std::string::npos) << struts.output;
  EXPECT_NE(struts.output.find("stick "), std::string::npos) << struts.output;
  EXPECT_NE(struts.output.find("pitch"), std::string::npos) << struts.output;
  const CliRun refused = run_cli("modes " + half_car + " --state stick");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.output.find("passive axles only"), std::string::npos) << refused.output;
  EXPECT_EQ(refused.output.find("natural"), std::string::npos) << refused.output;
}

TEST_F(Cli, SimulateWritesUnitAnnotatedCsvAndJsonStatistics) {
  const fs::path out = dir_ / "run.csv";
  const CliRun run = run_cli("simulate " + model() + " " + short_sweep() + " -o " + out.string() +
                             " --rate 200 --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("\"steps\""), std::string::npos);
  EXPECT_NE(run.output.find("body_acc_m_per_s2"), std::string::npos);
  std::ifstream in(out);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header,
            "time[s],road[m],body_acc[m/s^2],wheel_acc[m/s^2],travel[m],tyre_force[N],"
            "damper_force[N],friction_force[N],top_mount_deflection[m],stuck[1]");
  std::size_t rows = 0;
  std::string line;
  while (std::getline(in, line)) ++rows;
  EXPECT_EQ(rows, 401u);  // 2 s at 200 Hz, both ends
}

TEST_F(Cli, FrictionStudyRunsAndWritesPsds) {
  const CliRun run = run_cli("friction-study " + model() + " " + short_sweep() +
                             " --coulomb-forces 0,60 --rate 200 -o " + (dir_ / "out").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "sweep_psd.csv"));
  // dir_ holds the inputs (files ridefit did not write there): refused without --force, and
  // with it the inputs stay beside the PSDs.
  const CliRun beside = run_cli("friction-study " + model() + " " + short_sweep() +
                                " --coulomb-forces 0,60 --rate 200 -o " + dir_.string());
  EXPECT_EQ(beside.exit_code, 2) << beside.output;
  const CliRun forced = run_cli("friction-study " + model() + " " + short_sweep() +
                                " --coulomb-forces 0,60 --rate 200 --force -o " + dir_.string());
  ASSERT_EQ(forced.exit_code, 0) << forced.output;
  EXPECT_TRUE(fs::exists(dir_ / "sweep_psd.csv"));
  EXPECT_TRUE(fs::exists(short_sweep()));
  EXPECT_NE(run.output.find("body_pk"), std::string::npos);
}

TEST_F(Cli, MissingKeyIsNamed) {
  expect_bad_input("simulate " + model_with("sprung_mass_kg", "") + " " + short_sweep(),
                   "sprung_mass_kg");
}

TEST_F(Cli, UnknownKeyIsNamed) {
  expect_bad_input("simulate " +
                       model_with("damping_Ns_per_m", "damping_Ns_per_m: 887\ndampnig: 3") + " " +
                       short_sweep(),
                   "dampnig");
}

TEST_F(Cli, NonPositiveMassIsRejected) {
  expect_bad_input(
      "simulate " + model_with("sprung_mass_kg", "sprung_mass_kg: -385") + " " + short_sweep(),
      "sprung_mass_kg");
  expect_bad_input(
      "simulate " + model_with("unsprung_mass_kg", "unsprung_mass_kg: 0") + " " + short_sweep(),
      "unsprung_mass_kg");
}

TEST_F(Cli, TextWhereANumberBelongsIsRejected) {
  expect_bad_input("simulate " +
                       model_with("tyre_stiffness_N_per_m", "tyre_stiffness_N_per_m: stiff") + " " +
                       short_sweep(),
                   "tyre_stiffness_N_per_m");
}

TEST_F(Cli, BadExcitationAndFlagsAreRejected) {
  expect_bad_input("simulate " + model() + " " + write("e.yaml", "type: warp_drive\n"), "type");
  expect_bad_input("simulate " + model() + " " + short_sweep() + " --set coulomb_force_N=abc",
                   "coulomb_force_N");
  expect_bad_input("simulate " + model() + " " + short_sweep() + " --rate -5", "rate");
  expect_bad_input("simulate " + model() + " /nonexistent/exc.yaml", "exc.yaml");
}

// A measured record with a coil current: a controlled damper follows it (its filtered command is
// written), a passive model says it ignores it, and a controlled model on a road without one says
// it runs at command 0.
TEST_F(Cli, SimulateFollowsTheRecordsDamperCommand) {
  std::string csv = "time[s],road[mm],current[mA]\n";
  for (int k = 0; k <= 400; ++k) {
    csv += std::to_string(0.005 * k) + "," + std::to_string(2.0 * std::sin(0.1 * k)) + "," +
           (k < 200 ? "0" : "1500") + "\n";
  }
  write("drive.csv", csv);
  const std::string excitation = write("drive.yaml", "type: measured\nfile: drive.csv\n");
  const std::string controlled = model_with(
      "dahl_exponent", "dahl_exponent: 1\ndamping_per_command_Ns_per_m: 800\ncommand_lag_s: 0.015");
  const fs::path out = dir_ / "run.csv";
  CliRun run =
      run_cli("simulate " + controlled + " " + excitation + " --rate 200 -o " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::ifstream in(out);
  std::string header, line, last;
  std::getline(in, header);
  EXPECT_NE(header.find(",damper_command[A]"), std::string::npos) << header;
  while (std::getline(in, line)) last = line;
  // 1.5 A held for 1 s against a 15 ms lag: the filtered command has arrived.
  EXPECT_NEAR(std::stod(last.substr(last.rfind(',') + 1)), 1.5, 1e-6) << last;

  run = run_cli("simulate " + model() + " " + excitation + " --rate 200");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("the damper stays passive"), std::string::npos) << run.output;
  run = run_cli("simulate " + controlled + " " + short_sweep() + " --rate 200");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("runs at command 0"), std::string::npos) << run.output;
}

TEST_F(Cli, BadMeasuredRoadCsvIsRejectedWithoutOutput) {
  const std::string yaml_header = "type: measured\nfile: ";
  const auto measured = [&](const std::string& csv_name, const std::string& csv) {
    write(csv_name, csv);
    return write(csv_name + ".yaml", yaml_header + csv_name + "\n");
  };
  expect_bad_input("simulate " + model() + " " + measured("empty.csv", ""), "empty.csv");
  expect_bad_input(
      "simulate " + model() + " " + measured("nounit.csv", "time,road[m]\n0,0\n0.1,0\n"),
      "nounit.csv");
  expect_bad_input(
      "simulate " + model() + " " + measured("unit.csv", "time[s],road[furlong]\n0,0\n0.1,0\n"),
      "furlong");
  expect_bad_input("simulate " + model() + " " +
                       measured("time.csv", "time[s],road[m]\n0,0\n0.1,0\n0.1,0\n0.05,0\n"),
                   "time.csv");
  expect_bad_input(
      "simulate " + model() + " " + measured("bad.csv", "time[s],road[m]\n0,0\n0.1,x\n"),
      "bad.csv");
}

TEST_F(Cli, FailedRunKeepsAnExistingOutput) {
  // An unstable fixed step fails (exit 1) and must not replace a good file.
  const fs::path out = dir_ / "keep.csv";
  std::ofstream(out) << "precious\n";
  const CliRun run = run_cli("simulate " + model() + " " + short_sweep() +
                             " --method rk4 --rate 100 --step 0.005 -o " + out.string());
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("failed at t ="), std::string::npos) << run.output;
  std::ifstream in(out);
  std::string content;
  std::getline(in, content);
  EXPECT_EQ(content, "precious");
}

TEST_F(Cli, OutputThatCannotBeWrittenIsRefusedBeforeRunning) {
  const CliRun into_directory =
      run_cli("simulate " + model() + " " + short_sweep() + " -o " + dir_.string());
  EXPECT_EQ(into_directory.exit_code, 2) << into_directory.output;
  EXPECT_NE(into_directory.output.find("is a directory"), std::string::npos);
  const std::string victim = model_with("coulomb_force_N", "coulomb_force_N: 60");
  const CliRun onto_input = run_cli("simulate " + victim + " " + short_sweep() + " -o " + victim);
  EXPECT_EQ(onto_input.exit_code, 2) << onto_input.output;
  EXPECT_NE(onto_input.output.find("also an input"), std::string::npos);
  std::ifstream in(victim);
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first.rfind("#", 0), 0u) << "the model file must be untouched";
}

TEST_F(Cli, DuplicateKeysAndBadDamperStateAreRejectedEverywhere) {
  expect_bad_input("simulate " +
                       model_with("sprung_mass_kg", "sprung_mass_kg: 385\nsprung_mass_kg: 100") +
                       " " + short_sweep(),
                   "duplicate key 'sprung_mass_kg'");
  const CliRun modes = run_cli("modes " + model_with("damper_state", "damper_state: stick-slip"));
  EXPECT_EQ(modes.exit_code, 2) << modes.output;
  EXPECT_NE(modes.output.find("damper_state"), std::string::npos) << modes.output;
}

TEST_F(Cli, MessagesNameTheFlagThatWasWrong) {
  expect_bad_input("simulate " + model() + " " + short_sweep() + " --set sprung_mass_kg=-3",
                   "--set sprung_mass_kg");
  expect_bad_input("simulate " + model() + " " + short_sweep() + " --rate 0",
                   "expected a finite number > 0");
  expect_bad_input("simulate " + model() + " " + short_sweep() + " --duration 5",
                   "longer than the excitation");
  expect_bad_input("simulate " + model() + " " + short_sweep() + " --rate 1e9", "output samples");
  expect_bad_input("simulate " + model() + " " + short_sweep() + " --method rk4 --step 0.01",
                   "longer than the output interval");
}

TEST_F(Cli, FrictionStudyChecksEveryExcitationBeforeRunning) {
  const std::string bad = write("bad.yaml", "type: log_sweep\ninitial_amplitude_m: 0\n");
  const fs::path out = dir_ / "study";
  const CliRun run = run_cli("friction-study " + model() + " " + short_sweep() + " " + bad +
                             " --rate 200 -o " + out.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_FALSE(fs::exists(out / "sweep_psd.csv")) << "no partial results on bad input";
  const CliRun inf =
      run_cli("friction-study " + model() + " " + short_sweep() + " --coulomb-forces 0,inf");
  EXPECT_EQ(inf.exit_code, 2) << inf.output;
}

}  // namespace
}  // namespace ridefit
