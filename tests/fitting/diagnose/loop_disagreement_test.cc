// The loop map against closed forms: exact agreement, a constant force error, and an error
// confined to small velocities.
#include "ridefit/fitting/diagnose/loop_disagreement.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "ridefit/common/errors.h"

namespace ridefit::fitting::diagnose {
namespace {

// A 2 Hz, 3 mm sine loop of a viscous strut (c = 1000 Ns/m) with 1 N of seeded noise.
HysteresisRecord sine_loop() {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  HysteresisRecord r;
  r.source = "sine";
  const double w = 2.0 * std::numbers::pi * 2.0;
  for (int k = 0; k < 4000; ++k) {
    const double t = k / 1000.0;
    r.time_s.push_back(t);
    r.displacement_m.push_back(0.003 * std::sin(w * t));
    r.force_N.push_back(1000.0 * 0.003 * w * std::cos(w * t) + noise(rng));
  }
  return r;
}

TEST(LoopDisagreement, ExactAgreementHasNoGapAndNoRegion) {
  const HysteresisRecord r = sine_loop();
  const LoopDisagreementMap map = map_loop_disagreement({r}, {r.force_N});
  EXPECT_EQ(map.gap_percent, 0.0);
  EXPECT_TRUE(map.regions.empty());
  ASSERT_EQ(map.records.size(), 1u);
  EXPECT_EQ(map.records[0].residual_rms_N, 0.0);
}

TEST(LoopDisagreement, AConstantErrorGivesItsNrmseAndARegionEverywhere) {
  const HysteresisRecord r = sine_loop();
  std::vector<double> simulated = r.force_N;
  for (double& f : simulated) f += 5.0;
  const LoopDisagreementMap map = map_loop_disagreement({r}, {simulated});
  // RMS of the measured force about its mean: 1000·0.003·4π/√2 ≈ 26.7 N (plus the noise).
  double mean = 0.0, spread = 0.0;
  for (double f : r.force_N) mean += f / static_cast<double>(r.force_N.size());
  for (double f : r.force_N) spread += (f - mean) * (f - mean);
  const double rms = std::sqrt(spread / static_cast<double>(r.force_N.size()));
  EXPECT_NEAR(map.gap_percent, 100.0 * 5.0 / rms, 1e-9);
  ASSERT_EQ(map.regions.size(), 2u);  // along velocity and along displacement, end to end
  for (const auto& region : map.regions) {
    EXPECT_NEAR(region.mean_residual_N, 5.0, 1e-9);
    EXPECT_NEAR(region.share, 5.0 / rms, 1e-9);
  }
  EXPECT_NEAR(map.regions[1].low, -0.003, 1e-5);
  EXPECT_NEAR(map.regions[1].high, 0.003, 1e-5);
}

TEST(LoopDisagreement, AnErrorAtSmallVelocitiesIsLocatedThere) {
  const HysteresisRecord r = sine_loop();
  std::vector<double> simulated = r.force_N;
  const double w = 2.0 * std::numbers::pi * 2.0;
  // The model's force 10 N too low while |v| is below a third of its peak.
  for (std::size_t k = 0; k < simulated.size(); ++k) {
    if (std::abs(std::cos(w * r.time_s[k])) < 1.0 / 3.0) simulated[k] -= 10.0;
  }
  const LoopDisagreementMap map = map_loop_disagreement({r}, {simulated});
  bool found = false;
  for (const auto& region : map.regions) {
    if (region.quantity != "velocity") continue;
    found = true;
    EXPECT_LT(region.mean_residual_N, -5.0);
    // Quantile bins: the one straddling v_max/3 may join, the next (from v_max/2) may not.
    EXPECT_GT(region.low, -0.003 * w * 0.65);
    EXPECT_LT(region.high, 0.003 * w * 0.65);
  }
  EXPECT_TRUE(found);
}

TEST(LoopDisagreement, RefusesMismatchedInput) {
  const HysteresisRecord r = sine_loop();
  EXPECT_THROW(map_loop_disagreement({r}, {}), InputError);
  EXPECT_THROW(map_loop_disagreement({r}, {std::vector<double>(10, 0.0)}), InputError);
  std::vector<double> bad = r.force_N;
  bad[3] = NAN;
  EXPECT_THROW(map_loop_disagreement({r}, {bad}), InputError);
}

}  // namespace
}  // namespace ridefit::fitting::diagnose
