// `ridefit analyse` end to end: numbers a ride engineer can check by hand, the outputs it
// writes, and the bad-input contract (a clear message, exit code 2, no output file).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "ridefit/comfort/frequency_weighting.h"
#include "ridefit/io/csv_table.h"
#include "support/cli_runner.h"

namespace ridefit {
namespace {

namespace fs = std::filesystem;
using testing::run_cli;

constexpr double kRate_Hz = 1000.0;
constexpr double kFrequency_Hz = 4.0;

class AnalyseCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ridefit_analyse_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // 60 s at 1 kHz: body_acc a 4 Hz sine of amplitude `amplitude` (m/s^2), travel a 1 Hz sine
  // of 10 mm written in mm, tyre_force a 13 Hz sine of 500 N.
  std::string recording(const std::string& name, double amplitude) const {
    std::ofstream out(dir_ / name);
    out << "time[s],body_acc[m/s^2],travel[mm],tyre_force[N]\n";
    for (int i = 0; i < 60000; ++i) {
      const double t = i / kRate_Hz;
      out << t << "," << amplitude * std::sin(2.0 * std::numbers::pi * kFrequency_Hz * t) << ","
          << 10.0 * std::sin(2.0 * std::numbers::pi * t) << ","
          << 500.0 * std::sin(2.0 * std::numbers::pi * 13.0 * t) << "\n";
    }
    return (dir_ / name).string();
  }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  void expect_bad_input(const std::string& arguments, const std::string& must_mention) const {
    const fs::path psd = dir_ / "psd.csv";
    const auto run = run_cli("analyse " + arguments + " --psd " + psd.string());
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find(must_mention), std::string::npos)
        << "message should mention '" << must_mention << "':\n"
        << run.output;
    EXPECT_FALSE(fs::exists(psd)) << "no output file on bad input";
  }

  fs::path dir_;
};

