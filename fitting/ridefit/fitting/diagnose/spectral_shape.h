#pragma once

#include <string>
#include <vector>

#include "ridefit/fitting/diagnose/disagreement_map.h"
#include "ridefit/fitting/diagnose/sparse_selection.h"

namespace ridefit::fitting::diagnose {

// What a disagreement between a car's measured and simulated spectra looks like when no effect of
// the library explains it: each channel's measured-over-simulated ratio, 10·log10(P_meas/P_sim)
// over the band's bins (the disagreement map's, the simulated side through the sensor chain and
// with the noise floor), regressed on named shapes per channel:
// - level: a constant in dB (a sensor's gain, the road's level);
// - tilt: dB per decade of frequency (the road's waviness, the high frequencies' damping);
// - resonance near f₀: 10·log10 of |(1 + 2iζr)/(1 − r² + 2iζr)|², r = f/f₀, ζ = 0.1, on a grid of
//   six f₀ per octave (a sensor on a panel, a mode the model lacks; the coefficient 1 is one such
//   mount, negative an antiresonance);
// - low-pass above f_c: −10·log10(1 + (f/f_c)²), on the same grid (a sensor's band, a filter);
// - frequency shift: −d(10·log10 P_sim)/d ln f, the model's own spectrum moved along frequency by
//   a share δ (modes sitting too low or too high: a stiffness or a mass off).
// Forward selection (sparse_selection.h) fitted on the even bins and judged on the odd ones. A
// suggestion in words, never a named library effect.

struct SpectralShapeTerm {
  std::string id;             // "level", "tilt", "resonance", "low_pass", "frequency_shift"
  std::string channel;        // "body_acc", "wheel_acc"
  double frequency_Hz = 0.0;  // a resonance's f₀ or a low-pass' corner; 0 for the others
  std::string words;
  std::string unit;  // "dB", "dB/decade", "1" (multiples of the named shape), "share"
  double coefficient = 0.0;
  double standard_error = 0.0;
  double judged_share = 0.0;  // of the judging bins' sum of squares, removed as it entered
};

struct SpectralShape {
  std::vector<SpectralShapeTerm> terms;  // in the order they entered; none: nothing to say
  // What the terms remove together on the judging bins. Optimistic: each term was chosen as
  // the best of about 150 on those bins, and they neighbour the fitted ones.
  double judged_share = 0.0;
  SparseSelectionOptions options;  // the thresholds the terms passed
};

// The shape of `map`'s ratio over [band_low_Hz, band_high_Hz] (every channel). InputError for bad
// options or a band not 0 < low < high. Bins whose ratio is not finite are left out.
SpectralShape spectral_shape(const DisagreementMap& map, double band_low_Hz, double band_high_Hz,
                             const SparseSelectionOptions& options = {});

// A term's coefficient as an engineer reads it: "+1.74 ± 0.14 dB", "+6.7 ± 0.4 %", "+1.13 ± 0.02 ×
// the named shape".
std::string coefficient_text(const SpectralShapeTerm& term);

// The terms in words with their coefficients, "; " between them ("" for none).
std::string describe(const SpectralShape& shape);

}  // namespace ridefit::fitting::diagnose
