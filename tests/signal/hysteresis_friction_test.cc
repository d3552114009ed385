#include "ridefit/signal/hysteresis_friction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "ridefit/common/errors.h"

namespace ridefit::signal {
namespace {

// F = k·x + Fc·sgn(v) on a sine: the loop is Fc high above and below the spring line at x = 0,
// so half its height there is Fc exactly, in every cycle.
TEST(HysteresisFriction, IdealCoulombLoopGivesFcInEveryCycle) {
  std::vector<double> x, f;
  for (int k = 0; k < 4 * 1000; ++k) {
    const double phase = 2.0 * std::numbers::pi * (k + 0.5) / 1000.0;
    x.push_back(0.003 * std::sin(phase));
    f.push_back(20000.0 * x.back() + (std::cos(phase) >= 0.0 ? 55.0 : -55.0));
  }
  const auto r = hysteresis_friction(x, f);
  EXPECT_EQ(r.per_cycle_N.size(), 3u);  // the first crossing is falling: 3 full up–down pairs
  EXPECT_EQ(r.cycles_used, 2);
  EXPECT_NEAR(r.mean_N, 55.0, 1e-9);
  EXPECT_NEAR(r.standard_deviation_N, 0.0, 1e-9);
}

TEST(HysteresisFriction, TooFewCyclesOrNoCrossingIsAnInputError) {
  std::vector<double> x = {0.001, 0.002, 0.001, -0.001, -0.002, 0.001};
  std::vector<double> f = {1, 2, 3, 4, 5, 6};
  EXPECT_THROW(hysteresis_friction(x, f), InputError);
  std::vector<double> constant(6, 0.001);
  EXPECT_THROW(hysteresis_friction(constant, f), InputError);
  std::vector<double> nan = {0.0, NAN, 0.0, 0.0, 0.0, 0.0};
  EXPECT_THROW(hysteresis_friction(nan, f), InputError);
}

}  // namespace
}  // namespace ridefit::signal
