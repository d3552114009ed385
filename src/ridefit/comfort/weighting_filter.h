#pragma once

#include <span>
#include <vector>

#include "ridefit/comfort/frequency_weighting.h"
#include "ridefit/signal/biquad_cascade.h"

namespace ridefit::comfort {

// Time-domain ISO 2631-1 weighting of a uniformly sampled signal.
//
// Discretisation: each analogue section of weighting_sections() (H_h, H_l, H_t, H_s: a cascade
// of 3 or 4 biquads) is mapped by the bilinear transform pre-warped at its own characteristic
// frequency (f1, f2, f4, √(f5·f6)), so band limits and the transition/step frequencies fall
// exactly where Annex A puts them; the remaining error is the transform's compression of the
// frequency axis towards Nyquist, which lowers the response near f2.
//
// Accuracy, measured as |H_digital/H_analogue − 1| (tests/comfort/weighting_filter_test.cc
// asserts these bounds):
//   Wk, Wd, Wc, We, Wj, 500 Hz ≤ fs ≤ 2 kHz:  < 1 % from 0.1 Hz up to min(0.055·fs, f2)
//                                            (27 Hz at 500 Hz, 55 Hz at 1 kHz, 100 Hz at 2 kHz);
//   fs = 10·f2 (1 kHz for the 100 Hz band limit): ≤ 1.5 % (0.13 dB) up to 0.8·f2 (80 Hz);
//                                                 Wf ≤ 3 % up to 0.8·f2 (0.5 Hz);
//   fs = 5·f2 (500 Hz), the lowest accepted rate: ≤ 6 % (0.51 dB for Wk at 80 Hz) up to 0.8·f2;
//                                                 Wf ≤ 11 % (0.9 dB).
// Sample at 10·f2 or faster where the top of the band matters; the error is a smooth droop,
// so metrics dominated by the 1–20 Hz region (ride comfort) are far more accurate than that.
//
// A sample rate below minimum_sample_rate_Hz() = 5·f2 is an InputError naming that rate:
// below it the droop at 0.8·f2 exceeds 0.5 dB and grows fast (0.75 dB at 4·f2), and at
// 2·f2 the low-pass cannot be designed at all.
double minimum_sample_rate_Hz(Weighting weighting);

// The weighting's biquad cascade at sample_rate_Hz (see above for accuracy and errors).
signal::BiquadCascade weighting_filter(Weighting weighting, double sample_rate_Hz);

// Weighted signal a_w of an acceleration record (m/s², or rad/s² for We), filtered from rest.
// Throws InputError for a too-low or invalid rate, or a non-finite sample (naming its index).
// The filter starts from rest, so the first few time constants (≈ 1/f1 = 2.5 s for the 0.4 Hz
// band limit, 12.5 s for Wf) carry a start-up transient; discard them where it matters.
std::vector<double> apply_weighting(Weighting weighting, std::span<const double> acceleration,
                                    double sample_rate_Hz);

}  // namespace ridefit::comfort
