#include "ridefit/road/road_profile.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "ridefit/common/errors.h"
#include "support/input_error_message.h"

namespace ridefit::road {
namespace {

using ridefit::testing::input_error_message;

TEST(RoadProfile, NonIncreasingDistanceNamesTheSample) {
  const RoadProfile profile{{0.0, 1.0, 2.0, 2.0, 3.0}, {0.0, 0.0, 0.0, 0.0, 0.0}};
  const std::string message = input_error_message([&] { check_road_profile(profile); });
  EXPECT_NE(message.find("sample 3"), std::string::npos) << message;
  EXPECT_NE(message.find("strictly increasing"), std::string::npos) << message;
}

TEST(RoadProfile, NonFiniteValueNamesTheSample) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const RoadProfile profile{{0.0, 1.0, 2.0, 3.0}, {0.0, 0.0, nan, 0.0}};
  const std::string message = input_error_message([&] { check_road_profile(profile); });
  EXPECT_NE(message.find("sample 2"), std::string::npos) << message;
  const RoadProfile bad_distance{{0.0, std::numeric_limits<double>::infinity(), 2.0},
                                 {0.0, 0.0, 0.0}};
  EXPECT_NE(input_error_message([&] { check_road_profile(bad_distance); }).find("sample 1"),
            std::string::npos);
}

TEST(RoadProfile, MismatchedLengthsAreAnError) {
  const RoadProfile profile{{0.0, 1.0, 2.0}, {0.0, 0.0}};
  EXPECT_THROW(check_road_profile(profile), InputError);
}

TEST(RoadProfile, UniformInterpolatesLinearly) {
  const RoadProfile profile{{0.0, 1.0, 3.0, 3.5}, {0.0, 2.0, 0.0, 1.0}};
  const RoadProfile grid = uniform(profile, 0.5);
  ASSERT_EQ(grid.distance_m.size(), 8U);
  const double expected[] = {0.0, 1.0, 2.0, 1.5, 1.0, 0.5, 0.0, 1.0};
  for (std::size_t k = 0; k < grid.distance_m.size(); ++k) {
    EXPECT_DOUBLE_EQ(grid.distance_m[k], 0.5 * static_cast<double>(k));
    EXPECT_NEAR(grid.elevation_m[k], expected[k], 1e-12) << k;
  }
  EXPECT_TRUE(is_uniform(grid, 0.5));
  EXPECT_FALSE(is_uniform(profile, 0.5));
  EXPECT_DOUBLE_EQ(median_spacing_m(profile), 1.0);
  EXPECT_THROW(uniform(profile, 0.0), InputError);
  EXPECT_THROW(uniform(profile, 10.0), InputError);
}

}  // namespace
}  // namespace ridefit::road
