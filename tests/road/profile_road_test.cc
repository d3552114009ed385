#include "ridefit/road/profile_road.h"

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

class RoadProfileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           (std::string("ridefit_profile_") + info->name() + "_" + std::to_string(getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path write(const std::string& name, const std::string& content) const {
    std::ofstream(dir_ / name) << content;
    return dir_ / name;
  }
  std::string error_of(const std::filesystem::path& csv) const {
    try {
      load_profile_road(csv, {});
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
  std::filesystem::path dir_;
};

TEST_F(RoadProfileTest, ReadsMillimetresAndDrivesTheProfileAtTheSpeed) {
  std::string csv = "distance[m],elevation[mm],note[1]\n";
  for (int k = 0; k <= 40; ++k) {
    const double h_mm = 10.0 * std::sin(0.3 * k);
    csv += std::to_string(100.0 + 0.25 * k) + "," + std::to_string(h_mm) + ",0\n";
  }
  ProfileRoadParameters p;
  p.speed_m_per_s = 2.0;
  const SpatialProfileRoad road = load_profile_road(write("p.csv", csv), p);
  EXPECT_NEAR(road.duration_s(), 10.0 / 2.0, 1e-12);  // 10 m at 2 m/s
  EXPECT_DOUBLE_EQ(road.origin_m(), 100.0);
  for (int k = 0; k <= 40; ++k) {
    // Sample k is at distance 0.25·k from the start, reached at t = 0.125·k s.
    // (the file holds the millimetres with six decimals, as std::to_string wrote them)
    const double written_m = std::stod(std::to_string(10.0 * std::sin(0.3 * k))) / 1000.0;
    EXPECT_NEAR(road.at(0.125 * k).elevation_m, written_m, 1e-15) << k;
  }
  // An offset shifts the wheel along the road.
  const SpatialProfileRoad ahead = road.with_offset(1.0);
  EXPECT_NEAR(ahead.at(1.0).elevation_m, road.at(1.5).elevation_m, 1e-15);
}

TEST_F(RoadProfileTest, UnevenSpacingIsResampledAndARampStaysARamp) {
  std::vector<double> x{0.0, 0.1, 0.25, 0.3, 0.42, 0.5, 0.61, 0.7, 0.8, 0.9, 1.0};
  std::vector<double> h;
  for (double xi : x) h.push_back(0.01 * xi);  // 1 % grade
  ProfileRoadParameters p;
  p.speed_m_per_s = 0.5;
  const SpatialProfileRoad road = make_profile_road(x, h, p);
  for (double t : {0.1, 0.77, 1.5, 1.9}) {
    EXPECT_NEAR(road.at(t).elevation_m, 0.01 * 0.5 * t, 1e-12) << t;
    EXPECT_NEAR(road.at(t).rate_m_per_s, 0.01 * 0.5, 1e-10) << t;
  }
}

TEST_F(RoadProfileTest, BadProfilesNameFileRowAndColumn) {
  auto expect_in = [](const std::string& message, const std::vector<std::string>& fragments) {
    for (const auto& f : fragments) {
      EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' not in: " << message;
    }
  };
  expect_in(
      error_of(write("back.csv", "distance[m],elevation[m]\n0,0\n1,0\n2,0\n1.5,0\n3,0\n4,0\n")),
      {"back.csv", "row 5", "'distance'", "strictly increasing"});
  expect_in(error_of(write("force.csv", "distance[m],elevation[N]\n0,0\n1,0\n2,0\n3,0\n4,0\n")),
            {"force.csv", "'elevation'", "length"});
  expect_in(error_of(write("short.csv", "distance[m],elevation[m]\n0,0\n1,0\n2,0\n3,0\n")),
            {"short.csv", "4 data rows", "at least 5"});
  expect_in(error_of(write("nodist.csv", "x[m],elevation[m]\n0,0\n1,0\n2,0\n3,0\n4,0\n")),
            {"nodist.csv", "'distance'", "x[m]"});
  ProfileRoadParameters beyond;
  beyond.offset_m = 10.0;
  const std::vector<double> x{0, 1, 2, 3, 4}, h{0, 0, 0, 0, 0};
  EXPECT_THROW(make_profile_road(x, h, beyond), InputError);
}

}  // namespace
}  // namespace ridefit::road
