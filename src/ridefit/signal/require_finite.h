#pragma once

#include <span>
#include <string_view>

namespace ridefit::signal {

// Throws InputError naming the first non-finite sample (index and time i/fs) and `context`
// (e.g. "Wk weighting"), so NaN or ±inf never flows silently into a filter or a metric whose
// result would then be NaN without saying where it came from.
void require_finite_samples(std::span<const double> samples, std::string_view context,
                            double sample_rate_Hz);

}  // namespace ridefit::signal
