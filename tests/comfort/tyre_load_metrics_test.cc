#include "ridefit/comfort/tyre_load_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "support/throws_input_error.h"

namespace ridefit::comfort {
namespace {

using testing::throws_input_error;

// amplitude·sin(2πk/per_period), k = 0 … periods·per_period − 1: whole periods.
std::vector<double> sine(double amplitude, std::size_t per_period, std::size_t periods) {
  std::vector<double> x(per_period * periods);
  for (std::size_t k = 0; k < x.size(); ++k) {
    x[k] = amplitude * std::sin(2.0 * std::numbers::pi * static_cast<double>(k) /
                                static_cast<double>(per_period));
  }
  return x;
}

TEST(TyreLoadMetrics, SineForceHasRmsOverStaticInClosedForm) {
  // 900 N sine on 3000 N static: RMS 900/√2 = 636.40 N, 0.2121 of the static load.
  const auto force = sine(900.0, 1000, 3);
  const TyreLoadMetrics m = tyre_load_metrics(force, 3000.0);
  EXPECT_EQ(m.static_load_N, 3000.0);
  EXPECT_NEAR(m.dynamic_load_rms_N, 900.0 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(m.relative_dynamic_load, 0.3 / std::sqrt(2.0), 1e-12);
  EXPECT_EQ(m.lift_off_share, 0.0);
  EXPECT_NEAR(m.min_total_load_N, 2100.0, 1e-9);
}

TEST(TyreLoadMetrics, LiftOffShareOfAKnownSignal) {
  // 6000 N sine on 3000 N static: total ≤ 0 where sin ≤ −1/2, i.e. on (7π/6, 11π/6):
  // a third of every period; the total load dips to −3000 N.
  const auto force = sine(6000.0, 1200, 2);
  const TyreLoadMetrics m = tyre_load_metrics(force, 3000.0);
  EXPECT_NEAR(m.lift_off_share, 1.0 / 3.0, 1.0 / 1200.0);
  EXPECT_NEAR(m.min_total_load_N, -3000.0, 1e-9);

  // A step: 3 of 8 samples at or below −static (the boundary counts as lift-off).
  const std::vector<double> step{0, 0, -100, -200, -200, -250, 10, 0};
  EXPECT_DOUBLE_EQ(tyre_load_metrics(step, 200.0).lift_off_share, 3.0 / 8.0);
}

TEST(TyreLoadMetrics, StaticLoadOfAQuarterCarCarriesBothMasses) {
  model::QuarterCarParameters<double> p{};
  p.sprung_mass_kg = 400.0;
  p.unsprung_mass_kg = 40.0;
  EXPECT_NEAR(static_tyre_load_N(p), 440.0 * 9.80665, 1e-9);
}

TEST(TyreLoadMetrics, BadInputThrowsWithAMessageNamingTheProblem) {
  std::vector<double> force(10, 0.0);
  EXPECT_TRUE(throws_input_error([&] { tyre_load_metrics(force, 0.0); }, "static tyre load 0 N"));
  EXPECT_TRUE(throws_input_error(
      [&] { tyre_load_metrics(force, std::numeric_limits<double>::quiet_NaN()); },
      "static tyre load nan N"));
  force[4] = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(throws_input_error([&] { tyre_load_metrics(force, 3000.0); }, "sample 4 is inf"));
  EXPECT_TRUE(throws_input_error([&] { tyre_load_metrics({}, 3000.0); }, "at least 1"));
}

}  // namespace
}  // namespace ridefit::comfort
