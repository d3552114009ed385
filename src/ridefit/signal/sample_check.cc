#include "ridefit/signal/sample_check.h"

#include <fmt/format.h>

#include <cmath>

#include "ridefit/common/errors.h"

namespace ridefit::signal {

void check_samples(std::string_view caller, std::span<const double> samples,
                   std::size_t min_samples) {
  if (samples.size() < min_samples) {
    throw InputError(fmt::format("{}: the signal has {} samples; it needs at least {}", caller,
                                 samples.size(), min_samples));
  }
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (!std::isfinite(samples[i])) {
      throw InputError(fmt::format("{}: sample {} is {}; every sample must be a finite number",
                                   caller, i, samples[i]));
    }
  }
}

void check_sample_rate(std::string_view caller, double sample_rate_Hz) {
  if (!std::isfinite(sample_rate_Hz) || sample_rate_Hz <= 0.0) {
    throw InputError(
        fmt::format("{}: sample rate {} Hz is invalid; it must be a positive, finite number of Hz",
                    caller, sample_rate_Hz));
  }
}

void require_finite_samples(std::span<const double> samples, std::string_view context,
                            double sample_rate_Hz) {
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (!std::isfinite(samples[i])) {
      throw InputError(
          fmt::format("{}: sample {} (t = {} s) is {}; every sample must be a finite number",
                      context, i, static_cast<double>(i) / sample_rate_Hz, samples[i]));
    }
  }
}

}  // namespace ridefit::signal
