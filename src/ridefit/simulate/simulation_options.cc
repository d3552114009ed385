#include "ridefit/simulate/simulation_options.h"

#include <fmt/core.h>

#include <cmath>

#include "ridefit/common/errors.h"

namespace ridefit::simulate {

std::vector<double> output_times(const SimulationOptions& options, double road_duration_s) {
  if (!(options.output_rate_Hz > 0.0) || !std::isfinite(options.output_rate_Hz)) {
    throw InputError(
        fmt::format("output rate {} Hz: expected a finite rate > 0", options.output_rate_Hz));
  }
  if (!(options.duration_s >= 0.0) || !std::isfinite(options.duration_s)) {
    throw InputError(
        fmt::format("duration {} s: expected a finite duration > 0 (or 0 for the "
                    "excitation's own)",
                    options.duration_s));
  }
  if (options.duration_s > road_duration_s * (1.0 + 1e-12)) {
    throw InputError(fmt::format(
        "duration {} s is longer than the excitation ({} s); the road is not defined beyond it",
        options.duration_s, road_duration_s));
  }
  const double duration = options.duration_s > 0.0 ? options.duration_s : road_duration_s;
  if (!(duration > 0.0)) throw InputError("simulation duration must be > 0 s");
  const double sample_count = std::floor(duration * options.output_rate_Hz) + 1.0;
  if (sample_count > kMaxOutputSamples) {
    throw InputError(fmt::format(
        "{} s at {} Hz is {:.3g} output samples, more than the {:g} this tool keeps in memory; "
        "lower the output rate or the duration",
        duration, options.output_rate_Hz, sample_count, kMaxOutputSamples));
  }
  std::vector<double> times(static_cast<std::size_t>(sample_count));
  for (std::size_t k = 0; k < times.size(); ++k) {
    times[k] = static_cast<double>(k) / options.output_rate_Hz;
  }
  return times;
}

void check_output_rate(double rate_Hz, double duration_s) {
  if (rate_Hz > kMaxOutputRate_Hz) {
    throw InputError(
        fmt::format("{:g} Hz: output samples more than {:g} per second resolve nothing the solvers "
                    "compute for a vehicle; give a rate up to {:g} Hz",
                    rate_Hz, kMaxOutputRate_Hz, kMaxOutputRate_Hz));
  }
  const double samples = std::floor(duration_s * rate_Hz + 1e-9) + 1.0;
  if (samples < 2.0) {
    throw InputError(
        fmt::format("{:g} Hz over {:g} s gives {:g} output sample; give at least two: a rate of at "
                    "least {:g} Hz or a longer duration",
                    rate_Hz, duration_s, samples, 1.0 / duration_s));
  }
}

}  // namespace ridefit::simulate
