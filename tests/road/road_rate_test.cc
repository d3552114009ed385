// dh/dt of every road against central differences of h, at random times and at sample
// points (where the spline changes polynomial piece).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "ridefit/road/cleat.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/road/log_sweep.h"
#include "ridefit/road/measured_road.h"
#include "ridefit/road/power_law_road.h"
#include "ridefit/road/profile_road.h"

namespace ridefit::road {
namespace {

void expect_rate_matches_central_differences(const RoadInput& road, const std::string& name,
                                             double knot_step_s = 0.0) {
  SCOPED_TRACE(name);
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> uniform(0.0, road.duration_s());
  std::vector<double> times(300);
  for (double& t : times) t = uniform(rng);
  if (knot_step_s > 0.0) {
    for (int k = 1; k < 50; ++k) times.push_back(knot_step_s * k);
  }
  double scale = 0.0;
  for (double t : times) scale = std::max(scale, std::abs(road.at(t).rate_m_per_s));
  ASSERT_GT(scale, 0.0);
  const double h = 1e-6;
  for (double t : times) {
    const double central = (road.at(t + h).elevation_m - road.at(t - h).elevation_m) / (2 * h);
    EXPECT_NEAR(road.at(t).rate_m_per_s, central, 1e-5 * scale) << "t = " << t;
  }
}

TEST(RoadRate, LogSweep) {
  LogSweepParameters p;
  p.initial_amplitude_m = 0.01;
  p.end_amplitude_m = 1e-4;
  expect_rate_matches_central_differences(LogSweep(p), "log sweep");
}

TEST(RoadRate, Iso8608) {
  Iso8608RoadParameters p;
  p.road_class = Iso8608Class::kD;
  p.random.duration_s = 20.0;
  expect_rate_matches_central_differences(make_iso8608_road(p), "iso8608",
                                          0.05 / p.random.speed_m_per_s);
}

TEST(RoadRate, PowerLaw) {
  PowerLawRoadParameters p;
  p.roughness_coefficient_m3 = kSeed001SuburbanRoadCr_m3;
  p.random.duration_s = 20.0;
  p.random.speed_m_per_s = 20.0 / 3.6;
  expect_rate_matches_central_differences(make_power_law_road(p), "power law");
}

TEST(RoadRate, Cleats) {
  CleatParameters p;
  p.speed_m_per_s = 5.0;
  p.duration_s = 2.09 / 5.0 + 0.01;  // concentrate the random times on the cleat
  expect_rate_matches_central_differences(make_cleat_road(p), "semicircular");
  p.shape = CleatShape::kRectangular;
  p.length_m = 0.1;
  p.duration_s = 2.15 / 5.0;
  expect_rate_matches_central_differences(make_cleat_road(p), "rectangular", 0.05 / 40.0 / 5.0);
}

TEST(RoadRate, MeasuredProfileAndChannel) {
  // Unevenly spaced, so both go through the PCHIP resampling too.
  std::vector<double> x, h;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(0.05, 0.15);
  for (double xi = 0.0; xi < 30.0; xi += jitter(rng)) {
    x.push_back(xi);
    h.push_back(0.01 * std::sin(1.3 * xi) + 0.003 * std::sin(5.1 * xi));
  }
  ProfileRoadParameters p;
  p.speed_m_per_s = 10.0;
  expect_rate_matches_central_differences(make_profile_road(x, h, p), "profile");
  expect_rate_matches_central_differences(MeasuredRoad(x, h), "measured channel");
}

}  // namespace
}  // namespace ridefit::road
