#include "ridefit/signal/quantisation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "ridefit/signal/zero_phase_low_pass.h"

namespace ridefit::signal {
namespace {

constexpr double kPi = std::numbers::pi;

struct Record {
  std::vector<double> time_s, exact_m, velocity_m_per_s;
};

// A 10 mm, 2 Hz sine sampled at 1 kHz for 5 s on a rest position, as the MR press records it.
Record press_sine(double rate_Hz = 1000.0) {
  Record r;
  for (int k = 0; k <= static_cast<int>(5.0 * rate_Hz); ++k) {
    const double t = k / rate_Hz;
    r.time_s.push_back(t);
    r.exact_m.push_back(-0.0123 + 0.01 * std::sin(2 * kPi * 2.0 * t));
    r.velocity_m_per_s.push_back(0.01 * 2 * kPi * 2.0 * std::cos(2 * kPi * 2.0 * t));
  }
  return r;
}

std::vector<double> quantised(const std::vector<double>& x, double q) {
  std::vector<double> out;
  for (double v : x) out.push_back(q * std::round(v / q));
  return out;
}

TEST(QuantisationStep, FindsTheLatticeOfARecord) {
  const Record r = press_sine();
  EXPECT_NEAR(quantisation_step(quantised(r.exact_m, 3e-6)), 3e-6, 1e-9);
  // An ADC's 3.05 µm step exported to 0.1 µm: the gaps are 3.0 and 3.1 µm.
  std::vector<double> exported;
  for (double v : quantised(r.exact_m, 3.05e-6)) exported.push_back(1e-7 * std::round(v / 1e-7));
  EXPECT_NEAR(quantisation_step(exported), 3.05e-6, 0.06e-6);
  // Values of a computation are on no step, nor is a measurement with noise above its step.
  EXPECT_EQ(quantisation_step(r.exact_m), 0.0);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 2e-6);
  std::vector<double> noisy;
  for (double v : r.exact_m) noisy.push_back(v + noise(rng));
  EXPECT_EQ(quantisation_step(noisy), 0.0);
  EXPECT_EQ(quantisation_step(std::vector<double>(100, 0.01)), 0.0);
}

// The cut-off lies above the motion's content and the low-pass takes the steps' velocity spikes
// out: the forward-difference velocity of the filtered record is within a small share of the
// exact velocity, where the raw staircase's is off by q·fs/√6 RMS.
TEST(QuantisationLowPass, RemovesTheStepsVelocityAndKeepsTheMotion) {
  const Record r = press_sine();
  const auto x = quantised(r.exact_m, 3e-6);
  const QuantisationLowPass choice = choose_quantisation_low_pass(r.time_s, x);
  EXPECT_NEAR(choice.step, 3e-6, 1e-9);
  ASSERT_GT(choice.cutoff_Hz, 0.0) << choice.reason << " content " << choice.content_up_to_Hz;
  EXPECT_GE(choice.content_up_to_Hz, 2.0);
  EXPECT_LT(choice.cutoff_Hz, 100.0);
  // Closed form of the unfiltered noise: Δq/Δt with Var Δq = q²/6.
  EXPECT_NEAR(choice.velocity_noise_rms_before, 3e-6 * 1000.0 / std::sqrt(6.0), 1e-6);
  EXPECT_LT(choice.velocity_noise_rms_after, 0.05 * choice.velocity_noise_rms_before);
  const auto y = zero_phase_low_pass(x, 1000.0, choice.cutoff_Hz);
  auto velocity_error_rms = [&](const std::vector<double>& d) {
    double sum = 0.0;
    int count = 0;
    for (std::size_t k = 100; k + 101 < d.size(); ++k) {
      const double v = (d[k + 1] - d[k]) * 1000.0;
      const double exact = 0.5 * (r.velocity_m_per_s[k] + r.velocity_m_per_s[k + 1]);
      sum += (v - exact) * (v - exact);
      ++count;
    }
    return std::sqrt(sum / count);
  };
  const double raw = velocity_error_rms(x), filtered = velocity_error_rms(y);
  EXPECT_NEAR(raw, choice.velocity_noise_rms_before, 0.2 * choice.velocity_noise_rms_before);
  EXPECT_LT(filtered, 0.15 * raw);
  // The motion is kept: displacement within a quantum of the exact one.
  for (std::size_t k = 0; k < y.size(); k += 50) EXPECT_NEAR(y[k], r.exact_m[k], 3e-6);
}

TEST(QuantisationLowPass, LeavesRecordsAloneWhereNothingIsGained) {
  const Record r = press_sine();
  // Not quantised.
  const auto exact = choose_quantisation_low_pass(r.time_s, r.exact_m);
  EXPECT_EQ(exact.cutoff_Hz, 0.0);
  EXPECT_FALSE(exact.reason.empty());
  // Content up to the Nyquist frequency: a broadband record on a fine step.
  std::mt19937 rng(3);
  std::normal_distribution<double> white(0.0, 1e-3);
  std::vector<double> broadband;
  for (std::size_t k = 0; k < r.time_s.size(); ++k) broadband.push_back(white(rng));
  const auto wide = choose_quantisation_low_pass(r.time_s, quantised(broadband, 1e-6));
  EXPECT_GT(wide.step, 0.0);
  EXPECT_EQ(wide.cutoff_Hz, 0.0);
  EXPECT_NE(wide.reason.find("content"), std::string::npos) << wide.reason;
  // Time steps that vary by ±40 %.
  auto uneven = r.time_s;
  for (std::size_t k = 1; k < uneven.size(); k += 2) uneven[k] += 0.4e-3;
  const auto jittered = choose_quantisation_low_pass(uneven, quantised(r.exact_m, 3e-6));
  EXPECT_EQ(jittered.cutoff_Hz, 0.0);
  EXPECT_NE(jittered.reason.find("uneven"), std::string::npos) << jittered.reason;
}

}  // namespace
}  // namespace ridefit::signal
