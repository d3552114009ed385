#pragma once

#include <span>
#include <string_view>

#include "ridefit/signal/welch_psd.h"

namespace ridefit::signal {

// Checks a sampled spectrum given as (frequency_Hz, psd) pairs and a band [low_Hz, high_Hz]
// on it, for the spectrum helpers. Throws InputError, prefixed with `caller`, unless: both
// spans have the same length ≥ 2, frequencies are finite and strictly increasing, PSD values
// are finite and ≥ 0, and low_Hz < high_Hz both lie within [frequency.front(),
// frequency.back()] (a relative slack of 1e-9 absorbs rounding of a computed Nyquist
// frequency).
void check_spectrum_band(std::string_view caller, std::span<const double> frequency_Hz,
                         std::span<const double> psd, double low_Hz, double high_Hz);

// Checks that a PowerSpectralDensity carries the statistics the averaging, smoothing and
// confidence helpers need. Throws InputError, prefixed with `caller` and naming the spectrum by
// `name`, unless: frequency_Hz, psd and degrees_of_freedom have the same length ≥ 2, PSD values
// are finite and ≥ 0, degrees of freedom finite and > 0, sample rate finite and > 0, and
// segment length, segment count, hop and smoothing width are all ≥ 1.
void check_psd_statistics(std::string_view caller, std::string_view name,
                          const PowerSpectralDensity& spectrum);

}  // namespace ridefit::signal
