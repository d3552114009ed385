// The stroke speed a velocity law's knee starts from is read off the records: a sine's RMS
// speed in closed form, the velocity column where a record has one, and on a vehicle record the
// baseline's travel rate, which puts the digressive knee's start away from any one truth.
#include "ridefit/fitting/diagnose/damper_speed.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ridefit/fitting/diagnose/effect.h"
#include "support/hidden_effect_record.h"
#include "support/passat.h"

namespace ridefit::fitting::diagnose {
namespace {

HysteresisRecord sine_record(double amplitude_m, double frequency_Hz, bool uneven) {
  HysteresisRecord r;
  const double w = 2.0 * std::numbers::pi * frequency_Hz;
  double t = 0.0;
  for (int k = 0; t < 5.0; ++k) {
    r.time_s.push_back(t);
    r.displacement_m.push_back(amplitude_m * std::sin(w * t));
    r.force_N.push_back(0.0);
    t += uneven && k % 2 == 0 ? 0.9e-3 : 1.0e-3;
  }
  return r;
}

TEST(DamperSpeed, SineRecordsGiveAmplitudeTimesOmegaOverRootTwo) {
  const double expected = 0.01 * 2.0 * std::numbers::pi * 2.0 / std::sqrt(2.0);
  EXPECT_NEAR(damper_speed_rms_m_per_s({sine_record(0.01, 2.0, false)}), expected, 2e-3 * expected);
  EXPECT_NEAR(damper_speed_rms_m_per_s({sine_record(0.01, 2.0, true)}), expected, 2e-3 * expected);
  EXPECT_EQ(damper_speed_rms_m_per_s(std::vector<HysteresisRecord>{}), 0.0);
}

TEST(DamperSpeed, AVelocityColumnIsTakenAsMeasured) {
  HysteresisRecord r = sine_record(0.01, 2.0, false);
  r.velocity_m_per_s.assign(r.time_s.size(), 0.3);  // the rig's own channel wins
  EXPECT_NEAR(damper_speed_rms_m_per_s({r}), 0.3, 1e-12);
}

TEST(DamperSpeed, VehicleRecordsGiveTheBaselinesTravelRate) {
  const model::QuarterCar car(model::DamperState::kSlip, testing::passat_corner().parameters);
  const PsdMeasurement rough = testing::hidden_effect_record(car, road::Iso8608Class::kD, 1);
  const PsdMeasurement smooth = testing::hidden_effect_record(car, road::Iso8608Class::kB, 1);
  const double v_rough = damper_speed_rms_m_per_s(car, rough);
  const double v_smooth = damper_speed_rms_m_per_s(car, smooth);
  // ISO 8608 classes double the road's amplitude per class: a linear car's speeds scale with it.
  EXPECT_NEAR(v_rough / v_smooth, 4.0, 0.2);
  EXPECT_GT(v_smooth, 0.02);
  PsdMeasurement no_road = rough;
  no_road.road = nullptr;
  EXPECT_EQ(damper_speed_rms_m_per_s(car, no_road), 0.0);
}

// The knee's start is read off the record, not a fixed 0.1 m/s (the truth of every shipped
// digressive record and test): on the diagnosis test's class D record it is over 30 % away.
TEST(DamperSpeed, DigressiveKneeStartsAwayFromTheTestsTruth) {
  const model::QuarterCar car(model::DamperState::kSlip, testing::passat_corner().parameters);
  DiagnosisModel baseline{car};
  baseline.damper_speed_rms_m_per_s =
      damper_speed_rms_m_per_s(car, testing::hidden_effect_record(car, road::Iso8608Class::kD, 1));
  const EffectChange change = find_effect("damper_digressive").change(baseline);
  const double knee = change.set.at("damper_knee_velocity_m_per_s");
  EXPECT_GT(std::abs(knee - 0.1) / 0.1, 0.3) << knee;
}

}  // namespace
}  // namespace ridefit::fitting::diagnose
