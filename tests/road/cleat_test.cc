#include "ridefit/road/cleat.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "ridefit/common/errors.h"
#include "support/input_error_message.h"

namespace ridefit::road {
namespace {

// ∫ h dx of the road as driven, by sampling it over time.
double area_m2(const SpatialProfileRoad& road) {
  const double v = *road.speed_m_per_s();
  const double dt = 1e-5;
  double sum = 0.0;
  for (double t = 0.0; t < road.duration_s(); t += dt) sum += road.at(t).elevation_m * v * dt;
  return sum;
}

TEST(RoadCleat, RectangleBecomesATrapezoidOfFullHeight) {
  CleatParameters p;
  p.shape = CleatShape::kRectangular;
  p.height_m = 0.02;
  p.length_m = 0.1;
  p.tyre_contact_length_m = 0.05;
  p.start_distance_m = 2.0;
  p.speed_m_per_s = 5.0;
  // Closed form: 0 before 2 − 0.025, ramps to H at 2 + 0.025, holds to 2.075, 0 after 2.125.
  EXPECT_EQ(enveloped_cleat_elevation_m(p, 1.97), 0.0);
  EXPECT_NEAR(enveloped_cleat_elevation_m(p, 1.9875), 0.01 * 0.5, 1e-15);
  EXPECT_NEAR(enveloped_cleat_elevation_m(p, 2.0), 0.01, 1e-15);
  EXPECT_NEAR(enveloped_cleat_elevation_m(p, 2.05), 0.02, 1e-15);
  EXPECT_NEAR(enveloped_cleat_elevation_m(p, 2.1), 0.01, 1e-15);
  EXPECT_EQ(enveloped_cleat_elevation_m(p, 2.13), 0.0);

  const SpatialProfileRoad road = make_cleat_road(p);
  const double v = p.speed_m_per_s;
  EXPECT_NEAR(road.at(2.05 / v).elevation_m, 0.02, 1e-6);  // peak = full height
  EXPECT_NEAR(road.at(2.0 / v).elevation_m, 0.01, 1e-6);
  // Support of length L + l: flat before 1.975 m and after 2.125 m (up to spline ripple).
  EXPECT_LT(std::abs(road.at(1.97 / v).elevation_m), 1e-6);
  EXPECT_LT(std::abs(road.at(2.13 / v).elevation_m), 1e-6);
  EXPECT_GT(road.at(1.98 / v).elevation_m, 1e-3);
  EXPECT_GT(road.at(2.12 / v).elevation_m, 1e-3);
  // The moving average keeps the area H·L.
  EXPECT_NEAR(area_m2(road) / (0.02 * 0.1), 1.0, 1e-3);
  // Slope on the ramps is H/l·v.
  EXPECT_NEAR(road.at(1.99 / v).rate_m_per_s, 0.02 / 0.05 * v, 0.02 * 0.4 * v);
}

TEST(RoadCleat, SemicircleShorterThanThePatchIsLoweredButKeepsItsArea) {
  CleatParameters p;  // defaults: 20 mm semicircle, 40 mm long, 0.1 m patch, at 2 m
  p.speed_m_per_s = 20.0 / 3.6;
  const double peak = std::numbers::pi * 0.02 * 0.04 / (4.0 * 0.1);  // area / l = 6.28 mm
  EXPECT_NEAR(enveloped_cleat_elevation_m(p, 2.02), peak, 1e-15);
  const SpatialProfileRoad road = make_cleat_road(p);
  const double v = p.speed_m_per_s;
  EXPECT_NEAR(road.at(2.02 / v).elevation_m, peak, 1e-6);
  EXPECT_NEAR(area_m2(road) / (std::numbers::pi / 4.0 * 0.02 * 0.04), 1.0, 1e-3);
  EXPECT_LT(std::abs(road.at(1.949 / v).elevation_m), 1e-7);
  EXPECT_LT(std::abs(road.at(2.091 / v).elevation_m), 1e-7);
  // Default duration: until the patch leaves the cleat, plus the settling time.
  EXPECT_NEAR(road.duration_s(), (2.0 + 0.04 + 0.05) / v + kCleatSettleTime_s, 1e-12);
  EXPECT_EQ(road.at(0.0).elevation_m, 0.0);
  EXPECT_EQ(road.at(0.0).rate_m_per_s, 0.0);
  EXPECT_EQ(road.at(road.duration_s()).elevation_m, 0.0);
}

TEST(RoadCleat, ShortPatchFollowsTheSemicircle) {
  CleatParameters p;
  p.tyre_contact_length_m = 1e-3;
  const SpatialProfileRoad road = make_cleat_road(p);
  const double v = p.speed_m_per_s;
  EXPECT_NEAR(road.at(2.02 / v).elevation_m, 0.02, 2e-5);
  // At 10 mm from the start the semicircle of radius 20 mm is sqrt(20² − 10²) mm high.
  EXPECT_NEAR(road.at(2.01 / v).elevation_m, std::sqrt(0.02 * 0.02 - 0.01 * 0.01), 2e-5);
}

TEST(RoadCleat, InvalidParametersNameTheKey) {
  auto message = [](const CleatParameters& p) {
    return testing::input_error_message([&] { make_cleat_road(p); });
  };
  CleatParameters p;
  p.height_m = 0.0;
  EXPECT_NE(message(p).find("'height_m'"), std::string::npos);
  p = {};
  p.start_distance_m = 0.01;  // the 0.1 m patch would already touch the cleat
  EXPECT_NE(message(p).find("'start_distance_m'"), std::string::npos);
  p = {};
  p.tyre_contact_length_m = -0.1;
  EXPECT_NE(message(p).find("'tyre_contact_length_m'"), std::string::npos);
  EXPECT_EQ(parse_cleat_shape("rectangular"), CleatShape::kRectangular);
  EXPECT_THROW(parse_cleat_shape("triangular"), InputError);
}

TEST(RoadCleat, MaxStepIsTheFineSampleSpacingInTime) {
  CleatParameters p;  // 40 mm cleat, 0.1 m patch: sampled every 40 mm/40 = 1 mm
  p.speed_m_per_s = 40.0 / 3.6;
  const SpatialProfileRoad road = make_cleat_road(p);
  EXPECT_GT(road.max_step_s(), 0.0);
  EXPECT_TRUE(std::isfinite(road.max_step_s()));
  EXPECT_DOUBLE_EQ(road.max_step_s(), 0.04 / 40.0 / p.speed_m_per_s);
  p.tyre_contact_length_m = 0.02;  // now the patch is the narrower
  EXPECT_DOUBLE_EQ(make_cleat_road(p).max_step_s(), 0.02 / 40.0 / p.speed_m_per_s);
}

TEST(RoadCleat, ADurationThatEndsOnTheCleatIsAnInputErrorNamingTheMinimum) {
  CleatParameters p;  // at 2 m, 40 mm long, 0.1 m patch: left at 2.09 m
  p.speed_m_per_s = 40.0 / 3.6;
  p.duration_s = 0.1;
  EXPECT_THROW(make_cleat_road(p), InputError);
  try {
    make_cleat_road(p);
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'duration_s'"), std::string::npos) << message;
    EXPECT_NE(message.find("0.1881"), std::string::npos) << message;  // 2.09 m/(11.1 m/s)
  }
  p.duration_s = 2.09 / p.speed_m_per_s;  // just the passage is enough
  EXPECT_NO_THROW(make_cleat_road(p));
}

TEST(RoadCleat, ExtremeSizesSpeedsAndRunsAreInputErrors) {
  auto message = [](const CleatParameters& p) {
    return testing::input_error_message([&] { make_cleat_road(p); });
  };
  CleatParameters p;
  p.length_m = 1e-9;  // 4e9 samples across the patch
  EXPECT_NE(message(p).find("'length_m'"), std::string::npos) << message(p);
  EXPECT_NE(message(p).find("'tyre_contact_length_m'"), std::string::npos) << message(p);
  p = {};
  p.speed_m_per_s = 1e6;
  EXPECT_NE(message(p).find("'speed_m_per_s'"), std::string::npos) << message(p);
  p = {};
  p.height_m = 1e300;  // overflowed h̄
  EXPECT_NE(message(p).find("'height_m'"), std::string::npos) << message(p);
  p = {};
  p.start_distance_m = 1e9;  // a run-up of 1e12 samples
  EXPECT_NE(message(p).find("'start_distance_m'"), std::string::npos) << message(p);
  p = {};
  p.duration_s = 1e9;
  EXPECT_NE(message(p).find("'duration_s'"), std::string::npos) << message(p);
}

}  // namespace
}  // namespace ridefit::road
