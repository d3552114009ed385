// Parametric studies of the half car: the design read from YAML, its expansion, the bad
// inputs, and the seed's trends as measured numbers.
#include "ridefit/study/half_car_sweep.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/input_error_message.h"
#include "support/passat.h"

namespace ridefit::study {
namespace {

namespace fs = std::filesystem;

class HalfCarSweepTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ridefit_sweep_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // A study file with the dataset's model and roads and the given extra lines.
  fs::path study(const std::string& extra) const {
    const fs::path path = dir_ / "study.yaml";
    std::ofstream(path) << "model: " << testing::dataset("vehicles/ajayi_half_car.yaml") << "\n"
                        << "roads:\n  smooth: "
                        << testing::dataset("excitations/smooth_road_seed001.yaml")
                        << "\n  gravel: "
                        << testing::dataset("excitations/gravel_road_seed001.yaml") << "\n"
                        << extra;
    return path;
  }
  std::string error_of(const std::string& extra) const {
    return testing::input_error_message([&] { load_half_car_sweep(study(extra)); });
  }
  fs::path dir_;
};

TEST_F(HalfCarSweepTest, GridAndZipExpandInTheDocumentedOrder) {
  const auto grid = load_half_car_sweep(
      study("speeds_km_per_h: [20, 40]\nvary:\n  - parameter: front.damping_Ns_per_m\n"
            "    values: [800, 1200, 1600]\n  - parameter: [front.spring_stiffness_N_per_m, "
            "rear.spring_stiffness_N_per_m]\n    name: k_N_per_m\n"
            "    range: {from: 10000, to: 40000, count: 4, spacing: log}\n"));
  const auto points = expand(grid);
  ASSERT_EQ(points.size(), 2u * 2u * 3u * 4u);
  EXPECT_EQ(points[0].road, 0u);
  EXPECT_DOUBLE_EQ(points[0].speed_m_per_s, 20.0 / 3.6);
  EXPECT_DOUBLE_EQ(points[1].values[1], 10000.0 * std::pow(4.0, 1.0 / 3.0));  // last axis fastest
  EXPECT_DOUBLE_EQ(points[3].values[1], 40000.0);                             // exact end
  EXPECT_DOUBLE_EQ(points[4].values[0], 1200.0);
  EXPECT_EQ(points[24].road, 1u);
  EXPECT_EQ(grid.axes[1].keys.size(), 2u);
  const auto zip = load_half_car_sweep(
      study("combine: zip\nvary:\n  - parameter: front.damping_Ns_per_m\n    values: [800, 1200]\n"
            "  - parameter: rear.damping_Ns_per_m\n    values: [900, 1300]\n"));
  const auto zipped = expand(zip);
  ASSERT_EQ(zipped.size(), 2u * 2u);
  EXPECT_DOUBLE_EQ(zipped[1].values[0], 1200.0);
  EXPECT_DOUBLE_EQ(zipped[1].values[1], 1300.0);
}

TEST_F(HalfCarSweepTest, BadStudiesNameTheKey) {
  EXPECT_NE(error_of("vary:\n  - parameter: front.dampng_Ns_per_m\n    values: [1]\n")
                .find("'front.dampng_Ns_per_m' is not a key"),
            std::string::npos);
  EXPECT_NE(error_of("vary:\n  - parameter: front.damping_Ns_per_m\n    values: []\n")
                .find("vary[1].values"),
            std::string::npos);
  EXPECT_NE(error_of("vary: []\n").find("'vary'"), std::string::npos);
  EXPECT_NE(error_of("speeds_km_per_h: [20, -40]\n").find("not > 0"), std::string::npos);
  EXPECT_NE(error_of("vary:\n  - parameter: front.damping_Ns_per_m\n"
                     "    range: {from: 0, to: 10, count: 3, spacing: log}\n")
                .find("log spacing"),
            std::string::npos);
  EXPECT_NE(error_of("combine: zip\nvary:\n  - parameter: front.damping_Ns_per_m\n"
                     "    values: [1, 2]\n  - parameter: rear.damping_Ns_per_m\n    values: [1]\n")
                .find("zip"),
            std::string::npos);
  EXPECT_NE(error_of("plot: {x: speed_km_per_h, y: [comfort]}\n").find("'comfort' is not a metric"),
            std::string::npos);
  EXPECT_NE(error_of("colour: red\n").find("'colour'"), std::string::npos);
  // A controller whose limits cross, reached through the study: the run is named.
  const auto crossing = load_half_car_sweep(
      study("vary:\n  - parameter: control.min_damping_Ns_per_m\n    values: [100, 5000]\n"));
  const std::string message = testing::input_error_message([&] { run_half_car_sweep(crossing); });
  EXPECT_NE(message.find("c_min <= c_max"), std::string::npos) << message;
  EXPECT_NE(message.find("run 2 of 4"), std::string::npos) << message;
}

// Seed 001's trends (its Figures 5 and 6, Section 3): discomfort rises with speed and with
// road roughness, at every body segment; asserted on the exact frequency-domain figures.
TEST_F(HalfCarSweepTest, DiscomfortRisesWithSpeedAndRoughness) {
  const auto sweep = load_half_car_sweep(study("speeds_km_per_h: [20, 50, 80]\n"));
  const auto rows = run_half_car_sweep(sweep, 2);
  ASSERT_EQ(rows.size(), 6u);
  for (const auto& row : rows) EXPECT_TRUE(row.frequency_domain);
  for (std::size_t road = 0; road < 2; ++road) {
    for (std::size_t s = 0; s + 1 < 3; ++s) {
      const auto& slow = rows[road * 3 + s].metrics;
      const auto& fast = rows[road * 3 + s + 1].metrics;
      EXPECT_GT(fast.lower_body_acc_wk_rms_m_per_s2, 1.1 * slow.lower_body_acc_wk_rms_m_per_s2);
      EXPECT_GT(fast.upper_body_acc_wk_rms_m_per_s2, 1.1 * slow.upper_body_acc_wk_rms_m_per_s2);
      EXPECT_GT(fast.seat_acc_wk_rms_m_per_s2, 1.1 * slow.seat_acc_wk_rms_m_per_s2);
    }
  }
  // Gravel (Cr 4.4e-6) against smooth (4.8e-7) at one speed: the response is linear in the
  // road's amplitude, so every figure scales by sqrt(4.4e-6/4.8e-7) = 3.03 exactly.
  for (std::size_t s = 0; s < 3; ++s) {
    EXPECT_NEAR(rows[3 + s].metrics.upper_body_acc_wk_rms_m_per_s2 /
                    rows[s].metrics.upper_body_acc_wk_rms_m_per_s2,
                std::sqrt(4.4e-6 / 4.8e-7), 1e-9);
  }
}

// The compression/rebound split is an optional key the file leaves out: a study may vary it,
// and since it makes the car nonlinear the whole study runs in the time domain (every run's
// car decides, not only the first one's).
TEST_F(HalfCarSweepTest, VaryingTheDamperSplitRunsInTheTimeDomain) {
  const std::string vary =
      "vary:\n  - parameter: [front.compression_to_rebound_ratio, "
      "rear.compression_to_rebound_ratio]\n    values: [1, 0.5]\n";
  const std::string frequency = testing::input_error_message(
      [&] { run_half_car_sweep(load_half_car_sweep(study("method: frequency\n" + vary))); });
  EXPECT_NE(frequency.find("method frequency needs a linear car"), std::string::npos) << frequency;
  const auto sweep = load_half_car_sweep(
      study("time: {output_rate_Hz: 500, settle_s: 1, duration_s: 4}\n" + vary));
  const auto rows = run_half_car_sweep(sweep, 2);
  ASSERT_EQ(rows.size(), 4u);  // two roads, two ratios
  for (const auto& row : rows) EXPECT_FALSE(row.frequency_domain);
  EXPECT_EQ(rows[1].point.values[0], 0.5);
  EXPECT_NE(rows[1].metrics.front_travel_rms_m, rows[0].metrics.front_travel_rms_m);
}

TEST(SplitUnitSuffix, NamesAndUnits) {
  EXPECT_EQ(split_unit_suffix("seat_acc_wk_rms_m_per_s2"),
            std::make_pair(std::string("seat_acc_wk_rms"), std::string("m/s^2")));
  EXPECT_EQ(split_unit_suffix("front.damping_Ns_per_m").second, "Ns/m");
  EXPECT_EQ(split_unit_suffix("front_dynamic_load_ratio").second, "1");
}

}  // namespace
}  // namespace ridefit::study
