#pragma once

#include <cstddef>
#include <span>

#include "ridefit/signal/welch_psd.h"

namespace ridefit::signal {

struct SpectrumPeak {
  double frequency_Hz = 0.0;  // interpolated
  double psd = 0.0;           // interpolated peak level, [unit]²/Hz
  std::size_t bin = 0;        // index of the largest bin inside the band
};

// The largest PSD value among the bins with low_Hz ≤ f ≤ high_Hz, refined to sub-bin accuracy
// by fitting a parabola to ln PSD through that bin and its two neighbours and taking its
// vertex. A windowed sine's main lobe is close to a Gaussian, i.e. a parabola in ln PSD, so
// this is much tighter than on the linear PSD: for a sine under the Hann window the bias stays
// below 0.02 bin (0.016 at worst, near 0.3 bin off centre). The interpolated level is a
// density, not an amplitude; use band_power for a tone's power.
//
// The neighbours may lie outside the band. No refinement is done (the bin itself is returned)
// when the bin is at either end of the spectrum, is not a local maximum (the band edge cuts a
// slope), or any of the three values is zero.
//
// Throws InputError for a malformed spectrum or band (see check_spectrum_band) or a band
// containing no bin.
SpectrumPeak find_peak(std::span<const double> frequency_Hz, std::span<const double> psd,
                       double low_Hz, double high_Hz);
SpectrumPeak find_peak(const PowerSpectralDensity& spectrum, double low_Hz, double high_Hz);

}  // namespace ridefit::signal
