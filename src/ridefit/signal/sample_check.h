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

}  // namespace ridefit::signal