TEST_F(AnalyseCli, SineGivesTheWeightedRmsOfTheStandardAndTheClosedForms) {
  const std::string file = recording("sine.csv", 1.0);
  const auto run = run_cli("analyse " + file + " --static-tyre-load 4000 --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto j = nlohmann::json::parse(run.output);
  const auto& channels = j["recordings"][0]["channels"];
  ASSERT_EQ(channels.size(), 3u);
  const auto& body = channels[0];
  EXPECT_EQ(body["channel"], "body_acc");
  EXPECT_EQ(body["weighting"], "Wk");
  const double wk = comfort::weighting_magnitude(comfort::Weighting::kWk, kFrequency_Hz);
  // The filter starts from rest: its transient costs a little of the first second or two.
  EXPECT_NEAR(body["weighted_rms"].get<double>(), wk / std::sqrt(2.0), 0.01 * wk);
  EXPECT_NEAR(body["rms"].get<double>(), 1.0 / std::sqrt(2.0), 1e-4);
  EXPECT_NEAR(body["spectrum_peak_Hz"].get<double>(), kFrequency_Hz, 0.02);
  EXPECT_NEAR(body["band_rms"].get<double>(), 1.0 / std::sqrt(2.0), 0.01);
  EXPECT_NEAR(body["crest_factor"].get<double>(), std::sqrt(2.0), 0.05);
  // a_w ≈ 1.03/√2 = 0.73 m/s^2 lies only in Annex C's 0.5–1 range.
  ASSERT_EQ(body["comfort_reactions"].size(), 1u);
  EXPECT_EQ(body["comfort_reactions"][0], "fairly uncomfortable");
  const auto& travel = channels[1];
  EXPECT_EQ(travel["unit"], "m");  // mm read and converted
  EXPECT_NEAR(travel["rms"].get<double>(), 0.01 / std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(travel["max_compression_m"].get<double>(), 0.01, 1e-6);
  EXPECT_FALSE(travel.contains("weighting"));
  const auto& tyre = channels[2];
  EXPECT_NEAR(tyre["dynamic_tyre_load_ratio"].get<double>(), 500.0 / std::sqrt(2.0) / 4000.0, 1e-4);
  EXPECT_DOUBLE_EQ(tyre["lift_off_share"].get<double>(), 0.0);
}

TEST_F(AnalyseCli, LevelsGiveTheCorrelationAndThePerLevelSpectra) {
  const std::string a = recording("a.csv", 0.5);
  const std::string b = recording("b.csv", 1.0);
  const std::string c = recording("c.csv", 2.0);
  const fs::path psd = dir_ / "psd.csv";
  const fs::path plot = dir_ / "trend.png";
  const auto run = run_cli("analyse " + a + " " + b + " " + c +
                           " --channel body_acc --levels 10,20,40 --level-name friction_N --psd " +
                           psd.string() + " --plot " + plot.string() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto j = nlohmann::json::parse(run.output);
  bool found = false;
  for (const auto& row : j["correlations"]) {
    if (row["metric"] != "weighted_rms") continue;
    found = true;
    // a_w is proportional to the amplitude, which is proportional to the level: R = 1.
    EXPECT_NEAR(row["pearson_r"].get<double>(), 1.0, 1e-9);
    const double wk = comfort::weighting_magnitude(comfort::Weighting::kWk, kFrequency_Hz);
    EXPECT_NEAR(row["slope"].get<double>(), wk / std::sqrt(2.0) / 20.0, 0.01 * wk / 20.0);
    // 2.0/0.5 − 1, up to the 6 digits the CSV carries
    EXPECT_NEAR(row["relative_increase"].get<double>(), 3.0, 1e-4);
  }
  EXPECT_TRUE(found) << run.output;
  const io::CsvTable table = io::CsvTable::read(psd);
  EXPECT_TRUE(table.has("body_acc_psd_run3_friction_N_40"));
  EXPECT_GT(fs::file_size(plot), 1000u);
}

TEST_F(AnalyseCli, AveragedSpectraGoToCsvWithTheirBand) {
  const std::string a = recording("a.csv", 1.0);
  const std::string b = recording("b.csv", 1.0);
  const fs::path psd = dir_ / "psd.csv";
  const auto run =
      run_cli("analyse " + a + " " + b + " --channel body_acc --segment 10 --psd " + psd.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("PSDs averaged over 2 recordings"), std::string::npos);
  const io::CsvTable table = io::CsvTable::read(psd);
  const auto& f = table.column("frequency").values;
  const auto& p = table.column("body_acc_psd").values;
  const auto& lo = table.column("body_acc_psd_lower").values;
  const auto& hi = table.column("body_acc_psd_upper").values;
  EXPECT_NEAR(f[1] - f[0], 0.1, 1e-12);  // 10 s segments
  for (std::size_t k = 1; k < p.size(); ++k) {
    ASSERT_LE(lo[k], p[k]);
    ASSERT_GE(hi[k], p[k]);
  }
}

TEST_F(AnalyseCli, BadInputsAreNamedWithExitCode2AndNoOutput) {
  const std::string good = recording("good.csv", 1.0);
  expect_bad_input(good + " --channel seat_acc", "seat_acc");
  expect_bad_input(good + " --segment 100", "segment");
  expect_bad_input(good + " --weighting Wz", "Wz");
  expect_bad_input(good + " --levels 1,2", "one level per file");
  expect_bad_input(good + " --band 30,1", "band");
  expect_bad_input(good + " --smooth 4", "odd");
  expect_bad_input(good + " --smooth 1001", "at most 101");
  expect_bad_input(good + " " + good, "given twice");
  expect_bad_input(good + " --channel body_acc --channel body_acc", "asked for twice");
  const std::string other = recording("other.csv", 1.0);
  expect_bad_input(good + " " + other + " " + recording("third.csv", 2.0) + " --levels nan,1,2",
                   "not a finite number");
  expect_bad_input(good + " " +
                       write("unit2.csv",
                             "time[s],body_acc[m],travel[m],tyre_force[N]\n0,0,0,0\n"
                             "0.001,1,0,0\n0.002,2,0,0\n"),
                   "must measure the same quantity");
  expect_bad_input(good + " --level-name 'a b' --levels 1", "--level-name");
  expect_bad_input(good + " --plot " + (dir_ / "figure.pdf").string(), ".png or .svg");
  expect_bad_input(write("gap.csv",
                         "time[s],body_acc[m/s^2]\n0,1\n0.001,2\n0.002,3\n0.004,4\n"
                         "0.005,5\n0.006,6\n"),
                   "row 5");
  expect_bad_input(write("nan.csv", "time[s],body_acc[m/s^2]\n0,1\n0.001,nan\n0.002,3\n"), "row 3");
  expect_bad_input(write("unit.csv", "time[s],body_acc[furlongs]\n0,1\n0.001,2\n"), "furlongs");
  expect_bad_input(write("short.csv", "time[s],body_acc[m/s^2]\n0,1\n"), "at least 2");
  expect_bad_input(write("slow.csv",
                         [] {
                           std::string text = "time[s],body_acc[m/s^2]\n";
                           for (int i = 0; i < 400; ++i) {
                             // Varying: a constant channel is refused before its rate is looked at.
                             text += std::to_string(i * 0.01) + "," +
                                     std::to_string(std::sin(0.3 * i)) + "\n";
                           }
                           return text;
                         }()),
                   "500 Hz");
}

}  // namespace
}  // namespace ridefit
