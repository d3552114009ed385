#pragma once

#include <cstddef>
#include <span>
#include <string_view>

namespace ridefit::signal {

// Checks a sampled signal for the signal and comfort helpers. Throws InputError, prefixed
// with `caller`, when it has fewer than `min_samples` samples or a sample that is not finite
// (the message names the first such sample).
void check_samples(std::string_view caller, std::span<const double> samples,
                   std::size_t min_samples);

// Throws InputError, prefixed with `caller`, unless sample_rate_Hz is positive and finite.
void check_sample_rate(std::string_view caller, double sample_rate_Hz);

// Throws InputError naming the first non-finite sample (index and time i/fs) and `context`
// (e.g. "Wk weighting"), so NaN or ±inf never flows silently into a filter or a metric whose
// result would then be NaN without saying where it came from.
void require_finite_samples(std::span<const double> samples, std::string_view context,
                            double sample_rate_Hz);

}  // namespace ridefit::signal
