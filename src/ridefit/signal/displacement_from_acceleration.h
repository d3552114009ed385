#pragma once

#include <span>
#include <vector>

#include "ridefit/signal/detrend.h"

namespace ridefit::signal {

// Zero-phase high-pass applied while integrating (seed 000, Section 4.2: accelerations
// integrated and high-pass filtered at 0.75 Hz "to avoid signal drift").
struct HighPassIntegrationOptions {
  double high_pass_Hz = 0.75;  // cut-off f_c (−3 dB), 0 < f_c < fs/2
  // Order n of the Butterworth magnitude |H(f)| = 1/sqrt(1 + (f_c/f)^(2n)). The integrated
  // signal's response |H|/(2πf)^p must vanish at 0 Hz, so n > p: at least 2 for velocity
  // (p = 1) and 3 for displacement (p = 2); at most 16.
  int high_pass_order = 4;
  // Removed from the acceleration before the transform: offsets and drift of the sensor, and
  // the step they would make where the record meets its zero padding.
  Detrend detrend = Detrend::kLinear;
};

// Displacement [m] from an acceleration [m/s²] sampled at sample_rate_Hz, by double
// integration with a high-pass, in the frequency domain:
//
//   D(f) = A(f) · |H(f)| / (j2πf)² = −A(f) · |H(f)| / (2πf)²,
//
// A the FFT (Eigen) of the detrended acceleration zero-padded to a power of two of at least
// N + ceil(2n·fs/f_c) samples, D's inverse FFT truncated to the N input samples. Details:
// - |H| is applied as a real, even gain: zero phase, the output is not delayed (like
//   MATLAB's filtfilt, but filtfilt of an order-n Butterworth applies |H_n|², −6 dB at f_c;
//   here the gain at f_c is −3 dB).
// - The 0 Hz and the Nyquist bin are set to zero.
// - The padding, 2n periods of f_c, outlasts the filter's impulse response (the Butterworth's
//   slowest pole decays by exp(−4πn·sin(π/2n)) ≤ exp(−4π) over it), so the two ends of the
//   record do not wrap around onto each other.
// - The record's ends are still ends: where the signal starts or stops, integration meets
//   unknown initial velocity and displacement, and the output carries a transient that the
//   high-pass lets die out. Measured for order 4 and sines of 1–5 Hz: the error falls below
//   1 % of the displacement amplitude at about 2/f_c (2.7 s at 0.75 Hz) from either end and
//   below 0.01 % at 4/f_c; discard those stretches. Between them a sine at f ≫ f_c comes out
//   as −a/(2πf)².
//
// Throws InputError for fewer than 2 samples, a non-finite sample, a sample rate that is not
// positive and finite, a cut-off outside (0, fs/2) or an order outside [3, 16].
std::vector<double> displacement_from_acceleration(std::span<const double> acceleration,
                                                   double sample_rate_Hz,
                                                   const HighPassIntegrationOptions& options = {});

// Velocity [m/s] from an acceleration [m/s²] by single integration with the same high-pass:
// V(f) = A(f)·|H(f)|/(j2πf). As displacement_from_acceleration otherwise; the order must lie
// in [2, 16].
std::vector<double> velocity_from_acceleration(std::span<const double> acceleration,
                                               double sample_rate_Hz,
                                               const HighPassIntegrationOptions& options = {});

}  // namespace ridefit::signal
