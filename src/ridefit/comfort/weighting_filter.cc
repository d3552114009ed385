#include "ridefit/comfort/weighting_filter.h"

#include <fmt/format.h>

#include <cmath>

#include "ridefit/common/errors.h"
#include "ridefit/signal/sample_check.h"

namespace ridefit::comfort {

double minimum_sample_rate_Hz(Weighting weighting) {
  return 5.0 * weighting_parameters(weighting).f2_Hz;
}

signal::BiquadCascade weighting_filter(Weighting weighting, double sample_rate_Hz) {
  const double minimum_Hz = minimum_sample_rate_Hz(weighting);
  if (!std::isfinite(sample_rate_Hz) || sample_rate_Hz < minimum_Hz) {
    throw InputError(fmt::format(
        "{} weighting: sample rate {} Hz is too low; it needs at least {} Hz (5 × its {} Hz band "
        "limit) for the time-domain filter to stay within about 0.5 dB (0.51 dB for Wk) of ISO "
        "2631-1 Annex A up to {} "
        "Hz; resample the signal to {} Hz or more",
        to_string(weighting), sample_rate_Hz, minimum_Hz, weighting_parameters(weighting).f2_Hz,
        0.8 * weighting_parameters(weighting).f2_Hz, minimum_Hz));
  }
  const auto sections = weighting_sections(weighting);
  return signal::BiquadCascade::from_analogue(sections, sample_rate_Hz);
}

std::vector<double> apply_weighting(Weighting weighting, std::span<const double> acceleration,
                                    double sample_rate_Hz) {
  const signal::BiquadCascade filter = weighting_filter(weighting, sample_rate_Hz);
  signal::require_finite_samples(acceleration, fmt::format("{} weighting", to_string(weighting)),
                                 sample_rate_Hz);
  return filter.filter(acceleration);
}

}  // namespace ridefit::comfort
