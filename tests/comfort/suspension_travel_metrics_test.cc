#include "ridefit/comfort/suspension_travel_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "support/throws_input_error.h"

namespace ridefit::comfort {
namespace {

using testing::throws_input_error;

constexpr double kPi = std::numbers::pi;
constexpr std::size_t kPerPeriod = 2000;

// offset + amplitude·sin over 3 whole periods.
std::vector<double> travel(double offset, double amplitude) {
  std::vector<double> z(3 * kPerPeriod);
  for (std::size_t k = 0; k < z.size(); ++k) {
    z[k] = offset + amplitude * std::sin(2.0 * kPi * static_cast<double>(k) /
                                         static_cast<double>(kPerPeriod));
  }
  return z;
}

TEST(SuspensionTravelMetrics, RmsAndPeaksOfASine) {
  const SuspensionTravelMetrics m = suspension_travel_metrics(travel(0.0, 0.03));
  EXPECT_NEAR(m.rms_m, 0.03 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(m.peak_m, 0.03, 1e-12);
  EXPECT_NEAR(m.max_compression_m, 0.03, 1e-12);
  EXPECT_NEAR(m.max_rebound_m, 0.03, 1e-12);
  EXPECT_FALSE(m.beyond_rattle_space_share.has_value());
}

TEST(SuspensionTravelMetrics, OffsetSineAgainstAnAsymmetricRattleSpace) {
  // z = 0.01 + 0.03·sin: RMS = sqrt(0.01² + 0.03²/2) = 0.023452 m; rebound up to 0.04 m,
  // compression down to 0.02 m. Beyond 0.025 m rebound: sin > 1/2, a third of the time;
  // beyond 0.015 m compression: sin < −5/6, (π − 2·asin(5/6))/(2π) = 0.18643 of the time.
  const SuspensionTravelMetrics m =
      suspension_travel_metrics(travel(0.01, 0.03), RattleSpace{0.015, 0.025});
  EXPECT_NEAR(m.rms_m, std::sqrt(5.5e-4), 1e-12);
  EXPECT_NEAR(m.peak_m, 0.04, 1e-12);
  EXPECT_NEAR(m.max_rebound_m, 0.04, 1e-12);
  EXPECT_NEAR(m.max_compression_m, 0.02, 1e-12);
  ASSERT_TRUE(m.beyond_rattle_space_share.has_value());
  const double expected = 1.0 / 3.0 + (kPi - 2.0 * std::asin(5.0 / 6.0)) / (2.0 * kPi);
  EXPECT_NEAR(expected, 0.51976, 1e-5);
  EXPECT_NEAR(*m.beyond_rattle_space_share, expected, 2.0 / kPerPeriod);

  // Entirely in rebound: no compression at all.
  const SuspensionTravelMetrics up = suspension_travel_metrics(travel(0.05, 0.01));
  EXPECT_EQ(up.max_compression_m, 0.0);
  EXPECT_NEAR(up.max_rebound_m, 0.06, 1e-12);
}

TEST(SuspensionTravelMetrics, BadInputThrowsWithAMessageNamingTheProblem) {
  std::vector<double> z(10, 0.0);
  EXPECT_TRUE(throws_input_error(
      [&] {
        suspension_travel_metrics(z, RattleSpace{0.0, 0.05});
      },
      "rattle space in compression is 0 m"));
  EXPECT_TRUE(throws_input_error(
      [&] {
        suspension_travel_metrics(z, RattleSpace{0.05, std::numeric_limits<double>::infinity()});
      },
      "rattle space in rebound is inf m"));
  z[7] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(throws_input_error([&] { suspension_travel_metrics(z); }, "sample 7 is nan"));
  EXPECT_TRUE(throws_input_error([&] { suspension_travel_metrics({}); }, "at least 1"));
}

}  // namespace
}  // namespace ridefit::comfort
