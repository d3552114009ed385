#include "ridefit/road/measured_road.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "support/input_error_message.h"

namespace ridefit::road {
namespace {

class RoadMeasuredTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           (std::string("ridefit_measured_") + info->name() + "_" + std::to_string(getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path write(const std::string& name, const std::string& content) const {
    std::ofstream(dir_ / name) << content;
    return dir_ / name;
  }
  std::filesystem::path dir_;
};

TEST_F(RoadMeasuredTest, ChannelIsConvertedShiftedToZeroAndPassesThroughItsSamples) {
  std::string csv = "time[ms],road_front[mm],body_acc[g]\n";
  std::vector<double> road_m;
  for (int k = 0; k < 100; ++k) {
    const double mm = std::round(1000.0 * std::sin(0.05 * k)) / 100.0;  // two decimals
    road_m.push_back(mm / 1000.0);
    csv += std::to_string(2000 + 5 * k) + "," + std::to_string(mm) + ",0.1\n";
  }
  const MeasuredRoad road = load_measured_road(write("drive.csv", csv), "road_front");
  EXPECT_DOUBLE_EQ(road.start_time_s(), 2.0);
  EXPECT_NEAR(road.duration_s(), 0.495, 1e-12);
  for (int k = 0; k < 100; ++k) {
    EXPECT_NEAR(road.at(0.005 * k).elevation_m, road_m[static_cast<std::size_t>(k)], 1e-15) << k;
  }
  // Before and after the recording, the end values, flat.
  EXPECT_DOUBLE_EQ(road.at(-1.0).elevation_m, road_m.front());
  EXPECT_DOUBLE_EQ(road.at(10.0).elevation_m, road_m.back());
  EXPECT_EQ(road.at(10.0).rate_m_per_s, 0.0);
}

TEST_F(RoadMeasuredTest, ErrorsNameFileRowAndColumn) {
  auto error_of = [](const std::filesystem::path& csv, const std::string& channel) {
    return testing::input_error_message([&] { load_measured_road(csv, channel); });
  };
  const std::string good = "time[s],road[m]\n0,0\n0.1,0\n0.2,0\n0.3,0\n0.4,0\n";
  const std::string no_road = error_of(write("a.csv", good), "road_rear");
  EXPECT_NE(no_road.find("a.csv"), std::string::npos) << no_road;
  EXPECT_NE(no_road.find("'road_rear'"), std::string::npos) << no_road;
  EXPECT_NE(no_road.find("road[m]"), std::string::npos) << no_road;
  const std::string back =
      error_of(write("b.csv", "time[s],road[m]\n0,0\n0.1,0\n0.1,0\n0.3,0\n0.4,0\n"), "road");
  EXPECT_NE(back.find("b.csv"), std::string::npos) << back;
  EXPECT_NE(back.find("row 4"), std::string::npos) << back;
  EXPECT_NE(back.find("'time'"), std::string::npos) << back;
  const std::string unit =
      error_of(write("c.csv", "time[s],road[m/s]\n0,0\n0.1,0\n0.2,0\n0.3,0\n0.4,0\n"), "road");
  EXPECT_NE(unit.find("length"), std::string::npos) << unit;
  const std::string no_time =
      error_of(write("d.csv", "t[s],road[m]\n0,0\n0.1,0\n0.2,0\n0.3,0\n0.4,0\n"), "road");
  EXPECT_NE(no_time.find("'time'"), std::string::npos) << no_time;
}

TEST_F(RoadMeasuredTest, MaxStepIsTheTimeStep) {
  const std::vector<double> t{0.0, 0.002, 0.004, 0.006, 0.008, 0.010};
  const std::vector<double> h{0.0, 1e-3, 2e-3, 1e-3, 0.0, 0.0};
  const MeasuredRoad road(t, h);
  EXPECT_GT(road.max_step_s(), 0.0);
  EXPECT_TRUE(std::isfinite(road.max_step_s()));
  EXPECT_DOUBLE_EQ(road.max_step_s(), 0.002);
}

TEST_F(RoadMeasuredTest, AbsurdRecordingsAreInputErrors) {
  auto error_of = [](const std::filesystem::path& csv) {
    return testing::input_error_message([&] { load_measured_road(csv, "road"); });
  };
  const std::string directory = error_of(dir_);
  EXPECT_NE(directory.find("is a directory"), std::string::npos) << directory;
  EXPECT_NE(directory.find("time[s]"), std::string::npos) << directory;
  const std::string brief =
      error_of(write("ns.csv", "time[s],road[mm]\n0,0\n1e-9,1\n2e-9,2\n3e-9,1\n4e-9,0\n"));
  EXPECT_NE(brief.find("ns.csv"), std::string::npos) << brief;
  EXPECT_NE(brief.find("lasts 4e-09 s"), std::string::npos) << brief;
  const std::string gap =
      error_of(write("gap.csv", "time[s],road[mm]\n0,0\n1e-6,1\n2e-6,2\n3e-6,1\n1e6,0\n"));
  EXPECT_NE(gap.find("gap.csv"), std::string::npos) << gap;
  EXPECT_NE(gap.find("more than 2e+07"), std::string::npos) << gap;
  const std::string high =
      error_of(write("high.csv", "time[s],road[m]\n0,0\n1,1e300\n2,0\n3,0\n4,0\n"));
  EXPECT_NE(high.find("elevation"), std::string::npos) << high;
  const std::vector<double> t{0, 1, 2, 3, 4}, h{0, 0, 0, 0, 0};
  EXPECT_NO_THROW(MeasuredRoad(t, h));
}

TEST_F(RoadMeasuredTest, ACommandColumnIsCarriedLinearlyInterpolatedAndHeldAtItsEnds) {
  // A controlled damper's coil current in mA, switching between 0 and 2 A.
  std::string csv = "time[s],road[mm],current[mA]\n";
  for (int k = 0; k < 10; ++k) {
    csv += std::to_string(0.01 * k) + ",0.5," + (k < 5 ? "0" : "2000") + "\n";
  }
  const MeasuredRoad road = load_measured_road(write("switching.csv", csv));
  ASSERT_TRUE(road.has_command());
  EXPECT_EQ(road.command_unit(), "A");
  EXPECT_DOUBLE_EQ(road.at(0.02).command, 0.0);
  EXPECT_NEAR(road.at(0.045).command, 1.0, 1e-12);  // halfway up the ramp between samples
  EXPECT_NEAR(road.at(0.0475).command, 1.5, 1e-12);
  EXPECT_DOUBLE_EQ(road.at(0.07).command, 2.0);
  EXPECT_DOUBLE_EQ(road.at(-1.0).command, 0.0);
  EXPECT_DOUBLE_EQ(road.at(5.0).command, 2.0);
  // Without one, no command (0), and a record with both kinds refused by name.
  const MeasuredRoad plain =
      load_measured_road(write("plain.csv", "time[s],road[m]\n0,0\n0.1,0\n0.2,0\n0.3,0\n0.4,0\n"));
  EXPECT_FALSE(plain.has_command());
  EXPECT_EQ(plain.at(0.2).command, 0.0);
  const std::string both = testing::input_error_message([&] {
    load_measured_road(write("both.csv",
                             "time[s],road[m],current[A],voltage[V]\n0,0,0,0\n0.1,0,0,0\n"
                             "0.2,0,0,0\n0.3,0,0,0\n0.4,0,0,0\n"));
  });
  EXPECT_NE(both.find("both.csv"), std::string::npos) << both;
  EXPECT_NE(both.find("both a current and a voltage"), std::string::npos) << both;
  const std::string wrong_unit = testing::input_error_message([&] {
    load_measured_road(write(
        "unit.csv", "time[s],road[m],current[V]\n0,0,0\n0.1,0,0\n0.2,0,0\n0.3,0,0\n0.4,0,0\n"));
  });
  EXPECT_NE(wrong_unit.find("current is in V, expected a current"), std::string::npos)
      << wrong_unit;
}

}  // namespace
}  // namespace ridefit::road
