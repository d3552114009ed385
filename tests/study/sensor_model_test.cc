// The sensor model: its band limits at their corners, the noise it adds, the mount's peak, and
// bad settings.
#include "ridefit/study/sensor_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/signal/statistics.h"

namespace ridefit::study {
namespace {

constexpr double kRate_Hz = 500.0;

// The steady-state gain of the (noise-free) sensor for a sine at f.
double gain(const SensorModel& sensor, double f) {
  std::vector<double> x(static_cast<std::size_t>(40 * kRate_Hz));
  for (std::size_t k = 0; k < x.size(); ++k) {
    x[k] = std::sin(2.0 * std::numbers::pi * f * static_cast<double>(k) / kRate_Hz);
  }
  std::mt19937_64 rng(1);
  const auto y = measure(x, kRate_Hz, sensor, rng);
  const std::size_t half = x.size() / 2;  // after the transient
  return signal::rms(std::span(y).subspan(half)) / signal::rms(std::span(x).subspan(half));
}

TEST(SensorModel, ButterworthCornersAreMinusThreeDecibels) {
  SensorModel sensor;
  sensor.noise_fraction = 0.0;
  sensor.high_pass_Hz = 1.0;
  sensor.low_pass_Hz = 50.0;
  EXPECT_NEAR(20.0 * std::log10(gain(sensor, 50.0)), -3.01, 0.05);
  EXPECT_NEAR(20.0 * std::log10(gain(sensor, 1.0)), -3.01, 0.05);
  EXPECT_NEAR(gain(sensor, 7.0), 1.0, 0.01);  // flat in between
}

TEST(SensorModel, NoiseIsTheRequestedShareOfTheSignalsRms) {
  std::vector<double> x(100000);
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = 3.0 * std::sin(0.05 * static_cast<double>(k));
  SensorModel sensor;
  sensor.noise_fraction = 0.02;
  sensor.high_pass_Hz = 0.0;
  sensor.low_pass_Hz = 0.45 * kRate_Hz;
  std::mt19937_64 a(3), b(3);
  SensorModel clean = sensor;
  clean.noise_fraction = 0.0;
  const auto noisy = measure(x, kRate_Hz, sensor, a);
  const auto filtered = measure(x, kRate_Hz, clean, b);
  std::vector<double> e(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) e[k] = noisy[k] - filtered[k];
  EXPECT_NEAR(signal::rms(e) / signal::rms(x), 0.02, 0.002);
}

TEST(SensorModel, AMountAddsItsResonance) {
  SensorModel sensor;
  sensor.noise_fraction = 0.0;
  sensor.mount = SensorMount{12.0, 0.05};
  // Transmissibility at resonance sqrt(1 + (2ζ)²)/(2ζ) ≈ 10.05.
  EXPECT_NEAR(gain(sensor, 12.0), std::sqrt(1.0 + 0.01) / 0.1, 0.3);
  EXPECT_NEAR(gain(sensor, 2.0), 1.03, 0.02);
}

TEST(SensorModel, BadSettingsAreInputErrors) {
  std::vector<double> x(100, 1.0);
  std::mt19937_64 rng(1);
  SensorModel s;
  s.noise_fraction = -0.1;
  EXPECT_THROW(measure(x, kRate_Hz, s, rng), InputError);
  s = {};
  s.low_pass_Hz = 300.0;  // above Nyquist
  EXPECT_THROW(measure(x, kRate_Hz, s, rng), InputError);
  s = {};
  s.high_pass_Hz = 200.0;  // above the default low-pass
  EXPECT_THROW(measure(x, kRate_Hz, s, rng), InputError);
  s = {};
  s.mount = SensorMount{400.0, 0.05};
  EXPECT_THROW(measure(x, kRate_Hz, s, rng), InputError);
}

}  // namespace
}  // namespace ridefit::study
