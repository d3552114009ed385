#pragma once

#include <span>

#include "ridefit/signal/welch_psd.h"

namespace ridefit::signal {

// ∫ PSD df over [low_Hz, high_Hz] by the trapezoid rule on the PSD's own frequency grid; the
// PSD is interpolated linearly at band edges that fall between bins, so bands need not be
// bin-aligned. For a one-sided density in [unit]²/Hz the result is the mean square [unit]²
// contributed by the band (the whole range gives the variance). Over the whole range the
// trapezoid differs from the rectangle sum Σ P[k]·Δf, Parseval's exact counterpart for a Welch
// PSD, by half the end bins, (P[0] + P[last])·Δf/2: negligible unless DC or Nyquist hold power.
//
// Throws InputError for a malformed spectrum or a band that is empty or reaches outside the
// spectrum's frequency range (see check_spectrum_band).
double band_power(std::span<const double> frequency_Hz, std::span<const double> psd, double low_Hz,
                  double high_Hz);
double band_power(const PowerSpectralDensity& spectrum, double low_Hz, double high_Hz);

// sqrt(band_power): the RMS [unit] of the signal's content in the band.
double band_rms(std::span<const double> frequency_Hz, std::span<const double> psd, double low_Hz,
                double high_Hz);
double band_rms(const PowerSpectralDensity& spectrum, double low_Hz, double high_Hz);

}  // namespace ridefit::signal
