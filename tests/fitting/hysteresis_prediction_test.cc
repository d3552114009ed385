// A prediction of a held-out record says how much of its misfit lies within the band a random
// motion excites: white load-cell noise on a CVODE record of the truth is mostly above it; a sine
// test gets no split (its force's harmonics are the damper's own).
#include "ridefit/fitting/hysteresis_prediction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "support/controlled_damper_record.h"
#include "support/cvode_rig_record.h"
#include "support/loop_diagnosis_cases.h"

namespace ridefit::fitting {
namespace {

TEST(RecordPrediction, SplitsARandomRecordsMisfitAtTheMotionsBand) {
  const auto truth = testing::passat_rig_strut();
  HysteresisRecord r =
      testing::cvode_rig_record(truth, testing::random_rig_motion(4), 8.0, 1000.0, "random");
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 5.0);  // N, white up to 500 Hz
  for (double& f : r.force_N) f += noise(rng);
  const auto p = predict_records({r}, truth, {}).front();
  ASSERT_GT(p.excitation_band_Hz, 0.0);
  EXPECT_LT(p.excitation_band_Hz, 100.0);
  // White noise puts band/500 Hz of its power in the band; the model's own error is far smaller.
  const double expected = p.nrmse_percent * std::sqrt(p.excitation_band_Hz / 500.0);
  EXPECT_NEAR(p.in_band_nrmse_percent, expected, 0.25 * expected)
      << p.nrmse_percent << " % overall, band " << p.excitation_band_Hz << " Hz";
}

TEST(RecordPrediction, LeavesASineTestWhole) {
  const auto truth = testing::passat_rig_strut();
  const HysteresisRecord r = testing::cvode_rig_record(
      truth, [](double t) { return 0.005 * std::sin(2.0 * std::numbers::pi * 2.0 * t); }, 4.0,
      500.0, "sine");
  auto start = truth;
  start.damping_Ns_per_m *= 1.2;  // a misfit to split
  const auto p = predict_records({r}, start, {}).front();
  EXPECT_GT(p.nrmse_percent, 1.0);
  EXPECT_EQ(p.excitation_band_Hz, 0.0);
  EXPECT_EQ(p.in_band_nrmse_percent, p.nrmse_percent);
}

}  // namespace
}  // namespace ridefit::fitting
