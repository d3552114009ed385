// `ridefit simulate` with a half-car model and `ridefit sweep`: smoke runs and bad input.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_runner.h"
#include "support/passat.h"

namespace ridefit {
namespace {

namespace fs = std::filesystem;
using testing::run_cli;

class HalfCarCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ridefit_halfcar_cli_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  std::string study(const std::string& extra) const {
    return write("study.yaml", "model: " + testing::dataset("vehicles/ajayi_half_car.yaml") +
                                   "\nroads:\n  smooth: " +
                                   testing::dataset("excitations/smooth_road_seed001.yaml") + "\n" +
                                   extra);
  }
  fs::path dir_;
};

TEST_F(HalfCarCli, SimulateWritesEveryChannel) {
  const fs::path out = dir_ / "run.csv";
  const auto run = run_cli("simulate " + testing::dataset("vehicles/ajayi_half_car.yaml") + " " +
                           testing::dataset("excitations/smooth_road_seed001.yaml") +
                           " --duration 3 --set front.suspension=strut -o " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::ifstream in(out);
  std::string header;
  std::getline(in, header);
  EXPECT_NE(header.find("seat_acc[m/s^2]"), std::string::npos) << header;
  EXPECT_NE(header.find("pitch_acc[rad/s^2]"), std::string::npos);
  EXPECT_NE(header.find("road_rear[m]"), std::string::npos);
  EXPECT_NE(run.output.find("rear delay 0.504 s"), std::string::npos) << run.output;
  const auto bad =
      run_cli("simulate " + testing::dataset("vehicles/ajayi_half_car.yaml") + " " +
              testing::dataset("excitations/smooth_road_seed001.yaml") + " --damper-state slip");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("front.damper_state"), std::string::npos) << bad.output;
  const auto sweep_road = run_cli("simulate " + testing::dataset("vehicles/ajayi_half_car.yaml") +
                                  " " + testing::dataset("excitations/sweep_2mm.yaml"));
  EXPECT_EQ(sweep_road.exit_code, 2);
  EXPECT_NE(sweep_road.output.find("--rear-delay"), std::string::npos) << sweep_road.output;
}

TEST_F(HalfCarCli, SweepWritesOneRowPerRunAndAFigure) {
  const fs::path out = dir_ / "results.csv";
  const fs::path plot = dir_ / "figure.png";
  const auto run = run_cli(
      "sweep " +
      study("speeds_km_per_h: [20, 60]\nvary:\n  - parameter: front.damping_Ns_per_m\n"
            "    values: [800, 1600]\nplot: {x: front.damping_Ns_per_m, series: speed_km_per_h, "
            "y: [seat_acc_wk_rms_m_per_s2]}\n") +
      " -o " + out.string() + " --plot " + plot.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::ifstream in(out);
  std::string line;
  int rows = -1;
  std::string header;
  std::getline(in, header);
  while (std::getline(in, line)) ++rows;
  EXPECT_EQ(rows + 1, 4);
  EXPECT_NE(header.find("front.damping[Ns/m]"), std::string::npos) << header;
  EXPECT_NE(header.find("seat_acc_wk_rms[m/s^2]"), std::string::npos) << header;
  EXPECT_GT(fs::file_size(plot), 1000u);
}

TEST_F(HalfCarCli, BadStudiesExitWith2AndWriteNothing) {
  const fs::path out = dir_ / "results.csv";
  for (const auto& [extra, words] : std::vector<std::pair<std::string, std::string>>{
           {"vary:\n  - parameter: front.stiffness\n    values: [1]\n", "not a key"},
           {"vary:\n  - parameter: front.damping_Ns_per_m\n    values: []\n", "non-empty"},
           {"speeds_km_per_h: [-20]\n", "not > 0"},
           {"vary:\n  - parameter: control.min_damping_Ns_per_m\n    values: [9000]\n",
            "c_min <= c_max"}}) {
    const auto run = run_cli("sweep " + study(extra) + " -o " + out.string());
    EXPECT_EQ(run.exit_code, 2) << extra << run.output;
    EXPECT_NE(run.output.find(words), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(out));
  }
}

}  // namespace
}  // namespace ridefit
