#pragma once

#include <span>

namespace ridefit::signal {

// An estimate of a channel's white sensor-noise floor: the one-sided PSD level N [unit²/Hz] of
// additive white noise, from the measured series alone.
//
// Rule: Welch's PSD (Hann, 50 % overlap, 1 s segments, or an eighth of the record when that is
// shorter) is taken over (above_Hz, fs/2), above the fitted band, where a vehicle's response
// falls with frequency. There the spectrum is fitted by a falling power law plus a constant,
//   P(f) ≈ A·(f/above_Hz)^(−p) + N,   A, N ≥ 0,  p = 0.5, 1, …, 8,
// by least squares on relative errors (iteratively reweighted by the model, so the χ² scatter,
// whose size is proportional to the level, weighs every bin alike), and N of the best p is the
// estimate. Where the response has rolled off below the noise the spectrum flattens and N is the
// plateau; where the response falls all the way to fs/2 without flattening (a wheel's
// acceleration, which a tyre keeps high), the power law takes it and N stays near 0: the
// estimate errs low, towards the plain log-PSD comparison, rather than high (a floor above the
// in-band response would blind the fit there).
//
// Assumptions: the noise is white (the same level at every frequency, as an accelerometer's
// electronic noise and quantisation are) and is added after any anti-alias filtering (a filter
// acting on the noise makes the estimate low); the response above the band is a falling power
// law over the range (a resonance up there is read as part of the floor).
//
// Throws InputError for fewer than 64 samples, a non-finite sample, fs ≤ 0, or above_Hz outside
// [0, 0.45·fs) (fewer than 8 bins would remain).
double estimate_white_noise_floor(std::span<const double> series, double sample_rate_Hz,
                                  double above_Hz);

}  // namespace ridefit::signal
