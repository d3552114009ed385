#pragma once

#include <span>
#include <string_view>

namespace ridefit::signal {

// Checks a sampled spectrum given as (frequency_Hz, psd) pairs and a band [low_Hz, high_Hz]
// on it, for the spectrum helpers. Throws InputError, prefixed with `caller`, unless: both
// spans have the same length ≥ 2, frequencies are finite and strictly increasing, PSD values
// are finite and ≥ 0, and low_Hz < high_Hz both lie within [frequency.front(),
// frequency.back()] (a relative slack of 1e-9 absorbs rounding of a computed Nyquist
// frequency).
void check_spectrum_band(std::string_view caller, std::span<const double> frequency_Hz,
                         std::span<const double> psd, double low_Hz, double high_Hz);

}  // namespace ridefit::signal
