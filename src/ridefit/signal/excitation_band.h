#pragma once

#include <span>

namespace ridefit::signal {

// How much of a model's residual lies within the band its input excites. A misfit above that
// band is what the input does not drive: the sensor's noise, or dynamics of the rig the model
// does not have. On the NEES MR random record (0–50 Hz motion) 63 % of the judged residual's
// power lies above 50 Hz, incoherent with the motion, where the force holds 8 % of its own.
struct ExcitationBand {
  double band_Hz = 0.0;  // the lowest frequency below which input_share of the input's power lies
  double residual_in_band_share = 1.0;  // of the residual's power, below band_Hz
  // The input's largest autocorrelation (normalised, unbiased) beyond its first zero crossing, up
  // to half the record: about 1 for a sine or triangle test, which repeats its cycle; small for a
  // random motion. Above a half the motion counts as periodic, and what lies above its band is
  // the damper's own harmonics as much as noise.
  double repeat_correlation = 0.0;
};

// `input` (a rig's velocity) and `residual` at the same uniform samples. Both spectra by Welch
// (periodic Hann, 50 % overlap, segments of an eighth of the record, at least 64 samples; the
// mean taken out of each). InputError for series of different lengths or under 128 samples, a
// rate not above 0, a share outside (0, 1], a sample that is not finite.
ExcitationBand excitation_band(std::span<const double> input, std::span<const double> residual,
                               double sample_rate_Hz, double input_share = 0.99);

}  // namespace ridefit::signal
