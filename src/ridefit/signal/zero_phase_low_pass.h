#pragma once

#include <span>
#include <vector>

namespace ridefit::signal {

// A second-order Butterworth low-pass run forward and then backward over a uniformly sampled
// signal (as MATLAB's and SciPy's filtfilt do): no phase shift and no delay, magnitude
// |H(f)|² = 1/(1 + (f/f_c)⁴), −6 dB at f_c, −0.26 dB at f_c/2 and −24 dB at 2·f_c. The ends are
// extended by odd reflection (2·x₀ − x₁…) over 6/f_c (the filter's impulse response has decayed by
// e⁻²⁷ there) and each pass starts in steady state at its first value, so a record that starts
// or ends away from zero, or on a slope, gets no transient.
//
// Throws InputError for fewer than 4 samples, a non-finite sample, a sample rate that is not
// positive and finite, or a cut-off outside (0, fs/2).
std::vector<double> zero_phase_low_pass(std::span<const double> signal, double sample_rate_Hz,
                                        double cutoff_Hz);

}  // namespace ridefit::signal
