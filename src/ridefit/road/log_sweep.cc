#include "ridefit/road/log_sweep.h"

#include <fmt/core.h>

#include <cmath>
#include <numbers>

#include "ridefit/io/input_error.h"

namespace ridefit::road {
namespace {

void require_positive(const char* key, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(fmt::format("key '{}' is {}, expected a finite value > 0", key, value));
  }
}

}  // namespace

void LogSweepParameters::validate() const {
  require_positive("start_frequency_Hz", start_frequency_Hz);
  require_positive("end_frequency_Hz", end_frequency_Hz);
  require_positive("initial_amplitude_m", initial_amplitude_m);
  require_positive("end_amplitude_m", end_amplitude_m);
  require_positive("duration_s", duration_s);
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
