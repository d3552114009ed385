#include "ridefit/signal/require_finite.h"

#include <fmt/format.h>

#include <cmath>

#include "ridefit/io/input_error.h"

namespace ridefit::signal {

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
