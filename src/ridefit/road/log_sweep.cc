#include "ridefit/road/log_sweep.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ridefit/common/errors.h"
#include "ridefit/road/road_limits.h"

namespace ridefit::road {
namespace {

constexpr double kMaxSweepAmplitude_m = 1.0;

void require_positive(const char* key, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(fmt::format("key '{}' is {}, expected a finite value > 0", key, value));
  }
}

void require_frequency(const char* key, double value) {
  require_positive(key, value);
  if (!(value <= kMaxSweepFrequency_Hz)) {
    throw InputError(fmt::format(
        "key '{}' is {:g} Hz, expected at most {:g} Hz (a quarter car's wheel hop is at 10–15 Hz; "
        "its models mean nothing at a few hundred Hz)",
        key, value, kMaxSweepFrequency_Hz));
  }
}

// A shaker's stroke is about ±0.1 m: beyond 1 m it is no road (and near 1e308 the rate
// A·2πf overflows).
void require_amplitude(const char* key, double value) {
  require_positive(key, value);
  if (!(value <= kMaxSweepAmplitude_m)) {
    throw InputError(fmt::format("key '{}' is {:g} m, expected at most {:g} m", key, value,
                                 kMaxSweepAmplitude_m));
  }
}

}  // namespace

void LogSweepParameters::validate() const {
  require_frequency("start_frequency_Hz", start_frequency_Hz);
  require_frequency("end_frequency_Hz", end_frequency_Hz);
  require_amplitude("initial_amplitude_m", initial_amplitude_m);
  require_amplitude("end_amplitude_m", end_amplitude_m);
  require_positive("duration_s", duration_s);
  if (!(duration_s >= kMinRoadDuration_s)) {
    throw InputError(fmt::format("key 'duration_s' is {:g} s, expected at least {:g} s", duration_s,
                                 kMinRoadDuration_s));
  }
  // An adaptive integrator steps at most max_step_s() = 0.25/f_max.
  const double max_frequency_Hz = std::max(start_frequency_Hz, end_frequency_Hz);
  const double steps = duration_s * 4.0 * max_frequency_Hz;
  if (!(steps <= kMaxRoadSamples)) {
    throw InputError(fmt::format(
        "key 'duration_s' is {:g} s: a sweep up to {:g} Hz is integrated in steps of at most a "
        "quarter period ({:g} s), {:.3g} steps, more than {:g}; expected duration_s <= {:g} s",
        duration_s, max_frequency_Hz, 0.25 / max_frequency_Hz, steps, kMaxRoadSamples,
        kMaxRoadSamples * 0.25 / max_frequency_Hz));
  }
}

LogSweep::LogSweep(const LogSweepParameters& parameters)
    : parameters_(parameters), frequency_log_rate_per_s_(0.0), amplitude_log_rate_per_s_(0.0) {
  parameters_.validate();
  frequency_log_rate_per_s_ =
      std::log(parameters_.end_frequency_Hz / parameters_.start_frequency_Hz) /
      parameters_.duration_s;
  amplitude_log_rate_per_s_ =
      std::log(parameters_.end_amplitude_m / parameters_.initial_amplitude_m) /
      parameters_.duration_s;
}

double LogSweep::max_step_s() const {
  return 0.25 / std::max(parameters_.start_frequency_Hz, parameters_.end_frequency_Hz);
}

double LogSweep::instantaneous_frequency_Hz(double time_s) const {
  return parameters_.start_frequency_Hz * std::exp(frequency_log_rate_per_s_ * time_s);
}

double LogSweep::amplitude_m(double time_s) const {
  return parameters_.initial_amplitude_m * std::exp(amplitude_log_rate_per_s_ * time_s);
}

double LogSweep::phase_rad(double time_s) const {
  const double two_pi_f0 = 2.0 * std::numbers::pi * parameters_.start_frequency_Hz;
  const double b = frequency_log_rate_per_s_;
  // expm1 keeps φ accurate for a tiny ln r (and exactly 2π f0 t for r = 1).
  if (b == 0.0) return two_pi_f0 * time_s;
  return two_pi_f0 * std::expm1(b * time_s) / b;
}

RoadSample LogSweep::at(double time_s) const {
  if (time_s < 0.0) return {};
  const double phase = phase_rad(time_s);
  const double amplitude = amplitude_m(time_s);
  const double omega = 2.0 * std::numbers::pi * instantaneous_frequency_Hz(time_s);
  const double s = std::sin(phase);
  const double c = std::cos(phase);
  return {amplitude * s, amplitude * (amplitude_log_rate_per_s_ * s + omega * c)};
}

}  // namespace ridefit::road
