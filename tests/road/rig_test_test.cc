// The rig tests that `simulate-rig` runs (road/rig_test.h): their motions against closed forms,
// the random test's RMS and band, and every limit a test can break.
#include "ridefit/road/rig_test.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <vector>

#include "support/throws_input_error.h"

namespace ridefit::road {
namespace {

using testing::throws_input_error;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

RigTest sine(double amplitude_m, double frequency_Hz) {
  RigTest t;
  t.waveform = RigWaveform::kSine;
  t.amplitude_m = amplitude_m;
  t.frequency_Hz = frequency_Hz;
  return t;
}

RigTest triangle(double amplitude_m, double speed_m_per_s, double duration_s) {
  RigTest t;
  t.waveform = RigWaveform::kTriangle;
  t.amplitude_m = amplitude_m;
  t.speed_m_per_s = speed_m_per_s;
  t.duration_s = duration_s;
  t.sample_rate_Hz = 200.0;
  return t;
}

RigTest random_test(double rms_m, double low_Hz, double high_Hz, unsigned seed) {
  RigTest t;
  t.waveform = RigWaveform::kRandom;
  t.rms_m = rms_m;
  t.band_low_Hz = low_Hz;
  t.band_high_Hz = high_Hz;
  t.seed = seed;
  t.duration_s = 8.0;
  t.sample_rate_Hz = 500.0;
  return t;
}

TEST(RigTest, SineIsItsClosedForm) {
  const RigTest t = sine(0.01, 2.0);
  t.validate();
  const RigMotion m(t);
  for (double time : {0.0, 0.1, 0.37, 1.25}) {
    EXPECT_NEAR(m.displacement_m(time), 0.01 * std::sin(kTwoPi * 2.0 * time), 1e-15);
    EXPECT_NEAR(m.velocity_m_per_s(time), 0.01 * kTwoPi * 2.0 * std::cos(kTwoPi * 2.0 * time),
                1e-14);
  }
  EXPECT_DOUBLE_EQ(m.peak_displacement_m(), 0.01);
  EXPECT_DOUBLE_EQ(m.peak_velocity_m_per_s(), 0.01 * kTwoPi * 2.0);
  EXPECT_EQ(m.sample_times_s().size(), 10000u);  // 10 s at 1 kHz
  EXPECT_DOUBLE_EQ(m.sample_times_s()[1], 1e-3);
}

TEST(RigTest, TriangleTurnsAtItsAmplitudeAtConstantSpeed) {
  const RigTest t = triangle(0.003, 0.001, 24.0);  // period 12 s
  t.validate();
  const RigMotion m(t);
  EXPECT_NEAR(m.displacement_m(3.0), 0.003, 1e-15);
  EXPECT_NEAR(m.displacement_m(6.0), 0.0, 1e-15);
  EXPECT_NEAR(m.displacement_m(9.0), -0.003, 1e-15);
  EXPECT_NEAR(m.displacement_m(13.5), 0.0015, 1e-15);  // the second cycle
  EXPECT_DOUBLE_EQ(m.velocity_m_per_s(1.0), 0.001);
  EXPECT_DOUBLE_EQ(m.velocity_m_per_s(4.0), -0.001);
  EXPECT_DOUBLE_EQ(m.velocity_m_per_s(10.0), 0.001);
  EXPECT_DOUBLE_EQ(m.lowest_frequency_Hz(), 1.0 / 12.0);
}

TEST(RigTest, RandomTestHasItsRmsAndNothingOutsideItsBand) {
  const RigTest t = random_test(0.002, 1.0, 12.0, 5);
  t.validate();
  const RigMotion m(t);
  std::vector<double> time, x, v;
  m.samples(time, x, v);
  ASSERT_EQ(x.size(), 4000u);
  double square = 0.0;
  for (double value : x) square += value * value;
  EXPECT_NEAR(std::sqrt(square / static_cast<double>(x.size())), 0.002, 1e-12);
  // The samples' DFT on the 1/T grid: the band's lines carry it all.
  double inside = 0.0, outside = 0.0;
  for (int k = 1; k < 200; ++k) {
    std::complex<double> sum = 0.0;
    for (std::size_t n = 0; n < x.size(); ++n) {
      sum += x[n] *
             std::polar(1.0, -kTwoPi * k * static_cast<double>(n) / static_cast<double>(x.size()));
    }
    const double f_Hz = k / t.duration_s;
    (f_Hz >= 1.0 - 1e-9 && f_Hz <= 12.0 + 1e-9 ? inside : outside) += std::norm(sum);
  }
  EXPECT_LT(outside, 1e-20 * inside);
  // The samples (each line's phasor turned step by step) are the sum of sines at every instant.
  for (std::size_t n : {0u, 1u, 1234u, 3999u}) {
    EXPECT_NEAR(x[n], m.displacement_m(time[n]), 1e-13);
    EXPECT_NEAR(v[n], m.velocity_m_per_s(time[n]), 1e-11);
  }
  // The velocity is the displacement's rate (central differences at 1 µs).
  for (double s : {0.3, 2.71, 7.9}) {
    EXPECT_NEAR(m.velocity_m_per_s(s),
                (m.displacement_m(s + 1e-6) - m.displacement_m(s - 1e-6)) / 2e-6, 1e-7);
  }
  // The seed fixes the phases.
  const RigMotion again(t), other(random_test(0.002, 1.0, 12.0, 6));
  EXPECT_EQ(again.displacement_m(1.234), m.displacement_m(1.234));
  EXPECT_NE(other.displacement_m(1.234), m.displacement_m(1.234));
}

TEST(RigTest, EachBadValueOrBrokenLimitIsNamed) {
  struct Case {
    RigTest test;
    RigLimits limits;
    std::string words;
  };
  RigLimits small_rig;
  small_rig.stroke_m = 0.02;
  RigLimits slow_rig;
  slow_rig.frequency_Hz = 5.0;
  RigLimits broken_rig;
  broken_rig.velocity_m_per_s = -1.0;
  RigTest short_test = sine(0.01, 0.1);  // a cycle takes 10 s
  short_test.duration_s = 5.0;
  RigTest coarse = sine(0.01, 10.0);
  coarse.sample_rate_Hz = 100.0;
  RigTest no_line = random_test(0.002, 1.01, 1.1, 1);  // lines every 0.125 Hz: none in between
  RigTest nan_duration = sine(0.01, 2.0);
  nan_duration.duration_s = std::nan("");
  const std::vector<Case> cases = {
      {sine(-0.01, 2.0), {}, "amplitude_m: -0.01 is not a positive finite number"},
      {sine(0.01, std::nan("")), {}, "frequency_Hz: nan"},
      {nan_duration, {}, "duration_s: nan"},
      {triangle(0.003, 0.0, 24.0), {}, "speed_m_per_s: 0"},
      {random_test(0.002, 12.0, 1.0, 1), {}, "band_low_Hz: 12 Hz must be at least 0 and below"},
      {no_line, {}, "holds no line of a 8 s test"},
      {short_test, {}, "duration_s: 5 s is shorter than one cycle of the test (10 s at 0.1 Hz)"},
      {coarse, {}, "sample_rate_Hz: 100 Hz gives 10 samples per cycle at 10 Hz; give at least 200"},
      {sine(0.03, 1.0), small_rig,
       "amplitude_m: the test reaches ±30 mm, beyond the rig's stroke "
       "(±20 mm, rig.stroke_m); at most 20 mm fits"},
      {sine(0.04, 8.0), {}, "the test moves at up to 2.011 m/s, beyond the rig's 1.5 m/s"},
      {triangle(0.05, 2.0, 1.0), {}, "speed_m_per_s: the test moves at up to 2 m/s"},
      {sine(0.001, 8.0), slow_rig, "frequency_Hz: the test's motion reaches 8 Hz, above the 5 Hz"},
      {random_test(0.001, 1.0, 12.0, 1), slow_rig, "band_high_Hz: the test's motion reaches 12 Hz"},
      {sine(0.01, 2.0), broken_rig, "rig.velocity_m_per_s: -1 is not a positive finite number"},
  };
  for (const auto& c : cases) {
    EXPECT_TRUE(throws_input_error([&] { c.test.validate(c.limits); }, c.words)) << c.words;
  }
  // A random test's size that breaks the stroke is answered with the RMS that fits.
  RigLimits tight;
  tight.stroke_m = 0.004;
  const RigTest big = random_test(0.002, 1.0, 12.0, 5);
  const double peak = RigMotion(big).peak_displacement_m();
  ASSERT_GT(peak, 0.004);
  EXPECT_TRUE(throws_input_error([&] { big.validate(tight); },
                                 fmt::format("rms_m: the test reaches ±{:.4g} mm", 1e3 * peak)));
}

}  // namespace
}  // namespace ridefit::road
