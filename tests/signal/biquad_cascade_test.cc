#include "ridefit/signal/biquad_cascade.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "ridefit/common/errors.h"

namespace ridefit::signal {
namespace {

constexpr double kPi = std::numbers::pi;

// Second-order Butterworth low-pass ω²/(s² + √2·ω·s + ω²) at f_c.
AnalogueSection butterworth_low_pass(double cutoff_Hz) {
  const double w = 2.0 * kPi * cutoff_Hz;
  return {.numerator = {w * w, 0.0, 0.0},
          .denominator = {w * w, std::sqrt(2.0) * w, 1.0},
          .prewarp_frequency_Hz = cutoff_Hz};
}

TEST(BiquadCascade, BilinearMatchesAnalogueAtPrewarpDcAndMapsInfinityToNyquist) {
  const double fs = 1000.0, fc = 120.0;
  const AnalogueSection section = butterworth_low_pass(fc);
  const BiquadCascade cascade({bilinear_transform(section, fs)}, fs);
  const std::complex<double> at_cutoff = cascade.response(fc);
  EXPECT_NEAR(std::abs(at_cutoff - analogue_response(section, fc)), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(at_cutoff), std::sqrt(0.5), 1e-12);  // −3 dB exactly, pre-warped
  EXPECT_NEAR(std::abs(cascade.response(0.0)), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(cascade.response(fs / 2.0)), 0.0, 1e-12);  // s → ∞ lands on z = −1
}

TEST(BiquadCascade, DigitalResponseIsAnalogueOnTheWarpedFrequencyAxis) {
  const double fs = 500.0, fp = 40.0;
  const AnalogueSection section{
      .numerator = {3.0, 0.02, 1e-4}, .denominator = {2.0, 0.01, 3e-5}, .prewarp_frequency_Hz = fp};
  const BiquadCascade cascade = BiquadCascade::from_analogue(std::vector{section}, fs);
  for (double f : {0.5, 5.0, 40.0, 100.0, 200.0, 240.0}) {
    const double warped = fp * std::tan(kPi * f / fs) / std::tan(kPi * fp / fs);
    const std::complex<double> expected = analogue_response(section, warped);
    EXPECT_NEAR(std::abs(cascade.response(f) - expected), 0.0, 1e-10 * std::abs(expected))
        << "f = " << f;
  }
}

TEST(BiquadCascade, ImpulseResponseFollowsTheDifferenceEquation) {
  const Biquad q{.b0 = 0.3, .b1 = -0.2, .b2 = 0.05, .a1 = -1.1, .a2 = 0.4};
  const BiquadCascade cascade({q}, 100.0);
  std::vector<double> impulse(6, 0.0);
  impulse[0] = 1.0;
  const std::vector<double> y = cascade.filter(impulse);
  std::vector<double> expected(6);
  for (std::size_t n = 0; n < 6; ++n) {
    const double x0 = impulse[n], x1 = n >= 1 ? impulse[n - 1] : 0.0,
                 x2 = n >= 2 ? impulse[n - 2] : 0.0;
    const double y1 = n >= 1 ? expected[n - 1] : 0.0, y2 = n >= 2 ? expected[n - 2] : 0.0;
    expected[n] = q.b0 * x0 + q.b1 * x1 + q.b2 * x2 - q.a1 * y1 - q.a2 * y2;
  }
  for (std::size_t n = 0; n < 6; ++n) EXPECT_NEAR(y[n], expected[n], 1e-15) << "n = " << n;
}

TEST(BiquadCascade, CascadeEqualsSectionsAppliedInTurn) {
  const double fs = 800.0;
  const BiquadCascade a = BiquadCascade::from_analogue(std::vector{butterworth_low_pass(50.0)}, fs);
  const BiquadCascade b = BiquadCascade::from_analogue(std::vector{butterworth_low_pass(90.0)}, fs);
  const BiquadCascade both({a.sections()[0], b.sections()[0]}, fs);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> x(2000);
  for (double& v : x) v = noise(rng);
  const std::vector<double> in_turn = b.filter(a.filter(x));
  const std::vector<double> together = both.filter(x);
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(together[i], in_turn[i], 1e-12);
  EXPECT_NEAR(std::abs(both.response(70.0) - a.response(70.0) * b.response(70.0)), 0.0, 1e-14);
}

TEST(BiquadCascade, SineSteadyStateAmplitudeEqualsResponseMagnitude) {
  const double fs = 1000.0, f = 37.0;
  const BiquadCascade cascade =
      BiquadCascade::from_analogue(std::vector{butterworth_low_pass(30.0)}, fs);
  std::vector<double> x(4000);
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = std::sin(2.0 * kPi * f * static_cast<double>(i) / fs);
  }
  const std::vector<double> y = cascade.filter(x);
  double peak = 0.0;
  for (std::size_t i = 2000; i < y.size(); ++i) peak = std::max(peak, std::abs(y[i]));
  // 27 samples a period: the sampled peak is within 1 − cos(π/27) ≈ 0.7 % below the true one.
  EXPECT_NEAR(peak, std::abs(cascade.response(f)), 0.008 * std::abs(cascade.response(f)));
}

TEST(BiquadCascade, PrewarpAtOrAboveNyquistOrBadRateIsInputError) {
  EXPECT_THROW(bilinear_transform(butterworth_low_pass(100.0), 200.0), InputError);
  EXPECT_THROW(bilinear_transform(butterworth_low_pass(100.0), 0.0), InputError);
  try {
    bilinear_transform(butterworth_low_pass(100.0), 150.0);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sample faster than 200 Hz"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace ridefit::signal
