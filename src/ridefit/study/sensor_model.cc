#include "ridefit/study/sensor_model.h"

#include <fmt/core.h>

#include <cmath>
#include <numbers>

#include "ridefit/common/errors.h"
#include "ridefit/signal/biquad_cascade.h"
#include "ridefit/signal/statistics.h"

namespace ridefit::study {

std::vector<double> measure(std::span<const double> truth, double fs, const SensorModel& sensor,
                            std::mt19937_64& rng) {
  const double nyquist = 0.5 * fs;
  const double low_pass = sensor.low_pass_Hz > 0.0 ? sensor.low_pass_Hz : 0.4 * fs;
  if (!(sensor.noise_fraction >= 0.0) || !std::isfinite(sensor.noise_fraction)) {
    throw InputError(fmt::format("sensor noise {}: expected a fraction >= 0 of the signal's RMS",
                                 sensor.noise_fraction));
  }
  if (!(low_pass < nyquist) || !(sensor.high_pass_Hz >= 0.0) || !(sensor.high_pass_Hz < low_pass)) {
    throw InputError(fmt::format(
        "sensor band {}–{} Hz: expected 0 <= high_pass_Hz < low_pass_Hz < {} Hz (Nyquist)",
        sensor.high_pass_Hz, low_pass, nyquist));
  }
  std::vector<signal::AnalogueSection> sections;
  if (sensor.mount) {
    const double f = sensor.mount->frequency_Hz, zeta = sensor.mount->damping_ratio;
    if (!(f > 0.0 && f < nyquist) || !(zeta > 0.0)) {
      throw InputError(fmt::format(
          "sensor mount at {} Hz with damping ratio {}: expected 0 < f < {} Hz and a ratio > 0", f,
          zeta, nyquist));
    }
    const double w = 2.0 * std::numbers::pi * f;
    sections.push_back({{w * w, 2.0 * zeta * w, 0.0}, {w * w, 2.0 * zeta * w, 1.0}, f});
  }
  const double wl = 2.0 * std::numbers::pi * low_pass;
  sections.push_back({{wl * wl, 0.0, 0.0}, {wl * wl, std::numbers::sqrt2 * wl, 1.0}, low_pass});
  if (sensor.high_pass_Hz > 0.0) {
    const double wh = 2.0 * std::numbers::pi * sensor.high_pass_Hz;
    sections.push_back(
        {{0.0, 0.0, 1.0}, {wh * wh, std::numbers::sqrt2 * wh, 1.0}, sensor.high_pass_Hz});
  }
  std::vector<double> out = signal::BiquadCascade::from_analogue(sections, fs).filter(truth);
  const double sigma = sensor.noise_fraction * signal::rms(truth);
  if (sigma > 0.0) {
    std::normal_distribution<double> normal(0.0, sigma);
    for (double& v : out) v += normal(rng);
  }
  return out;
}

}  // namespace ridefit::study
