// A rig record whose displacement comes from a coarse encoder sampled fast: 10 µm steps at
// 2 kHz on a slow 0.5 Hz, 10 mm sine, where a spline through the staircase makes the damper feel
// velocity spikes of a quarter of the peak velocity (q·fs/√6 = 8.2 mm/s RMS against 31 mm/s).
// The force is made by CVODE at rtol 1e-10 on the exact motion; smooth_quantised_displacement
// (fitting/quantised_displacement.h) low-passes the quantised displacement and the fit, from away
// from the truth, recovers the strut from the low-passed record; the same record left as a
// staircase (the loaders' default) does not. The report says what a low-pass would cost and gain.
#include "ridefit/fitting/quantised_displacement.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "ridefit/fitting/hysteresis_fit.h"
#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/fitting/strut_start.h"
#include "ridefit/io/csv_table.h"
#include "ridefit/synthetic/reference_rig_record.h"
#include "support/cli_runner.h"
#include "support/fitted_value.h"
#include "support/temp_dir.h"

namespace ridefit::fitting {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kStep = 10e-6;

model::StrutTestParameters<double> truth() {
  model::StrutTestParameters<double> p{};
  p.dahl_sigma0_N_per_m = 2.0e6;
  p.coulomb_force_N = 150.0;
  p.top_mount_stiffness_N_per_m = 3.0e6;
  p.damping_Ns_per_m = 4000.0;
  return p;
}

// The record as the encoder wrote it, in a CSV.
std::string coarse_encoder_file(const testing::TempDir& dir) {
  auto x = [](double t) { return 0.01 * std::sin(2 * kPi * 0.5 * t); };
  const auto grid = synthetic::sample_times(4 * 2000 + 1, 2000.0);
  const HysteresisRecord exact = synthetic::reference_rig_record(grid, x, truth(), {}, "exact");
  std::vector<double> quantised;
  for (double v : exact.displacement_m) quantised.push_back(kStep * std::round(v / kStep));
  const std::string path = (dir.path() / "coarse_encoder.csv").string();
  io::CsvTable table(path);
  table.add("time", "s", exact.time_s);
  table.add("displacement", "m", quantised);
  table.add("force", "N", exact.force_N);
  table.write(path);
  return path;
}

HysteresisFitResult fit(const HysteresisRecord& record) {
  auto start = truth();
  start.dahl_sigma0_N_per_m = 5.0e6;
  start.coulomb_force_N = 90.0;
  start.damping_Ns_per_m = 2500.0;
  HysteresisFitOptions options;
  options.free = {"dahl_sigma0_N_per_m", "coulomb_force_N", "damping_Ns_per_m"};
  return fit_hysteresis(std::vector<HysteresisRecord>{record}, start, options);
}

TEST(HysteresisFit, QuantisedDisplacementIsLowPassedBeforeItDrivesTheFit) {
  const testing::TempDir dir("quantised_displacement");
  const std::string path = coarse_encoder_file(dir);
  // The loader examines the record and leaves it as it is.
  const HysteresisRecord staircase = load_hysteresis_record(path);
  ASSERT_TRUE(staircase.displacement_low_pass.has_value());
  EXPECT_FALSE(staircase.displacement_low_passed);
  EXPECT_EQ(staircase.displacement_m, io::CsvTable::read(path).column("displacement").values);
  const auto& treatment = *staircase.displacement_low_pass;
  EXPECT_NEAR(treatment.step, kStep, 1e-9);
  ASSERT_GT(treatment.cutoff_Hz, 0.5) << treatment.reason;
  EXPECT_LT(treatment.cutoff_Hz, 50.0);
  HysteresisRecord smoothed = staircase;
  smooth_quantised_displacement(smoothed);
  EXPECT_TRUE(smoothed.displacement_low_passed);
  const std::vector<double> once = smoothed.displacement_m;
  smooth_quantised_displacement(smoothed);  // applied once
  EXPECT_EQ(smoothed.displacement_m, once);

  const auto with = fit(smoothed), without = fit(staircase);
  ASSERT_TRUE(with.converged) << with.termination;
  EXPECT_NEAR(testing::fitted_value(with, "damping_Ns_per_m"), 4000.0, 0.02 * 4000.0);
  EXPECT_NEAR(testing::fitted_value(with, "coulomb_force_N"), 150.0, 0.05 * 150.0);
  EXPECT_LT(with.nrmse_percent, 1.0);
  // The staircase's spikes cost the fit: measured NRMSE and damping error several times larger.
  EXPECT_GT(without.nrmse_percent, 2.0 * with.nrmse_percent);
  RecordProperty("nrmse_smoothed_percent", std::to_string(with.nrmse_percent));
  RecordProperty("nrmse_staircase_percent", std::to_string(without.nrmse_percent));
  RecordProperty("damping_smoothed",
                 std::to_string(testing::fitted_value(with, "damping_Ns_per_m")));
  RecordProperty("damping_staircase",
                 std::to_string(testing::fitted_value(without, "damping_Ns_per_m")));
}

TEST(QuantisedDisplacementCli, ReportSaysHowAndWhatItCosts) {
  const testing::TempDir dir("quantised_displacement_cli");
  const std::string path = coarse_encoder_file(dir);
  const auto text = testing::run_cli("fit hysteresis " + path +
                                     " --model " RIDEFIT_SOURCE_DIR
                                     "/datasets/lab/mr_strut_passive.yaml --free "
                                     "coulomb_force_N,damping_Ns_per_m --keep");
  ASSERT_NE(text.exit_code, 2) << text.output;  // 1: the passive data sheet's verdict
  EXPECT_NE(text.output.find("displacement quantised in 10 µm steps: velocity noise of the steps"),
            std::string::npos)
      << text.output;
  const auto json = testing::run_cli("fit hysteresis " + path +
                                     " --model " RIDEFIT_SOURCE_DIR
                                     "/datasets/lab/mr_strut_passive.yaml --free "
                                     "coulomb_force_N,damping_Ns_per_m --keep --json");
  ASSERT_NE(json.exit_code, 2) << json.output;
  // The JSON document, then the verdict on stderr.
  const std::size_t open = json.output.find('{'), close = json.output.find("\n}\n");
  ASSERT_NE(close, std::string::npos) << json.output;
  const auto j = nlohmann::json::parse(json.output.substr(open, close + 2 - open));
  ASSERT_EQ(j.at("displacement_treatment").size(), 1u);
  const auto& t = j.at("displacement_treatment")[0];
  EXPECT_NEAR(t.at("quantisation_step_m").get<double>(), kStep, 1e-9);
  EXPECT_GT(t.at("low_pass_Hz").get<double>(), t.at("content_up_to_Hz").get<double>());
  EXPECT_LT(t.at("velocity_noise_rms_after_m_per_s").get<double>(),
            0.05 * t.at("velocity_noise_rms_before_m_per_s").get<double>());
}

}  // namespace
}  // namespace ridefit::fitting
