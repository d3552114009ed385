// The band a motion excites and the share of a residual within it: a closed form for sines and
// white noise of known powers.
#include "ridefit/signal/excitation_band.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "ridefit/common/errors.h"

namespace ridefit::signal {
namespace {

TEST(ExcitationBand, FindsTheMotionsBandAndTheResidualsShareInIt) {
  const double rate_Hz = 1000.0;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  // A random motion: 40 sines of equal velocity at frequencies drawn from 0.5–10 Hz.
  std::uniform_real_distribution<double> frequency(0.5, 10.0), angle(0.0, 2.0 * std::numbers::pi);
  std::vector<double> f(40), phase(40);
  for (std::size_t i = 0; i < f.size(); ++i) {
    f[i] = frequency(rng);
    phase[i] = angle(rng);
  }
  std::vector<double> velocity, residual;
  for (int k = 0; k < 20000; ++k) {
    const double t = k / rate_Hz;
    double v = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      v += std::sin(2.0 * std::numbers::pi * f[i] * t + phase[i]);
    }
    velocity.push_back(v);
    // Power 2 at 5 Hz, in the band, and white noise of power 1 over 0–500 Hz.
    residual.push_back(2.0 * std::sin(2.0 * std::numbers::pi * 5.0 * t) + noise(rng));
  }
  const ExcitationBand band = excitation_band(velocity, residual, rate_Hz);
  EXPECT_GT(band.band_Hz, 9.0);
  EXPECT_LT(band.band_Hz, 11.5);
  const double expected = (2.0 + band.band_Hz / 500.0) / 3.0;
  EXPECT_NEAR(band.residual_in_band_share, expected, 0.03);
  EXPECT_LT(band.repeat_correlation, 0.5);  // it never repeats
}

TEST(ExcitationBand, SaysASineOrATriangleRepeats) {
  const double rate_Hz = 500.0;
  std::vector<double> sine, square, residual;
  for (int k = 0; k < 5000; ++k) {
    const double phase = 2.0 * std::numbers::pi * 2.0 * k / rate_Hz;
    sine.push_back(std::cos(phase));
    square.push_back(std::cos(phase) >= 0.0 ? 1.0 : -1.0);  // a triangle's velocity
    residual.push_back(std::sin(7.0 * phase));
  }
  EXPECT_GT(excitation_band(sine, residual, rate_Hz).repeat_correlation, 0.95);
  EXPECT_GT(excitation_band(square, residual, rate_Hz).repeat_correlation, 0.95);
}

TEST(ExcitationBand, RefusesBadSeries) {
  const std::vector<double> a(200, 1.0), b(199, 1.0), short_one(100, 1.0);
  EXPECT_THROW(excitation_band(a, b, 100.0), InputError);
  EXPECT_THROW(excitation_band(short_one, short_one, 100.0), InputError);
  EXPECT_THROW(excitation_band(a, a, 100.0, 0.0), InputError);
  EXPECT_THROW(excitation_band(a, a, 0.0), InputError);
}

}  // namespace
}  // namespace ridefit::signal
