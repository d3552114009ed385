#include "ridefit/road/profile_road.h"

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

TEST_F(RoadProfileTest, MaxStepIsThePointSpacingInTime) {
  const std::vector<double> x{0.0, 0.2, 0.4, 0.6, 0.8, 1.0}, h{0, 1e-3, 0, -1e-3, 0, 0};
  ProfileRoadParameters p;
  p.speed_m_per_s = 4.0;
  const SpatialProfileRoad road = make_profile_road(x, h, p);
  EXPECT_GT(road.max_step_s(), 0.0);
  EXPECT_TRUE(std::isfinite(road.max_step_s()));
  EXPECT_DOUBLE_EQ(road.max_step_s(), 0.2 / 4.0);
  // Uneven points: the resampling grid, at the median spacing (0.1 m here).
  const std::vector<double> xu{0.0, 0.1, 0.25, 0.3, 0.42, 0.5, 0.61, 0.7, 0.8, 0.9, 1.0};
  const std::vector<double> hu(xu.size(), 0.0);
  EXPECT_NEAR(make_profile_road(xu, hu, p).max_step_s(), 0.1 / 4.0, 1e-15);
}

TEST_F(RoadProfileTest, FewWideGapsStillGiveTheSplineEnoughPoints) {
  // The median gap (0.8 m) spans 2 m in 2.5 gaps: rounded, 4 grid points, too few for the
  // spline before (a std::invalid_argument, an "internal error" for the user).
  const std::vector<double> x{0.0, 0.1, 0.2, 1.0, 2.0}, h{0, 0, 1e-3, 0, 0};
  const SpatialProfileRoad road = make_profile_road(x, h, {});
  EXPECT_EQ(road.profile().size(), 5u);
  EXPECT_NEAR(road.max_step_s(), 0.5 / ProfileRoadParameters{}.speed_m_per_s, 1e-15);
}

TEST_F(RoadProfileTest, AbsurdProfilesAreInputErrors) {
  auto message = [](const std::vector<double>& x, const std::vector<double>& h,
                    const ProfileRoadParameters& p) {
    return testing::input_error_message([&] { make_profile_road(x, h, p); });
  };
  const std::vector<double> flat(5, 0.0);
  // 5 nm of road: the run would last 4e-10 s.
  const std::vector<double> tiny{0.0, 1.25e-9, 2.5e-9, 3.75e-9, 5e-9};
  EXPECT_THROW(make_profile_road(tiny, flat, {}), InputError);
  EXPECT_NE(message(tiny, flat, {}).find("'speed_m_per_s'"), std::string::npos);
  // A nanometre-spaced start then a wide gap: resampled at the median, 1e15 points.
  std::vector<double> x, h;
  for (int k = 0; k < 10; ++k) x.push_back(1e-9 * k);
  x.push_back(1e6);
  h.assign(x.size(), 0.0);
  EXPECT_NE(message(x, h, {}).find("more than 2e+07"), std::string::npos) << message(x, h, {});
  const std::vector<double> huge{-1e308, -5e307, 0.0, 5e307, 1e308};  // spans infinity
  EXPECT_THROW(make_profile_road(huge, flat, {}), InputError);
  const std::vector<double> x5{0, 1, 2, 3, 4};
  EXPECT_THROW(make_profile_road(x5, std::vector<double>{0, 0, 1e308, 0, 0}, {}), InputError);
  ProfileRoadParameters fast;
  fast.speed_m_per_s = 1e6;
  EXPECT_NE(message(x5, flat, fast).find("'speed_m_per_s'"), std::string::npos);
  ProfileRoadParameters far_behind;
  far_behind.offset_m = -1e9;  // a run-up of 1e9 m at 1 m spacing
  EXPECT_NE(message(x5, flat, far_behind).find("'offset_m'"), std::string::npos);
}

TEST_F(RoadProfileTest, ADirectoryIsNamedAsSuchWithTheExpectedColumns) {
  const std::string message = error_of(dir_);
  EXPECT_NE(message.find("is a directory"), std::string::npos) << message;
  EXPECT_NE(message.find("distance[m]"), std::string::npos) << message;
  EXPECT_NE(message.find("elevation["), std::string::npos) << message;
}

TEST_F(RoadProfileTest, ATooShortFileNamesTheSpeedAndTheLength) {
  const std::string message = error_of(
      write("nm.csv", "distance[m],elevation[mm]\n0,0\n1.25e-9,0\n2.5e-9,0\n3.75e-9,0\n5e-9,0\n"));
  EXPECT_NE(message.find("'speed_m_per_s'"), std::string::npos) << message;
  EXPECT_NE(message.find("5e-09 m"), std::string::npos) << message;
}

}  // namespace
}  // namespace ridefit::road
