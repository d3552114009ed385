#include "ridefit/road/measured_road.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "ridefit/io/input_error.h"

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
    try {
      load_measured_road(csv, channel);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
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

}  // namespace
}  // namespace ridefit::road
