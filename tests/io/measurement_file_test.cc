// Every reader of measurements takes a .mat as well as a CSV: the same file written both ways
// (CSV text, and .mat by ridefit's writer) gives the same profile, measured road, rig record and
// vehicle measurement.
#include "ridefit/io/measurement_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/fitting/psd_fit.h"
#include "ridefit/road/measured_road.h"
#include "ridefit/road/road_profile_file.h"

namespace ridefit::io {
namespace {

namespace fs = std::filesystem;

class MeasurementFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           (std::string("ridefit_measurement_") + info->name() + "_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Writes `table` as NAME.csv and NAME.mat.
  std::pair<fs::path, fs::path> both(const CsvTable& table, const std::string& name) const {
    const fs::path csv = dir_ / (name + ".csv");
    const fs::path mat = dir_ / (name + ".mat");
    write_measurement_table(table, csv);
    write_measurement_table(table, mat);
    return {csv, mat};
  }

  fs::path dir_;
};

std::vector<double> samples(std::size_t n, double step, double amplitude, double frequency) {
  std::vector<double> v(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double x = static_cast<double>(k) * step;
    v[k] = amplitude * std::sin(2.0 * std::numbers::pi * frequency * x);
  }
  return v;
}

std::vector<double> ramp(std::size_t n, double step) {
  std::vector<double> v(n);
  for (std::size_t k = 0; k < n; ++k) v[k] = static_cast<double>(k) * step;
  return v;
}

TEST_F(MeasurementFile, WritesCsvOrMatByTheExtension) {
  CsvTable table;
  table.add("time", "s", ramp(10, 0.01));
  const auto [csv, mat] = both(table, "t");
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "time[s]");
  std::ifstream binary(mat, std::ios::binary);
  std::string magic(6, '\0');
  binary.read(magic.data(), 6);
  EXPECT_EQ(magic, "MATLAB");
}

TEST_F(MeasurementFile, RoadProfileFromMatEqualsItsCsv) {
  CsvTable table;
  table.add("distance", "m", ramp(500, 0.1));
  table.add("elevation", "mm", samples(500, 0.1, 5.0, 0.2));
  const auto [csv, mat] = both(table, "profile");
  const road::RoadProfile a = road::read_profile_csv(csv);
  const road::RoadProfile b = road::read_profile_csv(mat);
  EXPECT_EQ(a.distance_m, b.distance_m);
  EXPECT_EQ(a.elevation_m, b.elevation_m);
  EXPECT_NEAR(b.elevation_m[25], 5e-3 * std::sin(2.0 * std::numbers::pi * 0.2 * 2.5), 1e-15);
}

TEST_F(MeasurementFile, MeasuredRoadFromMatEqualsItsCsv) {
  CsvTable table;
  table.add("time", "s", ramp(2000, 0.005));
  table.add("road", "mm", samples(2000, 0.005, 10.0, 1.5));
  const auto [csv, mat] = both(table, "drive");
  const road::MeasuredRoad a = road::load_measured_road(csv);
  const road::MeasuredRoad b = road::load_measured_road(mat);
  EXPECT_EQ(a.duration_s(), b.duration_s());
  for (const double t : {0.0, 0.123, 4.5, 9.99}) {
    EXPECT_EQ(a.at(t).elevation_m, b.at(t).elevation_m) << t;
  }
  EXPECT_NEAR(b.at(0.1).elevation_m, 1e-2 * std::sin(2.0 * std::numbers::pi * 1.5 * 0.1), 1e-12);
}

TEST_F(MeasurementFile, HysteresisRecordFromMatEqualsItsCsv) {
  CsvTable table;
  table.add("time", "s", ramp(400, 0.005));
  table.add("displacement", "mm", samples(400, 0.005, 3.0, 0.5));
  table.add("force", "kN", samples(400, 0.005, 0.2, 0.5));
  const auto [csv, mat] = both(table, "loop");
  const fitting::HysteresisRecord a = fitting::load_hysteresis_record(csv);
  const fitting::HysteresisRecord b = fitting::load_hysteresis_record(mat);
  EXPECT_EQ(a.time_s, b.time_s);
  EXPECT_EQ(a.displacement_m, b.displacement_m);
  EXPECT_EQ(a.force_N, b.force_N);
  EXPECT_EQ(b.source, mat.string());
}

TEST_F(MeasurementFile, PsdMeasurementFromMatEqualsItsCsv) {
  CsvTable table;
  table.add("time", "s", ramp(4000, 0.002));
  table.add("road", "mm", samples(4000, 0.002, 4.0, 1.1));
  table.add("body_acc", "g", samples(4000, 0.002, 0.05, 1.3));
  table.add("current", "A", samples(4000, 0.002, 1.0, 0.2));
  const auto [csv, mat] = both(table, "drive");
  const fitting::PsdMeasurement a = fitting::load_psd_measurement(csv);
  const fitting::PsdMeasurement b = fitting::load_psd_measurement(mat);
  EXPECT_EQ(a.time_s, b.time_s);
  EXPECT_EQ(a.sample_rate_Hz, b.sample_rate_Hz);
  EXPECT_NEAR(b.sample_rate_Hz, 500.0, 1e-9);
  EXPECT_EQ(a.body_acc_m_per_s2, b.body_acc_m_per_s2);
  EXPECT_TRUE(b.wheel_acc_m_per_s2.empty());
  ASSERT_TRUE(b.road != nullptr);
  EXPECT_TRUE(b.road->has_command()) << "the current column reaches the road";
  EXPECT_EQ(a.road->at(1.234).elevation_m, b.road->at(1.234).elevation_m);
  EXPECT_EQ(a.road->at(1.234).command, b.road->at(1.234).command);
}

}  // namespace
}  // namespace ridefit::io
