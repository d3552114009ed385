#include "ridefit/comfort/vibration_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "ridefit/comfort/additional_methods_rule.h"
#include "ridefit/comfort/weighting_filter.h"
#include "ridefit/common/errors.h"

namespace ridefit::comfort {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<double> sine(double amplitude, double frequency_Hz, double fs, double duration_s) {
  std::vector<double> x(static_cast<std::size_t>(std::lround(duration_s * fs)));
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = amplitude * std::sin(2.0 * kPi * frequency_Hz * static_cast<double>(i) / fs);
  }
  return x;
}

// A sine of amplitude A over whole periods: RMS A/√2, crest √2 (fs a multiple of 4f puts a
// sample on the crest), VDV = A·(3T/8)^¼ (∫sin⁴ = 3T/8; the rectangle sum of sin⁴ over whole
// periods is exact with ≥ 5 samples a period), and every 1 s window holds 2 whole periods, so
// the running RMS is A/√2 everywhere and MTVV = RMS.
TEST(ComfortMetrics, SineAgainstClosedForms) {
  const double a = 1.7, f = 2.0, fs = 1000.0, duration = 10.0;
  const std::vector<double> x = sine(a, f, fs, duration);
  const double rms = a / std::sqrt(2.0);
  EXPECT_NEAR(weighted_rms(x, fs), rms, 1e-12);
  EXPECT_NEAR(crest_factor(x, fs), std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(vibration_dose_value(x, fs), a * std::pow(3.0 * duration / 8.0, 0.25), 1e-12);
  EXPECT_NEAR(maximum_transient_vibration_value(x, fs), rms, 1e-12);

  const std::vector<double> running = running_rms(x, fs);
  ASSERT_EQ(running.size(), x.size() - 1000 + 1);
  for (double r : running) ASSERT_NEAR(r, rms, 1e-12);

  const VibrationMetrics m = vibration_metrics(x, fs);
  EXPECT_DOUBLE_EQ(m.duration_s, duration);
  EXPECT_NEAR(m.weighted_rms_m_per_s2, rms, 1e-12);
  EXPECT_NEAR(m.peak_m_per_s2, a, 1e-12);
  EXPECT_NEAR(m.crest_factor, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(m.mtvv_m_per_s2, rms, 1e-12);
  EXPECT_NEAR(m.vdv_m_per_s1_75, a * std::pow(3.0 * duration / 8.0, 0.25), 1e-12);

  // Nothing to report for a steady sine: crest √2, MTVV/a_w = 1, VDV/(a_w·T^¼) = (3/8)^¼·√2.
  const AdditionalMethodsCheck check = check_additional_methods(m);
  EXPECT_FALSE(check.additional_methods_required());
  EXPECT_TRUE(check.reasons.empty());
  EXPECT_NEAR(check.mtvv_ratio, 1.0, 1e-12);
  EXPECT_NEAR(check.vdv_ratio, std::pow(3.0 / 8.0, 0.25) * std::sqrt(2.0), 1e-12);
}

// Linear integration over exactly N = τ·fs samples: a unit step after n0 zeros gives
// √(k/N) while the step fills the window, then 1.
TEST(ComfortMetrics, RunningRmsIsRectangularOverTau) {
  const double fs = 100.0, tau = 0.5;  // N = 50
  std::vector<double> x(300, 0.0);
  for (std::size_t i = 120; i < x.size(); ++i) x[i] = 1.0;
  const std::vector<double> r = running_rms(x, fs, tau);
  ASSERT_EQ(r.size(), 251u);
  EXPECT_EQ(r[70], 0.0);                              // window 70…119: all zero
  EXPECT_NEAR(r[71], std::sqrt(1.0 / 50.0), 1e-15);   // window 71…120: one sample of 1
  EXPECT_NEAR(r[95], std::sqrt(25.0 / 50.0), 1e-15);  // 95…144: ones from 120 on
  EXPECT_NEAR(r[120], 1.0, 1e-15);
  EXPECT_NEAR(maximum_transient_vibration_value(x, fs, tau), 1.0, 1e-15);
}

// The sliding sum stays exact on a long noisy record (it is re-summed every window).
TEST(ComfortMetrics, RunningRmsMatchesDirectSumsOnNoise) {
  std::mt19937_64 rng(2631);
  std::normal_distribution<double> noise(0.0, 1.0);
  const double fs = 200.0;
  std::vector<double> x(20'000);
  for (double& v : x) v = noise(rng) * (1.0 + 100.0 * static_cast<double>(&v - x.data() > 5000));
  const std::vector<double> r = running_rms(x, fs, 1.0);
  for (std::size_t i : {0u, 4999u, 5001u, 12'345u, 19'800u}) {
    double sum = 0.0;
    for (std::size_t j = i; j < i + 200; ++j) sum += x[j] * x[j];
    EXPECT_NEAR(r[i], std::sqrt(sum / 200.0), 1e-12 * std::sqrt(sum / 200.0)) << i;
  }
}

// A steady 5 Hz sine (0.5 m/s²) with one 20 ms, 15 m/s² shock: the crest factor (≈ 26) is far
// above 9, MTVV/a_w (≈ 3.6) above 1.5 and VDV/(a_w·T^¼) (≈ 4.5) above 1.75: all three flagged,
// each with its reason. Passed through Wk first, as a real record would be.
TEST(ComfortMetrics, ShockTriggersTheAdditionalMethodsRule) {
  const double fs = 1000.0;
  std::vector<double> x = sine(0.5, 5.0, fs, 30.0);
  for (std::size_t i = 20'000; i < 20'020; ++i) x[i] += 15.0;
  std::vector<double> aw = apply_weighting(Weighting::kWk, x, fs);
  aw.erase(aw.begin(), aw.begin() + 10'000);  // drop the filter's start-up transient

  const VibrationMetrics m = vibration_metrics(aw, fs);
  const AdditionalMethodsCheck check = check_additional_methods(m);
  EXPECT_GT(m.crest_factor, 9.0);
  EXPECT_TRUE(check.crest_factor_exceeded);
  EXPECT_TRUE(check.mtvv_ratio_exceeded);
  EXPECT_TRUE(check.vdv_ratio_exceeded);
  EXPECT_TRUE(check.additional_methods_required());
  ASSERT_EQ(check.reasons.size(), 3u);
  EXPECT_NE(check.reasons[0].find("crest factor"), std::string::npos) << check.reasons[0];
  EXPECT_NE(check.reasons[1].find("MTVV"), std::string::npos) << check.reasons[1];
  EXPECT_NE(check.reasons[2].find("VDV"), std::string::npos) << check.reasons[2];

  // Without the shock the same record is steady.
  std::vector<double> calm = apply_weighting(Weighting::kWk, sine(0.5, 5.0, fs, 30.0), fs);
  calm.erase(calm.begin(), calm.begin() + 10'000);
  EXPECT_FALSE(check_additional_methods(vibration_metrics(calm, fs)).additional_methods_required());
}

TEST(ComfortMetrics, RuleLimitsAreStrict) {
  VibrationMetrics m{.duration_s = 16.0,  // T^¼ = 2
                     .weighted_rms_m_per_s2 = 1.0,
                     .peak_m_per_s2 = 9.0,
                     .crest_factor = 9.0,
                     .mtvv_m_per_s2 = 1.5,
                     .vdv_m_per_s1_75 = 3.5};
  AdditionalMethodsCheck check = check_additional_methods(m);
  EXPECT_NEAR(check.vdv_ratio, 1.75, 1e-15);
  EXPECT_FALSE(check.additional_methods_required());
  m.crest_factor = 9.01;
  m.vdv_m_per_s1_75 = 3.51;
  check = check_additional_methods(m);
  EXPECT_TRUE(check.crest_factor_exceeded);
  EXPECT_FALSE(check.mtvv_ratio_exceeded);
  EXPECT_TRUE(check.vdv_ratio_exceeded);
  EXPECT_EQ(check.reasons.size(), 2u);
}

TEST(ComfortMetrics, BadInputIsInputError) {
  std::vector<double> x(2000, 0.3);
  x[1234] = std::numeric_limits<double>::quiet_NaN();
  try {
    vibration_metrics(x, 1000.0);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sample 1234"), std::string::npos) << e.what();
  }
  EXPECT_THROW(vibration_dose_value(x, 1000.0), InputError);
  EXPECT_THROW(crest_factor(x, 1000.0), InputError);
  const std::vector<double> ok(500, 0.3);
  EXPECT_THROW(weighted_rms({}, 1000.0), InputError);
  EXPECT_THROW(weighted_rms(ok, 0.0), InputError);
  EXPECT_THROW(running_rms(ok, 1000.0, 1.0), InputError);  // 0.5 s record, τ = 1 s
  EXPECT_THROW(running_rms(ok, 1000.0, 0.0), InputError);
  EXPECT_NO_THROW(running_rms(ok, 1000.0, 0.5));
}

}  // namespace
}  // namespace ridefit::comfort
